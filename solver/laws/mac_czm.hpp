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
};

inline void prepare(const MacCzm& law, LocalProblem2D& c, const LawStep& step) {
  start_damage(c, step);
  c.internal[0] = gap_cohesive_length(c);
  c.internal[2] = c.gap_begin;
  gap_form(c, step.h);
  use_damage(c, c.internal[3], c.internal[3] * c.internal[3], law.cn, law.ct, law.dfric, law.sfric, step.h);
}

inline bool update_at_check(const MacCzm& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                            const LawStep& step) {
  double beta = c.internal[5];
  mac_damage(law.cn, law.ct, law.visco, law.dupre, c.internal, u, step.h, beta);
  if (beta == c.internal[5]) return false;
  use_damage(c, beta, beta * beta, law.cn, law.ct, law.dfric, law.sfric, step.h);
  return true;
}

inline void finish(const MacCzm& law, Interaction2D& c, LawState2D& s, const LawStep& step) {
  store_damage(s, c.u, step, [&](double& taz) {
    mac_damage(law.cn, law.ct, law.visco, law.dupre, s.internal, c.u, step.h, taz);
  });
}

}  // namespace lmgc::solver
