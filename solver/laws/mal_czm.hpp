#pragma once
// MAL_CZM: a cohesive zone whose traction is β C δ (β, not MAC's β²) with a damage β of bilinear
// softening: elastic up to the opening where the traction reaches the strengths S1 (normal) and S2
// (tangential), then down to 0 over a length set by the energies G1, G2 (cohesive_zone.hpp
// mal_damage); GAP normal part, for deformable pairs (CLALp, CLJCx, PLALp, DKALp). Internals (2D):
// L, δt, δn, β, TPSini. mod_nlgs prep_nlgs (its MAL_CZM case) and mod_tact_behav iter/updt_CZM.
#include "solver/laws/cohesive_zone.hpp"

namespace lmgc::solver {

struct MalCzm {
  static constexpr std::string_view keyword = "MAL_CZM";
  static constexpr bool in_2d = true, in_3d = false;
  static constexpr int internals_2d = 5;
  double dfric, sfric, cn, ct, s1, s2, g1, g2;
  static constexpr LawParameter<MalCzm> parameters[] = {
      {"dfric", &MalCzm::dfric}, {"sfric", &MalCzm::sfric}, {"cn", &MalCzm::cn}, {"ct", &MalCzm::ct},
      {"S1", &MalCzm::s1},       {"S2", &MalCzm::s2},       {"G1", &MalCzm::g1}, {"G2", &MalCzm::g2}};
  static double stiffness(double beta) { return beta; }
  void damage(const std::array<double, 6>& internal, const Eigen::Vector2d& u, double h, double& taz) const {
    mal_damage(cn, ct, s1, s2, g1, g2, internal, u, h, taz);
  }
};

inline void prepare(const MalCzm& law, LocalProblem2D& c, const LawStep& step) {
  prepare_cohesive_zone(law, c, step, gap_cohesive_length(c), true);
}
inline bool update_at_check(const MalCzm& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                            const LawStep& step) {
  return update_cohesive_zone(law, c, u, step);
}
inline void finish(const MalCzm& law, Interaction2D& c, LawState2D& s, const LawStep& step) {
  finish_cohesive_zone(law, c, s, step);
}

}  // namespace lmgc::solver
