#pragma once
// VEL_SGR_CLB: velocity Signorini (Moreau), active only once the gap is closed, + Coulomb
// (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct VelSgrClb {
  static constexpr std::string_view keyword = "VEL_SGR_CLB";
  static constexpr int internals_2d = 1;  // taille_ele
  static VelSgrClb from_card(const LawParameters& p) { return {p("sfric")}; }
  double sfric;
};

template <class Interaction>
void prepare(const VelSgrClb& law, Interaction& c, const LawStep&) {
  c.inactive = c.gap_begin > 0.0;
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
