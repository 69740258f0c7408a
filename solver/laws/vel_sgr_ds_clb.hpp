#pragma once
// VEL_SGR_DS_CLB: velocity Signorini + static/dynamic Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct VelSgrDsClb {
  static constexpr std::string_view keyword = "VEL_SGR_DS_CLB";
  static constexpr int internals_2d = 1;  // taille_ele
  static VelSgrDsClb from_card(const LawParameters& p) { return {p("dfric"), p("sfric")}; }
  double dfric, sfric;
};

template <class Interaction>
void prepare(const VelSgrDsClb& law, Interaction& c, const LawStep&) {
  c.inactive = c.gap_begin > 0.0;
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

}  // namespace lmgc::solver
