#pragma once
// IQS_MOHR_DS_CLB: Mohr–Coulomb cohesion until the contact first stops sticking, then IQS_DS_CLB
// (contact-laws.md §3.2). 2D: cohesion c × the contact length. 3D (mod_nlgs_3D :1466-1520,
// :4547-4552): cohesive (Mstck) only from step 1 (Nstep = 1, as in 2D), cohesion c × the family's
// contact surface, added only while the local status is not noctc.
#include "solver/laws/cohesive_zone.hpp"

namespace lmgc::solver {

struct IqsMohrDsClb {
  static constexpr std::string_view keyword = "IQS_MOHR_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double cohen, cohet, dfric, sfric;
  static constexpr LawParameter<IqsMohrDsClb> parameters[] = {{"cohen", &IqsMohrDsClb::cohen},
                                                              {"cohet", &IqsMohrDsClb::cohet},
                                                              {"dfric", &IqsMohrDsClb::dfric},
                                                              {"sfric", &IqsMohrDsClb::sfric}};
  // The Mohr cone while cohesive: μ = cohet/cohen.
  double cohesive_friction() const { return cohen > 0.0 ? cohet / cohen : sfric; }
};

// 2D, IQS_MOHR_DS_CLB and GAP_MOHR_DS_CLB (cohen, cohet, dfric, sfric, cohesive_friction): cohesive
// only for the contacts of step 1 (mod_nlgs prep: `Nstep == 1 .and. nknow`), with cohesion cohen × L;
// the normal part IQS or, with `gap_normal`, GAP.
template <class Law>
void prepare_mohr(const Law& law, LocalProblem2D& c, const LawStep& step, double length, bool gap_normal) {
  if (step.first_step && c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Mstck;
  if (gap_normal)
    gap_form(c, step.h);
  else
    iqs_form(c, step.h);
  if (c.status_begin == ContactStatus::Mstck) {
    add_cohesion(c, law.cohen * length, step.h);
    c.mu = law.cohesive_friction();
  } else {
    c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
  }
}

// The cohesion survives only while the contact sticks.
template <class Interaction>
void keep_mohr_bond(Interaction& c) {
  if (c.status_begin == ContactStatus::Mstck && c.status == ContactStatus::stick)
    c.status = ContactStatus::Mstck;
}

inline void prepare(const IqsMohrDsClb& law, LocalProblem2D& c, const LawStep& step) {
  prepare_mohr(law, c, step, iqs_cohesive_length(c), false);
}

inline void prepare(const IqsMohrDsClb& law, Interaction3D& c, const LawState3D& s, const LawStep& step) {
  if (step.first_step && c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Mstck;
  iqs_form(c, step.h);
  c.correction_needs_contact = true;
  if (c.status_begin == ContactStatus::Mstck) {
    c.correction = -law.cohen * s.surface * step.h;
    c.mu = law.cohesive_friction();
  } else {
    c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
  }
}

template <class Interaction>
void finish(const IqsMohrDsClb&, Interaction& c, const LawStep&) {
  keep_mohr_bond(c);
}

}  // namespace lmgc::solver
