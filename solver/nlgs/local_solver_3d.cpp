#include "solver/nlgs/local_solver_3d.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace lmgc::solver {

namespace {

constexpr int kMaxNewtonIterations = 40;
// Relative round-off of a local residual: 1e-14 ≈ 45 ulps of the terms r, W r and q it is made of.
constexpr double kRoundOff = 1e-14;
constexpr int kMaxLineSearchHalvings = 30;
constexpr int kMaxFixedPointIterations = 2000;

// Alart–Curnier map of one contact in its "radius mu r_n" form (docs/lmgc90-facts/contact-laws.md §2.2) and
// its generalised Jacobian.
struct AlartCurnier {
  const Eigen::Matrix3d& W;
  const Eigen::Vector3d& q;
  double mu, rho_n, rho_t;

  Eigen::Vector3d value(const Eigen::Vector3d& r, Eigen::Matrix3d* jacobian) const {
    const Eigen::Vector3d u = W * r + q;
    Eigen::Vector3d phi;
    // Normal part: rn = max(0, rn - rho_n un).
    if (r(0) - rho_n * u(0) > 0.0) {
      phi(0) = rho_n * u(0);
      if (jacobian) jacobian->row(0) = rho_n * W.row(0);
    } else {
      phi(0) = r(0);
      if (jacobian) jacobian->row(0) = Eigen::RowVector3d(1.0, 0.0, 0.0);
    }
    // Tangential part: r_T = projection of r_T - rho_t u_T on the disc of radius mu rn.
    const Eigen::Vector2d z = r.tail<2>() - rho_t * u.tail<2>();
    const double radius = mu * std::max(r(0), 0.0);
    const double z_norm = z.norm();
    if (z_norm <= radius || z_norm == 0.0) {
      phi.tail<2>() = rho_t * u.tail<2>();
      if (jacobian) jacobian->bottomRows<2>() = rho_t * W.bottomRows<2>();
    } else {
      const Eigen::Vector2d direction = z / z_norm;
      phi.tail<2>() = r.tail<2>() - radius * direction;
      if (jacobian) {
        Eigen::Matrix<double, 2, 3> dz = -rho_t * W.bottomRows<2>();
        dz(0, 1) += 1.0;
        dz(1, 2) += 1.0;
        const Eigen::Matrix2d tangent_projector =
            (Eigen::Matrix2d::Identity() - direction * direction.transpose()) / z_norm;
        Eigen::Matrix<double, 2, 3> J = -radius * tangent_projector * dz;
        J(0, 1) += 1.0;
        J(1, 2) += 1.0;
        if (r(0) > 0.0) J.col(0) -= mu * direction;
        jacobian->bottomRows<2>() = J;
      }
    }
    return phi;
  }
};

// LMGC90's augmentation parameters: rho_n = 1/Wnn, rho_t = lambda_min / lambda_max^2 of the
// (symmetrised) tangential block.
void augmentation_parameters(const Eigen::Matrix3d& W, double& rho_n, double& rho_t) {
  rho_n = W(0, 0) > 0.0 ? 1.0 / W(0, 0) : 1.0;
  const double a = W(1, 1), d = W(2, 2), b = 0.5 * (W(1, 2) + W(2, 1));
  const double sum = a + d;
  const double root = std::sqrt(std::max(0.0, (a - d) * (a - d) + 4.0 * b * b));
  const double lambda_max = 0.5 * (sum + root), lambda_min = 0.5 * (sum - root);
  if (lambda_max <= 0.0)
    rho_t = rho_n;
  else if (lambda_min <= 1e-12 * lambda_max)
    rho_t = 1.0 / lambda_max;
  else
    rho_t = lambda_min / (lambda_max * lambda_max);
}

// Off-diagonal terms negligible (both triangles: FCLIB blocks need not be symmetric) and
// W_tt = W_ss, to 1e-12 of the diagonal (normal-first order).
bool uncoupled_isotropic(const Eigen::Matrix3d& W) {
  const double scale = 1e-12 * (std::fabs(W(0, 0)) + std::fabs(W(1, 1)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j && !(std::fabs(W(i, j)) <= scale)) return false;
  return std::fabs(W(1, 1) - W(2, 2)) <= scale;
}

LocalCase3D classify(const Eigen::Vector3d& r, double mu) {
  if (r(0) <= 0.0) return LocalCase3D::take_off;
  return r.tail<2>().norm() < mu * r(0) * (1.0 - 1e-10) ? LocalCase3D::stick : LocalCase3D::slide;
}

// Sliding solutions by the direction angle phi of r_T: r = r_n (1, mu d), d = (cos phi, sin phi),
// u_n = 0 gives r_n = -q_n / den(phi), den = W_nn + mu W_nT d (> 0 needed), and u_T must be
// anti-parallel to d. G(phi) = den * (d x u_T) is smooth (no pole at den = 0); its roots with den > 0
// and d . u_T <= 0 are the sliding solutions. The zeros of den are added to the grid so that a root
// lying between the last grid node and a zero of den (r_n very large) is still bracketed.
bool enumerate_sliding(const Eigen::Matrix3d& W, const Eigen::Vector3d& q, double mu, Eigen::Vector3d& out,
                       double& out_res) {
  if (mu <= 0.0 || q(0) >= 0.0) return false;
  const auto den_of = [&](double phi) {
    return W(0, 0) + mu * (W(0, 1) * std::cos(phi) + W(0, 2) * std::sin(phi));
  };
  const auto G = [&](double phi) {
    const Eigen::Vector2d d(std::cos(phi), std::sin(phi));
    const double den = den_of(phi);
    // den * u_T = -q_n (W_Tn + mu W_TT d) + den q_T
    const Eigen::Vector2d v =
        -q(0) * (W.col(0).tail<2>() + mu * W.bottomRightCorner<2, 2>() * d) + den * q.tail<2>();
    return d(0) * v(1) - d(1) * v(0);
  };
  const auto reaction = [&](double phi) {
    const double rn = -q(0) / den_of(phi);
    return Eigen::Vector3d(rn, mu * rn * std::cos(phi), mu * rn * std::sin(phi));
  };
  std::vector<double> nodes;
  const int n = 360;
  for (int k = 0; k <= n; ++k) nodes.push_back(-std::numbers::pi + 2.0 * std::numbers::pi * k / n);
  const double a = mu * W(0, 1), b = mu * W(0, 2), rho = std::hypot(a, b);
  if (rho > 0.0 && std::fabs(W(0, 0)) <= rho) {
    const double psi = std::atan2(b, a), delta = std::acos(-W(0, 0) / rho);
    for (double phi : {psi + delta, psi - delta}) {
      phi = std::remainder(phi, 2.0 * std::numbers::pi);
      nodes.push_back(phi);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  bool found = false;
  out_res = 1e300;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    double lo = nodes[k], hi = nodes[k + 1];
    const double mid = 0.5 * (lo + hi);
    if (!(den_of(mid) > 0.0)) continue;
    double g_lo = G(lo);
    const double g_hi = G(hi);
    if ((g_lo <= 0.0) == (g_hi <= 0.0)) continue;
    for (int it = 0; it < 200 && hi - lo > 0.0; ++it) {
      const double m = 0.5 * (lo + hi);
      if (m <= lo || m >= hi) break;
      const double gm = G(m);
      if ((gm <= 0.0) == (g_lo <= 0.0)) {
        lo = m;
        g_lo = gm;
      } else {
        hi = m;
      }
    }
    for (const double phi : {lo, hi}) {
      if (!(den_of(phi) > 0.0)) continue;
      const Eigen::Vector3d r = reaction(phi);
      const double res = natural_map_3d(r, W * r + q, mu).norm();
      if (res < out_res) {
        out_res = res;
        out = r;
        found = true;
      }
    }
  }
  return found;
}

}  // namespace

LocalSolution3D solve_signorini_coulomb_3d(const Eigen::Matrix3d& W, const Eigen::Vector3d& q, double mu,
                                           const Eigen::Vector3d& r_start, double tolerance) {
  return solve_signorini_coulomb_3d(W, nullptr, q, mu, r_start, tolerance);
}

LocalSolution3D solve_signorini_coulomb_3d(const Eigen::Matrix3d& W, const Eigen::Matrix3d* W_inverse_given,
                                           const Eigen::Vector3d& q, double mu,
                                           const Eigen::Vector3d& r_start, double tolerance, double forcing,
                                           double keep_tolerance) {
  LocalSolution3D s;
  // A caller's inverse is all NaN when W is singular or not finite (then W is checked here); the
  // caller computed it once per step, so W needs no check per call.
  const bool given = W_inverse_given && !std::isnan((*W_inverse_given)(0, 0));
  if (!q.allFinite() || (!given && !W.allFinite())) {
    s.failed = true;
    return s;
  }
  // Take-off: r = 0 solves the problem whenever the free velocity separates.
  if (q(0) >= 0.0) return s;

  // Sticking: u = 0, r = -W⁻¹ q, valid when it lies inside the cone. The inverse is the caller's
  // when given (once per contact and step), else by cofactors here.
  Eigen::Matrix3d own_inverse;
  bool invertible = given;
  if (!W_inverse_given) {
    const double scale = W.cwiseAbs().maxCoeff();
    W.computeInverseWithCheck(own_inverse, invertible, 1e-14 * scale * scale * scale);
  }
  if (invertible) {
    const Eigen::Matrix3d& W_inverse = given ? *W_inverse_given : own_inverse;
    const Eigen::Vector3d r_stick = -W_inverse * q;
    if (r_stick(0) > 0.0 && r_stick.tail<2>().norm() <= mu * r_stick(0)) {
      // A previous reaction that already sticks within keep_tolerance is kept, so that converged
      // sweeps stand still instead of trading round-off. The natural map, at most (1 + mu) |u| near
      // the cone's interior, is computed only when that bound passes. u = W r_start + q directly:
      // as W (r_start - r_stick) it carried r_stick's round-off, which an ill-conditioned block
      // amplifies beyond the keep tolerance (a property test's nearly rank-one W).
      if (keep_tolerance > 0.0 && r_start(0) > 0.0 && r_start != r_stick) {
        const double bound = keep_tolerance / (1.0 + mu);
        const Eigen::Vector3d u_start = W * r_start + q;
        if (u_start.squaredNorm() <= bound * bound) {
          const double residual = natural_map_3d(r_start, u_start, mu).norm();
          if (residual <= keep_tolerance) {
            s.r = r_start;
            s.residual = residual;
            s.state = classify(r_start, mu);
            return s;
          }
        }
      }
      // Inside the cone with u = W r + q = 0: exact up to the round-off of the inverse, checked
      // only when this function inverted W itself (a caller's inverse is trusted).
      s.r = r_stick;
      s.state = LocalCase3D::stick;
      if (W_inverse_given) return s;
      s.residual = natural_map_3d(s.r, W * s.r + q, mu).norm();
      if (s.residual <= tolerance) return s;
    }
  }

  // The residual round-off allows at the scale of this contact: a tolerance below it (heavy bodies:
  // r of 1e4 against u of 1) cannot be met, and chasing it through the fallbacks below costs many
  // Newton solves for nothing.
  const auto bound_of = [&](const Eigen::Vector3d& r, const Eigen::Vector3d& Wr) {
    return std::max(tolerance, kRoundOff * (r.norm() + Wr.norm() + q.norm()));
  };
  const auto attainable = [&](const Eigen::Vector3d& r) { return bound_of(r, W * r); };
  // The natural-map residual of r and that bound, from one product W r.
  const auto evaluate = [&](const Eigen::Vector3d& r, double& residual, double& bound) {
    const Eigen::Vector3d Wr = W * r;
    residual = natural_map_3d(r, Wr + q, mu).norm();
    bound = bound_of(r, Wr);
  };

  // Evaluates x; when it solves the problem within its bound, it becomes the answer.
  const auto answers = [&](const Eigen::Vector3d& x, double& residual, double& bound) {
    evaluate(x, residual, bound);
    if (!(residual <= bound)) return false;  // NaN (an overflowing candidate) is no answer
    s.r = x;
    s.residual = residual;
    s.state = classify(x, mu);
    return true;
  };
  // Sliding (or a near-singular block): generalised Newton on the Alart–Curnier map, from the
  // previous reaction. In NLGS sweeps that start often already solves the problem (the others moved
  // little): then it is returned without building the map.
  Eigen::Vector3d r = r_start.allFinite() ? project_on_coulomb_cone(r_start, mu) : Eigen::Vector3d::Zero();
  double best_residual = 0.0, best_bound = 0.0;  // set on both paths below
  if (r(0) > 0.0 && answers(r, best_residual, best_bound)) return s;
  // A block without normal–tangential coupling and with an isotropic tangential part (a sphere
  // against a sphere or a plane: W_nT = 0, W_TT = α I up to round-off) slides in closed form:
  // r_n = -q_n / W_nn and r_T on the cone's edge against q_T. Checked like any answer; it spares
  // those contacts a sliding Newton solve.
  if (uncoupled_isotropic(W) && W(0, 0) > 0.0) {
    const double rn = -q(0) / W(0, 0);
    const double qt_norm = q.tail<2>().norm();
    Eigen::Vector3d slide(rn, 0.0, 0.0);
    if (qt_norm > 0.0) slide.tail<2>() = (-mu * rn / qt_norm) * q.tail<2>();
    double residual, bound;
    if (answers(slide, residual, bound)) return s;
  }
  double rho_n, rho_t;
  augmentation_parameters(W, rho_n, rho_t);
  const AlartCurnier map{W, q, mu, rho_n, rho_t};
  if (r(0) <= 0.0) {
    r = Eigen::Vector3d(-q(0) * rho_n, 0.0, 0.0);
    evaluate(r, best_residual, best_bound);
  }
  // Inexact solve: also done once the residual is `forcing` times the start's (0: off).
  const double forced = std::isfinite(best_residual) ? forcing * best_residual : 0.0;
  const auto done = [&](double residual, double bound) { return residual <= std::max(bound, forced); };
  Eigen::Vector3d best = r;
  Eigen::Matrix3d J;
  Eigen::Vector3d phi = map.value(r, &J);
  double merit = phi.squaredNorm();
  int iteration = 0;
  for (; iteration < kMaxNewtonIterations && !done(best_residual, best_bound); ++iteration) {
    // Newton step by cofactors (J is 3×3); a singular J falls back to the steepest descent.
    const Eigen::Vector3d c0 = J.row(1).cross(J.row(2)).transpose();
    const double det = J.row(0).dot(c0.transpose());
    Eigen::Vector3d step = -phi;
    if (det != 0.0 && std::isfinite(det)) {
      Eigen::Matrix3d adjugate;
      adjugate.col(0) = c0;
      adjugate.col(1) = J.row(2).cross(J.row(0)).transpose();
      adjugate.col(2) = J.row(0).cross(J.row(1)).transpose();
      step = -(adjugate * phi) / det;
      if (!step.allFinite()) step = -phi;
    }
    double t = 1.0;
    Eigen::Vector3d trial;
    Eigen::Vector3d trial_phi;
    Eigen::Matrix3d trial_J;
    bool accepted = false;
    for (int halving = 0; halving < kMaxLineSearchHalvings; ++halving, t *= 0.5) {
      trial = r + t * step;
      trial_phi = map.value(trial, &trial_J);
      if (trial_phi.squaredNorm() <= (1.0 - 1e-4 * t) * merit) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    r = trial;
    phi = trial_phi;
    J = trial_J;
    merit = phi.squaredNorm();
    const Eigen::Vector3d admissible = project_on_coulomb_cone(r, mu);
    double residual, bound;
    evaluate(admissible, residual, bound);
    if (residual < best_residual) {
      best_residual = residual;
      best_bound = bound;
      best = admissible;
    }
  }
  s.newton_iterations = iteration;
  if (!done(best_residual, best_bound)) {
    // Near a direction where W_nn + mu W_nT d vanishes r_n is huge and the damped Newton does not
    // get there: enumerate the sliding directions instead.
    Eigen::Vector3d enumerated;
    double enumerated_residual;
    if (enumerate_sliding(W, q, mu, enumerated, enumerated_residual) && enumerated_residual < best_residual) {
      best = enumerated;
      best_residual = enumerated_residual;
    }
  }

  // Fallback: the projected fixed point r <- P_K(r - rho (u + mu |u_T| e_n)), keeping the best iterate.
  if (!done(best_residual, attainable(best))) {
    const double rho = 1.0 / std::max(W.norm(), 1e-300);
    r = best;
    for (int k = 0; k < kMaxFixedPointIterations && !done(best_residual, attainable(best)); ++k) {
      const Eigen::Vector3d u = W * r + q;
      Eigen::Vector3d x = r - rho * u;
      x(0) -= rho * mu * u.tail<2>().norm();
      r = project_on_coulomb_cone(x, mu);
      const double residual = natural_map_3d(r, W * r + q, mu).norm();
      if (residual < best_residual) {
        best_residual = residual;
        best = r;
      }
    }
  }
  // The enumeration's r_T = mu r_n d can exceed the cone by round-off: return an admissible reaction.
  best = project_on_coulomb_cone(best, mu);
  best_residual = natural_map_3d(best, W * best + q, mu).norm();
  s.r = best;
  s.residual = best_residual;
  s.state = classify(best, mu);
  s.failed = !done(best_residual, attainable(best));
  return s;
}

}  // namespace lmgc::solver
