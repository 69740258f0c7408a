#pragma once
// COUPLED_DOF: bilateral glue on every component (contact-laws.md §3.4; 3D: mod_nlgs_3D :5809,
// r = −W⁻¹ uu). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct CoupledDof {
  static constexpr std::string_view keyword = "COUPLED_DOF";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  static constexpr std::array<LawParameter<CoupledDof>, 0> parameters{};
};

inline void prepare(const CoupledDof&, LocalProblem2D& c, const LawStep&) {
  c.mu = 0.0;
}

inline void prepare(const CoupledDof&, Interaction3D& c, const LawStep&) {
  c.form = LocalForm3D::glued;
  c.mu = 0.0;
}

}  // namespace lmgc::solver
