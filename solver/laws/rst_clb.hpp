#pragma once
// RST_CLB: Newton restitution (restn, restt) + Coulomb (contact-laws.md §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct RstClb {
  static constexpr std::string_view keyword = "RST_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double restn, restt, sfric;
  static constexpr LawParameter<RstClb> parameters[] = {
      {"restn", &RstClb::restn}, {"restt", &RstClb::restt}, {"sfric", &RstClb::sfric}};
};

template <class Interaction>
void prepare(const RstClb& law, Interaction& c, const LawStep&) {
  restitution_form(c, law.restn, law.restt);
  c.mu = law.sfric;
}

}  // namespace lmgc::solver
