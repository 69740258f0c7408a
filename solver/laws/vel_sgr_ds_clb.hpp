#pragma once
// VEL_SGR_DS_CLB: velocity Signorini + static/dynamic Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct VelSgrDsClb {
  static constexpr std::string_view keyword = "VEL_SGR_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 1;  // taille_ele
  double dfric, sfric;
  static constexpr LawParameter<VelSgrDsClb> parameters[] = {{"dfric", &VelSgrDsClb::dfric},
                                                             {"sfric", &VelSgrDsClb::sfric}};
};

template <class Interaction>
void prepare(const VelSgrDsClb& law, Interaction& c, const LawStep&) {
  c.inactive = c.gap_begin > 0.0;
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

}  // namespace lmgc::solver
