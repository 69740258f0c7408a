#pragma once
// MD_JKRs, a law LMGC90's 2D NLGS has no branch for (a smooth law): LMGC90 then solves the default
// problem, velocity Signorini without any gap term and Coulomb with the law's friction
// (contact-laws.md §0 "Dimension note"). Reproduced for that law only. 2D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct NoNlgsBranch {
  static constexpr std::string_view keyword = "MD_JKRs";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 0;
  double sfric;
  static constexpr LawParameter<NoNlgsBranch> parameters[] = {{"sfric", &NoNlgsBranch::sfric}};
};

inline void prepare(const NoNlgsBranch& law, LocalProblem2D& c, const LawStep&) {
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
