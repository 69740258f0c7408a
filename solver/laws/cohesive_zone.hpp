#pragma once
// What the 2D cohesive-zone laws share (contact-laws.md §3.5): the local problem of a damage β and
// the two damage evolutions, MAC's (Monerie–Acary–Cangémi: a viscosity and a fracture energy) and
// MAL's (a bilinear-softening envelope of strengths S1, S2 and energies G1, G2). LMGC90's
// mod_tact_behav iter_CZM, updt_CZM and get_fric_CZM.
#include <cmath>

#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

// LMGC90's mac_beta_tol: below it β is 0 and the contact is no longer cohesive.
inline constexpr double kCohesiveBetaTolerance = 1e-12;

// The length L a 2D cohesive law multiplies its tractions by (mod_nlgs prep_nlgs): the pair's contact
// length for the IQS laws (on DKDKx, DKJCx, PLPLx, PLJCx; LMGC90's fixed 0.05 on DKDKL); for the laws
// of deformable pairs, the CLxxx point's share of its edge on CLALp and CLJCx, and LMGC90's fixed 0.35
// on PLALp and DKALp.
inline double iqs_cohesive_length(const Interaction2D& c) {
  return c.family == PairFamily2D::DKDKL ? 0.05 : c.length;
}
inline double gap_cohesive_length(const Interaction2D& c) {
  return c.family == PairFamily2D::CLALp || c.family == PairFamily2D::CLJCx ? c.length : 0.35;
}

// A 2D cohesive-zone law (MAC_CZM, IQS_MAC_CZM, MAL_CZM) has dfric, sfric, cn, ct, its traction's
// factor `stiffness(β)` (β² for MAC's, β for MAL's) and its updt_CZM `damage(internal, u, h, taz)`,
// which updates the working β taz from the jumps δ + h u.
//
// The local problem of damage β (iter_CZM): while β > tol the linear traction −L s(β) h C δ_end as an
// impulse, δ_end = δ_begin + h uu (the normal δ_begin is folded into uu by the normal free velocity);
// friction × (1 − β) either way (get_fric_CZM, power 1). internal[5] holds the β in use (LMGC90's
// taz(1)).
template <class Law>
void use_damage(const Law& law, LocalProblem2D& c, double beta, double h) {
  c.internal[5] = beta;
  c.mu = (is_sliding(c.status_begin) ? law.dfric : law.sfric) * (1.0 - beta);
  c.cohesive = beta > kCohesiveBetaTolerance;
  if (c.cohesive) {
    const double length = c.internal[0], s = law.stiffness(beta);
    c.cohesive_slope = Eigen::Vector2d(-length * s * h * h * law.ct, -length * s * h * h * law.cn);
    c.cohesive_shift_t = -length * s * h * law.ct * c.internal[1];
  } else {
    c.cohesive_slope.setZero();
    c.cohesive_shift_t = 0.0;
  }
}

// MAC's updt_CZM on the working β `taz` (from the step's starting β0 = internal[3] and the jumps
// δ + h u): β* = (h w + β0 b)/(b + h (ct δt² + cn ⟨δn⟩²)), 1 when that denominator is 0; taz = 0
// when β* < tol; taz = β* when β* ≤ β0 and the stored energy reaches w.
inline void mac_damage(double cn, double ct, double visco, double dupre,
                       const std::array<double, 6>& internal, const Eigen::Vector2d& u, double h,
                       double& taz) {
  const double dt = internal[1] + h * u(0), dn = internal[2] + h * u(1);
  const double beta_start = internal[3];
  const double energy = ct * (dt * dt) + cn * (dn > 0.0 ? dn * dn : 0.0);
  const double denominator = visco + h * energy;
  const double beta = denominator == 0.0 ? 1.0 : (h * dupre + beta_start * visco) / denominator;
  if (beta < kCohesiveBetaTolerance) taz = 0.0;
  if (beta <= beta_start && dupre <= beta_start * energy) taz = beta;
}

// MAL's updt_CZM: with the opening d = |(δt, ⟨δn⟩)| and its mode mix r² = δt²/⟨δn⟩² (1e20 in pure
// shear), the elastic limit dc = (S1/cn)(S2/ct) √((1 + r²)/((S2/ct)² + r² (S1/cn)²)) and the
// softening length dt = 1.5 (G1 G2 − ½ dc² G)/(dc G), G = (G2 cn + G1 ct r²)/(1 + r²) (the product
// G1 G2 is LMGC90's): β = min(β0, 1) below dc, min(β0, (dc/d)(1 − ((d − dc)/dt)²)) up to dc + dt,
// 0 past it. Always taken.
inline void mal_damage(double cn, double ct, double s1, double s2, double g1, double g2,
                       const std::array<double, 6>& internal, const Eigen::Vector2d& u, double h,
                       double& taz) {
  const double dt = internal[1] + h * u(0), dn = internal[2] + h * u(1);
  const double beta_start = internal[3];
  const double normal_opening = (std::fabs(dn) + dn) * 0.5;
  const double tangential2 = dt * dt, normal2 = normal_opening * normal_opening;
  const double opening = std::sqrt(tangential2 + normal2);
  const double mix2 = normal2 > 0.0 ? tangential2 / normal2 : 1e20;
  const double limit_n = s1 / cn, limit_t = s2 / ct;
  const double energy = (g2 * cn / (1.0 + mix2)) + (g1 * ct * mix2 / (1.0 + mix2));
  const double dc =
      limit_n * limit_t * std::sqrt((1.0 + mix2) / ((limit_t * limit_t) + mix2 * (limit_n * limit_n)));
  const double softening = 1.5 * (g1 * g2 - (0.5 * dc * dc * energy)) / (dc * energy);
  if (opening < dc) {
    taz = std::min(beta_start, 1.0);
  } else if (opening < dc + softening) {
    const double x = (opening - dc) / softening;
    taz = std::min(beta_start, (dc / opening) * (1.0 - x * x));
  } else {
    taz = 0.0;
  }
}

// The step's local problem (mod_nlgs prep_nlgs). At the run's first preparation with interactions
// nknow becomes Cnnow, and init_CZM makes the interface sound (β = 1) if that is step 1; any other
// contact keeps its internals (β = 0 for one created later: broken from the start). Then L, and the
// normal part: IQS ((γ)+/h, δn = (γ)+) or, with `gap_normal`, GAP (γ/h, δn = γ, which may be < 0).
template <class Law>
void prepare_cohesive_zone(const Law& law, LocalProblem2D& c, const LawStep& step, double length,
                           bool gap_normal) {
  if (step.first_preparation) {
    if (step.first_step) c.internal = {0.0, 0.0, 0.0, 1.0, -99.0, 0.0};
    if (c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Cnnow;
  }
  c.internal[0] = length;
  if (gap_normal) {
    c.internal[2] = c.gap_begin;
    gap_form(c, step.h);
  } else {
    c.internal[2] = positive(c.gap_begin);
    iqs_form(c, step.h);
  }
  use_damage(law, c, c.internal[3], step.h);
}

// β evaluated again at each convergence check (updt_CZM(.false.) at i_check in mod_nlgs) from the
// check's velocity; the sweeps after it use it. True when the local problem changed.
template <class Law>
bool update_cohesive_zone(const Law& law, LocalProblem2D& c, const Eigen::Vector2d& u, const LawStep& step) {
  double beta = c.internal[5];
  law.damage(c.internal, u, step.h, beta);
  if (beta == c.internal[5]) return false;
  use_damage(law, c, beta, step.h);
  return true;
}

// End of step (updt_CZM with store): the working β from the final velocity, the jumps δ += h u,
// TPSini at first damage.
template <class Law>
void finish_cohesive_zone(const Law& law, const Interaction2D& c, LawState2D& s, const LawStep& step) {
  double taz = s.internal[5];
  law.damage(s.internal, c.u, step.h, taz);
  s.internal[1] += step.h * c.u(0);
  s.internal[2] += step.h * c.u(1);
  s.internal[3] = taz;
  s.internal[5] = 0.0;
  if (s.internal[3] < 1.0 && s.internal[4] < 0.0) s.internal[4] = step.time;
}

}  // namespace lmgc::solver
