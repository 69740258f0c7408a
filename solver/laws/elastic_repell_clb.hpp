#pragma once
// ELASTIC_REPELL_CLB: linear spring in compression (stiffness F/gap) in series, + Coulomb
// (contact-laws.md §3.3). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct ElasticRepellClb {
  static constexpr std::string_view keyword = "ELASTIC_REPELL_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double stiffness, sfric;
  static constexpr LawParameter<ElasticRepellClb> parameters[] = {{"F/gap", &ElasticRepellClb::stiffness},
                                                                  {"sfric", &ElasticRepellClb::sfric}};
};

// r_n = -h k γ_end gives WWnn = Wnn + 1/(k h²), covfree = γ/h.
inline void prepare(const ElasticRepellClb& law, LocalProblem2D& c, const LawStep& step) {
  if (law.stiffness > 0.0) c.WW(1, 1) = c.W(1, 1) + 1.0 / (law.stiffness * step.h * step.h);
  gap_form(c, step.h);
  c.mu = law.sfric;
}

// 3D (mod_nlgs_3D prep :1523-1530): the same WWnn and covfree.
inline void prepare(const ElasticRepellClb& law, Interaction3D& c, const LawStep& step) {
  if (law.stiffness > 0.0) c.normal_compliance = 1.0 / (law.stiffness * step.h * step.h);
  gap_form(c, step.h);
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
