#pragma once
// IQS_CLB: inelastic quasi-shock Signorini + Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsClb {
  static constexpr std::string_view keyword = "IQS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double sfric;
  static constexpr LawParameter<IqsClb> parameters[] = {{"sfric", &IqsClb::sfric}};
};

template <class Interaction>
void prepare(const IqsClb& law, Interaction& c, const LawStep& step) {
  iqs_form(c, step.h);
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
