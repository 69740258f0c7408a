#pragma once
// COUPLED_DOF: bilateral glue on both components (contact-laws.md §3). 2D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct CoupledDof {
  static constexpr std::string_view keyword = "COUPLED_DOF";
  static constexpr int internals_2d = 0;
  static CoupledDof from_card(const LawParameters&) { return {}; }
};

inline void prepare(const CoupledDof&, Interaction2D& c, const LawStep&) {
  c.mu = 0.0;
}

}  // namespace lmgc::solver
