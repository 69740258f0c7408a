#pragma once
// IQS_MAC_CZM: Monerie–Acary–Cangémi cohesive zone with an IQS normal part (contact-laws.md §3.5):
// friction dfric/sfric, stiffnesses cn, ct, viscosity visco and fracture energy dupre of the damage
// β. Internals (2D): L, δt, δn, β, TPSini (state-and-outputs.md §1.4.4). 2D.
#include "solver/laws/law_forms.hpp"

namespace lmgc::solver {

struct IqsMacCzm {
  static constexpr std::string_view keyword = "IQS_MAC_CZM";
  static constexpr int internals_2d = 5;
  static IqsMacCzm from_card(const LawParameters& p) {
    return {p("dfric"), p("sfric"), p("cn"), p("ct"), p("visco"), p("dupre")};
  }
  double dfric, sfric, cn, ct, visco, dupre;
};

inline void prepare(const IqsMacCzm& law, Interaction2D& c, const LawStep& step) {
  const double h = step.h;
  if (c.status_begin == ContactStatus::nknow) {
    c.internal = {0.0, 0.0, 0.0, 1.0, -99.0, 0.0};
    c.status_begin = ContactStatus::Cnnow;
  }
  const double length = c.length;
  const double beta = c.internal[3];
  c.internal[0] = length;
  c.internal[2] = positive(c.gap_begin);
  iqs_form(c, h);
  const bool sliding = is_sliding(c.status_begin);
  c.mu = (sliding ? law.dfric : law.sfric) * (1.0 - beta);
  c.cohesive = beta > 1e-12;
  if (c.cohesive) {
    // Linear traction β² C δ_end on the length L, as an impulse over the step.
    const double b2 = beta * beta;
    c.cohesive_slope = Eigen::Vector2d(-length * b2 * h * h * law.ct, -length * b2 * h * h * law.cn);
    c.cohesive_shift_t = -length * b2 * h * law.ct * c.internal[1];
  } else {
    c.cohesive_slope.setZero();
    c.cohesive_shift_t = 0.0;
  }
}

// Damage (§3.5): jumps from the final velocity, β from the energy balance, TPSini at first damage.
inline void finish(const IqsMacCzm& law, Interaction2D& c, const LawStep& step) {
  const double h = step.h;
  const double dt = c.internal[1] + h * c.u(0);
  const double dn = c.internal[2] + h * c.u(1);
  c.internal[1] = dt;
  c.internal[2] = dn;
  const double beta_old = c.internal[3];
  const double nt = dt * dt, nn = dn > 0.0 ? dn * dn : 0.0;
  const double energy = law.ct * nt + law.cn * nn;
  double beta = (h * law.dupre + beta_old * law.visco) / (law.visco + h * energy);
  if (beta < 1e-12) beta = 0.0;
  if (beta <= beta_old && law.dupre <= beta_old * energy) c.internal[3] = beta;
  if (c.internal[3] < 1.0 && c.internal[4] < 0.0) c.internal[4] = step.time;
}

}  // namespace lmgc::solver
