#pragma once
// GAP_WET_DS_CLB: IQS_WET_DS_CLB's reversible cohesion (cohen, a force) inside the wet halo
// γ ≤ Wethk with a GAP normal part; outside the halo the status is left as it was (IQS_WET_DS_CLB
// forces noctc). Internal (2D): L, the CLxxx point's length on CLALp and CLJCx, 0 on other pairs
// (mod_nlgs prep_nlgs, its GAP_WET_DS_CLB case). 2D.
#include "solver/laws/iqs_wet_ds_clb.hpp"

namespace lmgc::solver {

struct GapWetDsClb {
  static constexpr std::string_view keyword = "GAP_WET_DS_CLB";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 1;  // taille_ele
  double cohen, cohet, wethk, dfric, sfric;
  static constexpr LawParameter<GapWetDsClb> parameters[] = {{"cohen", &GapWetDsClb::cohen},
                                                             {"cohet", &GapWetDsClb::cohet},
                                                             {"Wethk", &GapWetDsClb::wethk},
                                                             {"dfric", &GapWetDsClb::dfric},
                                                             {"sfric", &GapWetDsClb::sfric}};
};

inline void prepare(const GapWetDsClb& law, LocalProblem2D& c, const LawStep& step) {
  prepare_wet(law, c, step, true);
}

// The end status in its W form while the step began wet (mod_nlgs solve_nlgs, the WET laws' case):
// a contact wetted once stays so until its status is dry again, in or out of the halo.
inline void finish(const GapWetDsClb&, Interaction2D& c, const LawStep&) {
  const bool began_wet = dry_status(c.status_begin) != c.status_begin;
  c.status = began_wet ? wet_status(c.status) : dry_status(c.status);
}

}  // namespace lmgc::solver
