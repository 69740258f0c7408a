#pragma once
// IQS_MAC_CZM: Monerie–Acary–Cangémi cohesive zone with an IQS normal part (contact-laws.md §3.5):
// friction dfric/sfric, stiffnesses cn, ct, viscosity visco and fracture energy dupre of the damage
// β. Internals (2D): L, δt, δn, β, TPSini; (3D): L, δt, δn, δs, β, TPSini (state-and-outputs.md
// §1.4.4). 2D and 3D.
#include "solver/laws/cohesive_zone.hpp"

namespace lmgc::solver {

struct IqsMacCzm {
  static constexpr std::string_view keyword = "IQS_MAC_CZM";
  static constexpr bool in_2d = true, in_3d = true;
  static constexpr int internals_2d = 5;
  double dfric, sfric, cn, ct, visco, dupre;
  static constexpr LawParameter<IqsMacCzm> parameters[] = {
      {"dfric", &IqsMacCzm::dfric}, {"sfric", &IqsMacCzm::sfric}, {"cn", &IqsMacCzm::cn},
      {"ct", &IqsMacCzm::ct},       {"visco", &IqsMacCzm::visco}, {"dupre", &IqsMacCzm::dupre}};
  static double stiffness(double beta) { return beta * beta; }
  void damage(const std::array<double, 6>& internal, const Eigen::Vector2d& u, double h, double& taz) const {
    mac_damage(cn, ct, visco, dupre, internal, u, h, taz);
  }
};

// 2D (cohesive_zone.hpp): β² C, the IQS normal part; L the pair's contact length.
inline void prepare(const IqsMacCzm& law, LocalProblem2D& c, const LawStep& step) {
  prepare_cohesive_zone(law, c, step, iqs_cohesive_length(c), false);
}
inline bool update_at_check(const IqsMacCzm& law, LocalProblem2D& c, const Eigen::Vector2d& u,
                            const LawStep& step) {
  return update_cohesive_zone(law, c, u, step);
}
inline void finish(const IqsMacCzm& law, Interaction2D& c, LawState2D& s, const LawStep& step) {
  finish_cohesive_zone(law, c, s, step);
}

// 3D: the local problem of damage β (iter_CZM_3D :4509-4560, get_fric_CZM :5858-5898): while
// β > 1e-12 the cohesive impulse is −L β² h C (δ_begin + h uu) componentwise, C = diag(ct, cn, ct)
// (the normal δ_begin is folded into uu by the IQS covfree); friction × (1 − β) either way.
inline void use_beta(const IqsMacCzm& law, Interaction3D& c, LawState3D& s, double beta, double h) {
  s.law_working = beta;
  c.mu = (is_sliding(c.status_begin) ? law.dfric : law.sfric) * (1.0 - beta);
  if (beta <= 1e-12) {
    c.form = LocalForm3D::coulomb;
    s.cohesive_slope.setZero();
    s.cohesive_shift.setZero();
    return;
  }
  c.form = LocalForm3D::cohesive;
  const double scale = -s.surface * beta * beta * h;
  s.cohesive_slope = Eigen::Vector3d(scale * law.ct * h, scale * law.cn * h, scale * law.ct * h);
  s.cohesive_shift = Eigen::Vector3d(scale * law.ct * s.internal[1], 0.0, scale * law.ct * s.internal[3]);
}

// updt_CZM_3D (:4856-4925) with the jumps δ + h u: β_new = (h w + β b)/(b + h (ct |δ_t,s|² +
// cn (δn)+²)) from the step's starting β, taken when it does not grow and the stored energy exceeds
// w. False when it is not taken.
inline bool damaged_beta(const IqsMacCzm& law, const LawState3D& s, const Eigen::Vector3d& u, double h,
                         double& beta) {
  const double dt = s.internal[1] + h * u(0), dn = s.internal[2] + h * u(1), ds = s.internal[3] + h * u(2);
  const double beta_start = s.internal[4];
  const double energy = law.ct * (dt * dt + ds * ds) + law.cn * (dn > 0.0 ? dn * dn : 0.0);
  const double denominator = law.visco + h * energy;
  beta = denominator == 0.0 ? 1.0 : (h * law.dupre + beta_start * law.visco) / denominator;
  if (beta < 1e-12) beta = 0.0;
  return beta <= beta_start && law.dupre <= beta_start * energy;
}

// 3D (mod_nlgs_3D prep :1994-2040, init_CZM_3D :4352-4444): at step 1, if it has interactions,
// every internal is reset and β = 1 (other contacts start broken, β = 0); L = the pair's contact
// surface. The step starts from the stored β.
inline void prepare(const IqsMacCzm& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  if (step.first_preparation) {  // as in 2D
    if (step.first_step) s.internal = {0.0, 0.0, 0.0, 0.0, 1.0, -99.0};
    if (c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Cnnow;
  }
  s.internal[0] = s.surface;
  s.internal[2] = positive(c.gap_begin);
  iqs_form(c, step.h);
  use_beta(law, c, s, s.internal[4], step.h);
}

// At each convergence check of the step (solve_nlgs i_check: updt_CZM_3D(.false.)), β is evaluated
// again with the velocity u of the check's local solution; the sweeps after it use the new β. True
// when the contact's local problem changed.
inline bool update_at_check(const IqsMacCzm& law, Interaction3D& c, LawState3D& s, const Eigen::Vector3d& u,
                            const LawStep& step) {
  double beta = 0.0;
  if (!damaged_beta(law, s, u, step.h, beta) || beta == s.law_working) return false;
  use_beta(law, c, s, beta, step.h);
  return true;
}

// 3D damage at the end of the step (updt_CZM_3D, store :5426-5450): β from the final velocity
// when taken, else the last checks' β; the jumps δ += h u; TPSini at first damage. Statuses in
// their C form while cohesive.
inline void finish(const IqsMacCzm& law, Interaction3D& c, LawState3D& s, const LawStep& step) {
  const double h = step.h;
  double beta = 0.0;
  s.internal[4] = damaged_beta(law, s, c.u, h, beta) ? beta : s.law_working;
  s.internal[1] += h * c.u(0);
  s.internal[2] += h * c.u(1);
  s.internal[3] += h * c.u(2);
  if (s.internal[5] == -99.0 && s.internal[4] < 1.0) s.internal[5] = step.time;
  if (c.form == LocalForm3D::cohesive) c.status = cohesive_status(c.status);
}

}  // namespace lmgc::solver
