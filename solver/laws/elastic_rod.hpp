#pragma once
// ELASTIC_ROD: a bilateral linear spring between two points, stiffness F/str per unit strain,
// prestrain prstr, reference length gapREF (internal 1) (contact-laws.md §3.4). 3D (PTPT3 links).
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct ElasticRod {
  static constexpr std::string_view keyword = "ELASTIC_ROD";
  static constexpr bool in_2d = false, in_3d = true;
  static constexpr int internals_2d = 1;
  double force_per_strain, prestrain;
  static constexpr LawParameter<ElasticRod> parameters[] = {{"F/str", &ElasticRod::force_per_strain},
                                                            {"prstr", &ElasticRod::prestrain}};
};

inline void prepare(const ElasticRod& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  spring_form(c, s, law.force_per_strain, law.prestrain, step.h, LocalForm3D::rod);
}

}  // namespace lmgc::solver
