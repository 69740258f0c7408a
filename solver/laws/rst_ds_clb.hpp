#pragma once
// RST_DS_CLB: restitution + static/dynamic Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct RstDsClb {
  static constexpr std::string_view keyword = "RST_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double restn, restt, dfric, sfric;
  static constexpr LawParameter<RstDsClb> parameters[] = {{"restn", &RstDsClb::restn},
                                                          {"restt", &RstDsClb::restt},
                                                          {"dfric", &RstDsClb::dfric},
                                                          {"sfric", &RstDsClb::sfric}};
};

template <class Interaction>
void prepare(const RstDsClb& law, Interaction& c, const LawStep&) {
  restitution_form(c, law.restn, law.restt);
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

}  // namespace lmgc::solver
