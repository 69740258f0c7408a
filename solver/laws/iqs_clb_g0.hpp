#pragma once
// IQS_CLB_g0: IQS relative to the gap at the interaction's first step, kept as internal g_ref
// (contact-laws.md §3.1). 2D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsClbG0 {
  static constexpr std::string_view keyword = "IQS_CLB_g0";
  static constexpr int internals_2d = 1;  // g_ref
  static IqsClbG0 from_card(const LawParameters& p) { return {p("sfric")}; }
  double sfric;
};

inline void prepare(const IqsClbG0& law, Interaction2D& c, const LawStep& step) {
  if (c.status_begin == ContactStatus::nknow) c.internal[0] = positive(c.gap_begin);
  c.covfree(1) = positive(c.gap_begin - c.internal[0]) / step.h;
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
