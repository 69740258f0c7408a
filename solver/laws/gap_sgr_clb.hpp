#pragma once
// GAP_SGR_CLB: gap-Signorini (the end-of-step gap >= 0) + Coulomb (contact-laws.md §3.1). 2D, 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct GapSgrClb {
  static constexpr std::string_view keyword = "GAP_SGR_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 1;  // taille_ele
  double sfric;
  static constexpr LawParameter<GapSgrClb> parameters[] = {{"sfric", &GapSgrClb::sfric}};
};

template <class Interaction>
void prepare(const GapSgrClb& law, Interaction& c, const LawStep& step) {
  gap_form(c, step.h);
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
