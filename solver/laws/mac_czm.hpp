#pragma once
// MAC_CZM: the Monerie–Acary–Cangémi cohesive zone of IQS_MAC_CZM with a GAP normal part, for
// deformable pairs (CLALp, CLJCx, PLALp, DKALp): the end-of-step gap is ≥ 0, or 0 in tension, and
// the stored normal jump may be negative (only its positive part damages). Internals (2D): L, δt,
// δn, β, TPSini. mod_nlgs prep_nlgs (its MAC_CZM case) and mod_tact_behav iter/updt_CZM.
#include "solver/laws/cohesive_zone.hpp"

namespace lmgc::solver {

struct MacCzm {
  static constexpr std::string_view keyword = "MAC_CZM";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 5;
  double dfric, sfric, cn, ct, visco, dupre;
  static constexpr LawParameter<MacCzm> parameters[] = {{"dfric", &MacCzm::dfric}, {"sfric", &MacCzm::sfric},
                                                        {"cn", &MacCzm::cn},       {"ct", &MacCzm::ct},
                                                        {"visco", &MacCzm::visco}, {"dupre", &MacCzm::dupre}};
  static double stiffness(double beta) { return beta * beta; }
  void damage(const std::array<double, 6>& internal, const Eigen::Vector2d& u, double h, double& taz) const {
    mac_damage(cn, ct, visco, dupre, internal, u, h, taz);
  }
};

inline void prepare(const MacCzm& law, LocalProblem2D& c, const LawStep& step) {
  prepare_cohesive_zone(law, c, step, gap_cohesive_length(c), true);
}
inline bool update_at_check(const MacCzm& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                            const LawStep& step) {
  return update_cohesive_zone(law, c, u, step);
}
inline void finish(const MacCzm& law, Interaction2D& c, LawState2D& s, const LawStep& step) {
  finish_cohesive_zone(law, c, s, step);
}

}  // namespace lmgc::solver
