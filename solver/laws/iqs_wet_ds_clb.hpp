#pragma once
// IQS_WET_DS_CLB: reversible cohesion c inside a wet halo γ ≤ Wethk, statuses in their W form,
// static/dynamic Coulomb (contact-laws.md §3.2; mod_nlgs_3D prep :1379-1405). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsWetDsClb {
  static constexpr std::string_view keyword = "IQS_WET_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double cohen, cohet, wethk, dfric, sfric;
  static constexpr LawParameter<IqsWetDsClb> parameters[] = {{"cohen", &IqsWetDsClb::cohen},
                                                             {"cohet", &IqsWetDsClb::cohet},
                                                             {"Wethk", &IqsWetDsClb::wethk},
                                                             {"dfric", &IqsWetDsClb::dfric},
                                                             {"sfric", &IqsWetDsClb::sfric}};
};

// 2D, IQS_WET_DS_CLB and GAP_WET_DS_CLB (cohen, wethk, dfric, sfric): inside the halo the status in
// its W form and the cohesion cohen; outside it, IQS_WET_DS_CLB's status is noctc and GAP_WET_DS_CLB's
// is left as it was; the normal part IQS or, with `gap_normal`, GAP.
template <class Law>
void prepare_wet(const Law& law, LocalProblem2D& c, const LawStep& step, bool gap_normal) {
  if (gap_normal)
    gap_form(c, step.h);
  else
    iqs_form(c, step.h);
  if (c.gap_begin <= law.wethk) {
    c.status_begin = wet_status(c.status_begin);
    add_cohesion(c, law.cohen, step.h);
  } else if (!gap_normal) {
    c.status_begin = ContactStatus::noctc;
  }
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

inline void prepare(const IqsWetDsClb& law, LocalProblem2D& c, const LawStep& step) {
  prepare_wet(law, c, step, false);
}

inline void prepare(const IqsWetDsClb& law, Interaction3D& c, const LawStep& step) {
  iqs_form(c, step.h);
  if (c.gap_begin <= law.wethk) {
    c.status_begin = wet_status(c.status_begin);
    c.correction = -law.cohen * step.h;
  } else {
    c.status_begin = ContactStatus::noctc;
  }
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

// Dry unless prepare added a nonzero cohesion (its correction −cohen h), as it did for this gap.
inline void finish(const IqsWetDsClb& law, Interaction2D& c, const LawStep& step) {
  if (!(c.gap_begin <= law.wethk) || -law.cohen * step.h == 0.0) c.status = dry_status(c.status);
}
inline void finish(const IqsWetDsClb&, Interaction3D& c, const LawStep&) {
  c.status = c.correction != 0.0 ? wet_status(c.status) : dry_status(c.status);
}

}  // namespace lmgc::solver
