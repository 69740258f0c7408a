#pragma once
// ELASTIC_WIRE: a tension-only linear spring between two points, stiffness F/str per unit strain,
// prestrain prstr, reference length gapREF (internal 1); slack, it carries nothing and the link is
// 'vnish' (contact-laws.md §3.4; mod_nlgs_3D :3937-3950). 3D (PTPT3 links).
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct ElasticWire {
  static constexpr std::string_view keyword = "ELASTIC_WIRE";
  static constexpr bool in_2d = false, in_3d = true;
  static constexpr int internals_2d = 1;
  double force_per_strain, prestrain;
  static constexpr LawParameter<ElasticWire> parameters[] = {{"F/str", &ElasticWire::force_per_strain},
                                                             {"prstr", &ElasticWire::prestrain}};
};

inline void prepare(const ElasticWire& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  spring_form(c, s, law.force_per_strain, law.prestrain, step.h, LocalForm3D::wire);
}

}  // namespace lmgc::solver
