#pragma once
// The 3D Signorini–Coulomb problem of one contact:
//   u = W r + q,  r in K_mu,  u + mu |u_T| e_n in K*_mu,  r . (u + mu |u_T| e_n) = 0
// (fc3d/FORMAT.md §1.1). Vectors here are ordered normal first, (n, t, s), as in FCLIB;
// LMGC90's (t, n, s) callers permute.
//
// Method: the two closed-form cases first (take-off: q_n >= 0; sticking: -W⁻¹q inside the cone),
// then a generalised Newton on the Alart–Curnier map with LMGC90's augmentation parameters
// (docs/lmgc90-facts/contact-laws.md §2.2, "mu_NG_solver") made globally convergent by a backtracking line
// search, then (when Newton stalls) a bisection over the sliding direction angle, and a projected
// fixed-point fallback. Every answer is checked with the natural map.
#include <Eigen/Core>

namespace lmgc::solver {

enum class LocalCase3D : unsigned char { take_off, stick, slide };

struct LocalSolution3D {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  LocalCase3D state = LocalCase3D::take_off;
  int newton_iterations = 0;
  // |F(r)| of the natural map of this contact alone (same units as u).
  double residual = 0.0;
  bool failed = false;  // NaN in the data or no iterate reached the tolerance: best iterate kept
};

// `r_start` is the Newton starting point for the sliding case (the previous reaction).
// `tolerance` is absolute, on |F(r)| of the natural map.
LocalSolution3D solve_signorini_coulomb_3d(const Eigen::Matrix3d& W, const Eigen::Vector3d& q, double mu,
                                           const Eigen::Vector3d& r_start, double tolerance);

// The same, with W⁻¹ computed by the caller (NaN entries when W is singular; nullptr: computed here
// when needed, as above): the scene NLGS
// inverts each block once per step instead of once per sweep. With `forcing` > 0 the iterative
// cases also stop once the residual is below `forcing` times the residual of their start (the
// previous reaction, or -q_n rho_n e_n when that is not in the cone's interior): an inexact solve,
// for sweeps far from convergence. With `keep_tolerance` > 0, when the problem sticks and `r_start`
// solves it within keep_tolerance, `r_start` itself is returned (as a sliding start already is within
// `tolerance`): sweeps that have converged then repeat their reactions bit for bit.
LocalSolution3D solve_signorini_coulomb_3d(const Eigen::Matrix3d& W, const Eigen::Matrix3d* W_inverse,
                                           const Eigen::Vector3d& q, double mu,
                                           const Eigen::Vector3d& r_start, double tolerance,
                                           double forcing = 0.0, double keep_tolerance = 0.0);

// LMGC90's (t, n, s) order <-> the solver's normal-first (n, t, s): swapping the first two entries
// (rows and columns of a block) is its own inverse.
inline Eigen::Vector3d swap_normal_first(const Eigen::Vector3d& v) {
  return Eigen::Vector3d(v(1), v(0), v(2));
}
inline Eigen::Matrix3d swap_normal_first(const Eigen::Matrix3d& W) {
  Eigen::Matrix3d S;
  S << W(1, 1), W(1, 0), W(1, 2), W(0, 1), W(0, 0), W(0, 2), W(2, 1), W(2, 0), W(2, 2);
  return S;
}

// Projection onto the Coulomb cone K_mu = { |x_T| <= mu x_n } (fc3d/FORMAT.md §3). Inline: the local
// solver evaluates it several times per contact and sweep.
inline Eigen::Vector3d project_on_coulomb_cone(const Eigen::Vector3d& x, double mu) {
  const double tangent_norm = x.tail<2>().norm();
  if (mu * tangent_norm <= -x(0)) return Eigen::Vector3d::Zero();
  if (tangent_norm <= mu * x(0)) return x;
  const double a = (mu * tangent_norm + x(0)) / (1.0 + mu * mu);
  Eigen::Vector3d p;
  p(0) = a;
  p.tail<2>() =
      tangent_norm > 0.0 ? Eigen::Vector2d(mu * a * x.tail<2>() / tangent_norm) : Eigen::Vector2d::Zero();
  return p;
}

// F(r) = r - P_K(r - u - mu |u_T| e_n) of one contact (fc3d/FORMAT.md §3).
inline Eigen::Vector3d natural_map_3d(const Eigen::Vector3d& r, const Eigen::Vector3d& u, double mu) {
  Eigen::Vector3d x = r - u;
  x(0) -= mu * u.tail<2>().norm();
  return r - project_on_coulomb_cone(x, mu);
}

}  // namespace lmgc::solver
