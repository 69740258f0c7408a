#pragma once
// IQS_DS_CLB: IQS with static/dynamic friction (contact-laws.md §1.3, §3.1). 2D and 3D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsDsClb {
  static constexpr std::string_view keyword = "IQS_DS_CLB";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 0;
  double dfric, sfric;
  static constexpr LawParameter<IqsDsClb> parameters[] = {{"dfric", &IqsDsClb::dfric},
                                                          {"sfric", &IqsDsClb::sfric}};
};

template <class Interaction>
void prepare(const IqsDsClb& law, Interaction& c, const LawStep& step) {
  iqs_form(c, step.h);
  c.mu = static_dynamic(law.dfric, law.sfric, c.status_begin);
}

}  // namespace lmgc::solver
