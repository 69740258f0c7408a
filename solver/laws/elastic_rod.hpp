#pragma once
// ELASTIC_ROD: a bilateral linear spring between two points, stiffness F/str per unit strain,
// prestrain prstr, reference length gapREF (internal 1) (contact-laws.md §3.4). 3D (PTPT3 links).
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct ElasticRod {
  static constexpr std::string_view keyword = "ELASTIC_ROD";
  static constexpr int internals_2d = 1;
  static ElasticRod from_card(const LawParameters& p) { return {p("F/str"), p("prstr")}; }
  double force_per_strain, prestrain;
};

inline void prepare(const ElasticRod& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  spring_form(c, s, law.force_per_strain, law.prestrain, step.h, LocalForm3D::rod);
}

}  // namespace lmgc::solver
