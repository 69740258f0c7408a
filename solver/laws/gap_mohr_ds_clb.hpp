#pragma once
// GAP_MOHR_DS_CLB: IQS_MOHR_DS_CLB's Mohr–Coulomb cohesion (cohen × the CLxxx point's length, until
// the contact first stops sticking) with a GAP normal part, for CLALp and CLJCx (contact-laws.md
// §3.2; mod_nlgs prep_nlgs, its GAP_MOHR_DS_CLB case). 2D.
#include "solver/laws/iqs_mohr_ds_clb.hpp"

namespace lmgc::solver {

struct GapMohrDsClb {
  static constexpr std::string_view keyword = "GAP_MOHR_DS_CLB";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 0;
  double cohen, cohet, dfric, sfric;
  static constexpr LawParameter<GapMohrDsClb> parameters[] = {{"cohen", &GapMohrDsClb::cohen},
                                                              {"cohet", &GapMohrDsClb::cohet},
                                                              {"dfric", &GapMohrDsClb::dfric},
                                                              {"sfric", &GapMohrDsClb::sfric}};
  double cohesive_friction() const { return cohen > 0.0 ? cohet / cohen : sfric; }
};

inline void prepare(const GapMohrDsClb& law, LocalProblem2D& c, const LawStep& step) {
  prepare_mohr(law, c, step, c.length, true);
}
inline void finish(const GapMohrDsClb&, Interaction2D& c, const LawStep&) {
  keep_mohr_bond(c);
}

}  // namespace lmgc::solver
