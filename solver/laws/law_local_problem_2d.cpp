// spec: contact-laws.md §2 (derived Signorini–Coulomb), §3.1-3.4 (laws one by one).
#include "solver/laws/law_local_problem_2d.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace lmgc::solver {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

using Eigen::Vector2d;

double positive(double x) {
  return x > 0.0 ? x : 0.0;
}

// §1.3: dynamic friction when the contact was sliding at the beginning of the step.
double static_dynamic(double dfric, double sfric, ContactStatus begin) {
  return is_sliding(begin) ? dfric : sfric;
}

// "IQS form": the bodies may close an open gap within the step, no push-out when penetrated.
void iqs_form(Interaction2D& c, double h) {
  c.covfree(1) = positive(c.gap_begin) / h;
}
// "GAP form": the end-of-step gap must be >= 0 (penetrations corrected in one step).
void gap_form(Interaction2D& c, double h) {
  c.covfree(1) = c.gap_begin / h;
}

// Cohesion c (force) acting through the normal: rr_n = r_n + c h >= 0 (§3.2).
void add_cohesion(Interaction2D& c, double cohesion, double h) {
  c.covfree(0) -= cohesion * h * c.W(0, 1);
  c.covfree(1) -= cohesion * h * c.WW(1, 1);
  c.correction(1) = -cohesion * h;
}

bool is_wet_law(const ContactLaw& law) {
  return std::holds_alternative<IqsWetDsClb>(law);
}

}  // namespace

void prepare_local_problem_2d(const ContactLaw& law, Interaction2D& c, double h) {
  c.WW = c.W;
  c.covfree.setZero();
  c.correction.setZero();
  c.inactive = false;
  c.mu = 0.0;
  std::visit(Overloaded{
                 [&](const IqsClb& p) {
                   iqs_form(c, h);
                   c.mu = p.sfric;
                 },
                 [&](const IqsDsClb& p) {
                   iqs_form(c, h);
                   c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                 },
                 [&](const IqsClbG0& p) {
                   // g_ref = (γ)+ at the first step of the interaction (internal 1).
                   if (c.status_begin == ContactStatus::nknow) c.internal[0] = positive(c.gap_begin);
                   c.covfree(1) = positive(c.gap_begin - c.internal[0]) / h;
                   c.mu = p.sfric;
                 },
                 [&](const RstClb& p) {
                   if (c.gap_begin > 0.0) {
                     c.inactive = true;
                     return;
                   }
                   c.covfree = Vector2d(p.restt * c.velocity_begin(0), p.restn * c.velocity_begin(1));
                   c.mu = p.sfric;
                 },
                 [&](const RstDsClb& p) {
                   if (c.gap_begin > 0.0) {
                     c.inactive = true;
                     return;
                   }
                   c.covfree = Vector2d(p.restt * c.velocity_begin(0), p.restn * c.velocity_begin(1));
                   c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                 },
                 [&](const GapSgrClb& p) {
                   gap_form(c, h);
                   c.mu = p.sfric;
                 },
                 [&](const GapSgrDsClb& p) {
                   gap_form(c, h);
                   c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                 },
                 [&](const VelSgrClb& p) {
                   // Active only once the gap is closed (Moreau's velocity Signorini).
                   c.inactive = c.gap_begin > 0.0;
                   c.mu = p.sfric;
                 },
                 [&](const VelSgrDsClb& p) {
                   c.inactive = c.gap_begin > 0.0;
                   c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                 },
                 [&](const ElasticRepellClb& p) {
                   // Spring in series: r_n = -h k γ_end gives WWnn = Wnn + 1/(k h²), covfree = γ/h (§3.3).
                   if (p.stiffness > 0.0) c.WW(1, 1) = c.W(1, 1) + 1.0 / (p.stiffness * h * h);
                   gap_form(c, h);
                   c.mu = p.sfric;
                 },
                 [&](const IqsMohrDsClb& p) {
                   if (c.status_begin == ContactStatus::nknow) c.status_begin = ContactStatus::Mstck;
                   if (c.status_begin == ContactStatus::Mstck) {
                     iqs_form(c, h);
                     add_cohesion(c, p.cohen * c.length, h);
                     c.mu = p.cohen > 0.0 ? p.cohet / p.cohen : p.sfric;
                   } else {
                     iqs_form(c, h);
                     c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                   }
                 },
                 [&](const IqsWetDsClb& p) {
                   if (c.gap_begin <= p.wethk) {
                     c.status_begin = wet_status(c.status_begin);
                     iqs_form(c, h);
                     add_cohesion(c, p.cohen, h);
                   } else {
                     c.status_begin = ContactStatus::noctc;
                     iqs_form(c, h);
                   }
                   c.mu = static_dynamic(p.dfric, p.sfric, c.status_begin);
                 },
                 [&](const IqsMacCzm& p) {
                   // Internals (2D): L, δt, δn, β, TPSini (state-and-outputs.md §1.4.4).
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
                   c.mu = (sliding ? p.dfric : p.sfric) * (1.0 - beta);
                   c.cohesive = beta > 1e-12;
                   if (c.cohesive) {
                     // Linear traction β² C δ_end on the length L, as an impulse over the step.
                     const double b2 = beta * beta;
                     c.cohesive_slope = Vector2d(-length * b2 * h * h * p.ct, -length * b2 * h * h * p.cn);
                     c.cohesive_shift_t = -length * b2 * h * p.ct * c.internal[1];
                   } else {
                     c.cohesive_slope.setZero();
                     c.cohesive_shift_t = 0.0;
                   }
                 },
                 [&](const CoupledDof&) { c.mu = 0.0; },
                 [&](const NoNlgsBranch& p) { c.mu = p.sfric; },
             },
             law);
  // Guard of the tangential term for degenerate blocks (§2).
  if (c.WW(0, 0) <= 1e-6 * c.WW(1, 1)) c.WW(0, 0) = 1e-6 * c.WW(1, 1);
}

LocalSolution2D solve_local_problem_2d(const ContactLaw& law, const Interaction2D& c,
                                       const Vector2d& ufree_loc) {
  const Vector2d vv = ufree_loc + c.covfree;
  LocalSolution2D s;
  if (c.inactive) return s;
  if (std::holds_alternative<CoupledDof>(law)) {
    // Bilateral glue: u = 0 on both components.
    s.r = -c.WW.inverse() * vv;
    s.status = ContactStatus::stick;
    return s;
  }
  s = solve_signorini_coulomb_2d(c.WW, vv, c.mu);
  s.r += c.correction;
  if (is_wet_law(law) && !(c.correction.array() == 0.0).all()) s.status = wet_status(s.status);
  return s;
}

double local_residual_squared_2d(const ContactLaw& law, const Interaction2D& c, const Vector2d& r,
                                 const Vector2d& ufree_loc) {
  if (c.inactive) return r.squaredNorm();
  const Vector2d rr = r - c.correction;
  const Vector2d uu = ufree_loc + c.covfree + c.WW * rr;
  if (std::holds_alternative<CoupledDof>(law)) return uu.squaredNorm();
  return natural_map_residual_squared_2d(rr, uu, c.mu);
}

void finish_step_2d(const ContactLaw& law, Interaction2D& c, double h, double time) {
  std::visit(Overloaded{
                 [&](const IqsMacCzm& p) {
                   // Damage of the MAC law (contact-laws.md §3.5): jumps from the final velocity.
                   const double dt = c.internal[1] + h * c.u(0);
                   const double dn = c.internal[2] + h * c.u(1);
                   c.internal[1] = dt;
                   c.internal[2] = dn;
                   const double beta_old = c.internal[3];
                   const double nt = dt * dt, nn = dn > 0.0 ? dn * dn : 0.0;
                   const double energy = p.ct * nt + p.cn * nn;
                   double beta = (h * p.dupre + beta_old * p.visco) / (p.visco + h * energy);
                   if (beta < 1e-12) beta = 0.0;
                   if (beta <= beta_old && p.dupre <= beta_old * energy) c.internal[3] = beta;
                   if (c.internal[3] < 1.0 && c.internal[4] < 0.0) c.internal[4] = time;
                 },
                 [&](const IqsMohrDsClb&) {
                   // Cohesion survives only while the contact sticks (§3.2).
                   if (c.status_begin == ContactStatus::Mstck && c.status == ContactStatus::stick)
                     c.status = ContactStatus::Mstck;
                 },
                 [&](const IqsWetDsClb&) {
                   if (c.correction(1) == 0.0) c.status = dry_status(c.status);
                 },
                 [&](const auto&) {},
             },
             law);
}

}  // namespace lmgc::solver
