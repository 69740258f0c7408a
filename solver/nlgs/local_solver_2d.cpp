#include "solver/nlgs/local_solver_2d.hpp"

#include <cmath>

namespace lmgc::solver {

LocalSolution2D solve_signorini_coulomb_2d(const Eigen::Matrix2d& W, const Eigen::Vector2d& q, double mu) {
  LocalSolution2D s;
  const double qt = q(0), qn = q(1);
  // Take-off: the free velocity already separates.
  if (qn >= 0.0) {
    s.status = ContactStatus::noctc;
    return s;
  }
  const double wtt = W(0, 0), wtn = W(0, 1), wnt = W(1, 0), wnn = W(1, 1);
  const double det = wtt * wnn - wtn * wnt;
  // det × the sticking solution r = -W⁻¹ q.
  const double dft = -(wnn * qt - wtn * qn);
  const double dfn = -(-wnt * qt + wtt * qn);
  const double forward = wnn - mu * wnt;   // slide with u_t > 0: r_t = -mu r_n
  const double backward = wnn + mu * wnt;  // slide with u_t < 0: r_t = +mu r_n
  const double cf = dft + mu * dfn;
  const double cb = dft - mu * dfn;
  if (cf < 0.0) {
    if (forward <= 1e-18) {
      s.failed = !solve_signorini_coulomb_2d_any_case(wtt, 0.5 * (wtn + wnt), wnn, qt, qn, mu, s.r(0), s.r(1),
                                                      s.status);
      return s;
    }
    s.r(1) = -qn / forward;
    s.r(0) = -mu * s.r(1);
    s.status = ContactStatus::slifw;
  } else if (cb > 0.0) {
    if (backward <= 1e-18) {
      s.failed = !solve_signorini_coulomb_2d_any_case(wtt, 0.5 * (wtn + wnt), wnn, qt, qn, mu, s.r(0), s.r(1),
                                                      s.status);
      return s;
    }
    s.r(1) = -qn / backward;
    s.r(0) = mu * s.r(1);
    s.status = ContactStatus::slibw;
  } else if (cf >= 0.0 && cb <= 0.0 && det != 0.0) {
    s.r(1) = dfn / det;
    s.r(0) = dft / det;
    s.status = ContactStatus::stick;
  } else {
    s.failed = true;  // NaN in the data, or a singular block
  }
  return s;
}

bool solve_signorini_coulomb_2d_any_case(double wtt, double wtn, double wnn, double qt, double qn, double mu,
                                         double& rt, double& rn, ContactStatus& status) {
  rt = rn = 0.0;
  if (qn >= 0.0) {
    status = ContactStatus::noctc;
    return true;
  }
  const double slack = 1e-12 * (std::fabs(qt) + std::fabs(qn));
  // Forward slide (u_t >= 0, r_t = -μ r_n), then backward (u_t <= 0, r_t = +μ r_n).
  for (const double sign : {-1.0, 1.0}) {
    const double denominator = wnn + sign * mu * wtn;
    if (!(denominator > 1e-18)) continue;
    const double n = -qn / denominator, t = sign * mu * n;
    const double ut = wtt * t + wtn * n + qt;
    if (n >= 0.0 && -sign * ut >= -slack) {
      rt = t;
      rn = n;
      status = sign < 0.0 ? ContactStatus::slifw : ContactStatus::slibw;
      return true;
    }
  }
  const double det = wtt * wnn - wtn * wtn;
  if (det != 0.0 && std::isfinite(det)) {
    const double n = -(-wtn * qt + wtt * qn) / det, t = -(wnn * qt - wtn * qn) / det;
    if (n >= 0.0 && std::fabs(t) <= mu * n * (1.0 + 1e-12)) {
      rt = t;
      rn = n;
      status = ContactStatus::stick;
      return true;
    }
  }
  return false;
}

Eigen::Vector2d natural_map_2d(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu) {
  // x = r - (u + mu |u_t| e_n), components (t, n).
  const double xt = r(0) - u(0);
  const double xn = r(1) - (u(1) + mu * std::fabs(u(0)));
  double pt, pn;
  const double at = std::fabs(xt);
  if (mu * at <= -xn) {
    pt = pn = 0.0;
  } else if (at <= mu * xn) {
    pt = xt;
    pn = xn;
  } else {
    const double a = (mu * at + xn) / (1.0 + mu * mu);
    pn = a;
    pt = at > 0.0 ? mu * a * xt / at : 0.0;
  }
  return Eigen::Vector2d(r(0) - pt, r(1) - pn);
}

double natural_map_residual_squared_2d(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu) {
  return natural_map_2d(r, u, mu).squaredNorm();
}

}  // namespace lmgc::solver
