#pragma once
// GAP_MOHR_DS_CLB: IQS_MOHR_DS_CLB's Mohr–Coulomb cohesion (cohen × the CLxxx point's length, until
// the contact first stops sticking) with a GAP normal part, for CLALp and CLJCx (contact-laws.md
// §3.2; mod_nlgs prep_nlgs, its GAP_MOHR_DS_CLB case). 2D.
#include "solver/laws/iqs_mohr_ds_clb.hpp"

namespace lmgc::solver {

struct GapMohrDsClb {
  static constexpr std::string_view keyword = "GAP_MOHR_DS_CLB";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 0;
  double cohen, cohet, dfric, sfric;
  static constexpr LawParameter<GapMohrDsClb> parameters[] = {{"cohen", &GapMohrDsClb::cohen},
                                                              {"cohet", &GapMohrDsClb::cohet},
                                                              {"dfric", &GapMohrDsClb::dfric},
                                                              {"sfric", &GapMohrDsClb::sfric}};
  double cohesive_friction() const { return cohen > 0.0 ? cohet / cohen : sfric; }
};

inline void prepare(const GapMohrDsClb& law, LocalProblem2D& c, const LawStep& step) {
  if (step.first_step && c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Mstck;
  gap_form(c, step.h);
  if (c.status_begin == ContactStatus::Mstck) {
    add_cohesion(c, law.cohen * c.length, step.h);
    c.mu = law.cohesive_friction();
  } else {
    c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
  }
}

inline void finish(const GapMohrDsClb&, Interaction2D& c, const LawStep&) {
  if (c.status_begin == ContactStatus::Mstck && c.status == ContactStatus::stick)
    c.status = ContactStatus::Mstck;
}

}  // namespace lmgc::solver
