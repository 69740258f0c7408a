#pragma once
// GAP_SGR_DS_CLB: gap-Signorini + static/dynamic Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct GapSgrDsClb {
  static constexpr std::string_view keyword = "GAP_SGR_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 1;  // taille_ele
  double dfric, sfric;
  static constexpr LawParameter<GapSgrDsClb> parameters[] = {{"dfric", &GapSgrDsClb::dfric},
                                                             {"sfric", &GapSgrDsClb::sfric}};
};

template <class Interaction>
void prepare(const GapSgrDsClb& law, Interaction& c, const LawStep& step) {
  gap_form(c, step.h);
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

}  // namespace lmgc::solver
