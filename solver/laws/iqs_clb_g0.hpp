#pragma once
// IQS_CLB_g0: IQS relative to the gap at the run's first preparation with interactions, kept as g_ref
// (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsClbG0 {
  static constexpr std::string_view keyword = "IQS_CLB_g0";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 1;  // g_ref
  double sfric;
  static constexpr LawParameter<IqsClbG0> parameters[] = {{"sfric", &IqsClbG0::sfric}};
};

// g_ref = (γ)+ at the run's first preparation (mod_nlgs / mod_nlgs_3D prep, `.not. is_initialized`);
// contacts created later keep g_ref = 0, i.e. plain IQS_CLB.
// The reference gap g_ref is the law's internal variable: in 2D in the interaction, in 3D in its
// law state.
template <class Interaction>
void prepare_from_reference(const IqsClbG0& law, Interaction& c, double& reference_gap, const LawStep& step) {
  if (step.first_preparation) reference_gap = positive(c.gap_begin);
  c.covfree(1) = positive(c.gap_begin - reference_gap) / step.h;
  c.mu = law.sfric;
}
inline void prepare(const IqsClbG0& law, LocalProblem2D& c, const LawStep& step) {
  prepare_from_reference(law, c, c.internal[0], step);
}
inline void prepare(const IqsClbG0& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  prepare_from_reference(law, c, s.internal[0], step);
}

}  // namespace lmgc::solver
