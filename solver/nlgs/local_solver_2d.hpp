#pragma once
// The 2D Signorini–Coulomb problem of one contact, solved exactly by enumerating the cases of
// the friction cone. docs/lmgc90-facts/contact-laws.md §2.1 ("mu_SC_std_solver").
//   u = W r + q,  u_n >= 0, r_n >= 0, u_n r_n = 0,  |r_t| <= mu r_n, Coulomb on (u_t, r_t)
// Vectors are ordered (t, n) as in LMGC90.
#include <Eigen/Core>
#include <cmath>

#include "solver/model/contact_status.hpp"

namespace lmgc::solver {

struct LocalSolution2D {
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  ContactStatus status = ContactStatus::noctc;
  bool failed = false;  // NaN or a degenerate block: the caller keeps what was computed
};

LocalSolution2D solve_signorini_coulomb_2d(const Eigen::Matrix2d& W, const Eigen::Vector2d& q, double mu);

// When the sign test picks a sliding branch whose denominator is not positive (W strongly
// coupled and μ large), LMGC90 stops with an error although another case solves the problem:
// this tries forward slide, backward slide and stick, each checked for consistency (r_n >= 0,
// the sliding direction matching the sign of u_t, |r_t| <= μ r_n), and returns the first that
// holds. False when none does (NaN data). W symmetric: wtn = wnt.
bool solve_signorini_coulomb_2d_any_case(double wtt, double wtn, double wnn, double qt, double qn, double mu,
                                         double& rt, double& rn, ContactStatus& status);

// The same enumeration on scalars, inlined in the NLGS sweep (W symmetric: wtn = wnt).
// Returns false on a degenerate block or NaN (r left at 0).
inline bool solve_signorini_coulomb_2d(double wtt, double wtn, double wnn, double qt, double qn, double mu,
                                       double& rt, double& rn, ContactStatus& status) {
  rt = rn = 0.0;
  if (qn >= 0.0) {
    status = ContactStatus::noctc;
    return true;
  }
  const double det = wtt * wnn - wtn * wtn;
  const double dft = -(wnn * qt - wtn * qn);
  const double dfn = -(-wtn * qt + wtt * qn);
  const double cf = dft + mu * dfn;
  const double cb = dft - mu * dfn;
  if (cf < 0.0) {
    const double forward = wnn - mu * wtn;
    if (forward <= 1e-18)
      return solve_signorini_coulomb_2d_any_case(wtt, wtn, wnn, qt, qn, mu, rt, rn, status);
    rn = -qn / forward;
    rt = -mu * rn;
    status = ContactStatus::slifw;
  } else if (cb > 0.0) {
    const double backward = wnn + mu * wtn;
    if (backward <= 1e-18)
      return solve_signorini_coulomb_2d_any_case(wtt, wtn, wnn, qt, qn, mu, rt, rn, status);
    rn = -qn / backward;
    rt = mu * rn;
    status = ContactStatus::slibw;
  } else if (cf >= 0.0 && cb <= 0.0 && det != 0.0) {
    rn = dfn / det;
    rt = dft / det;
    status = ContactStatus::stick;
  } else {
    return false;
  }
  return true;
}

// The reciprocals of the block that the enumeration divides by: the NLGS sweeps compute them once
// per contact and step and multiply at every visit, instead of dividing.
// 0 where the division is not taken (a singular block, a slide denominator <= 1e-18).
struct SignoriniCoulombReciprocals2D {
  double det = 0.0, forward = 0.0, backward = 0.0;
};

inline SignoriniCoulombReciprocals2D signorini_coulomb_reciprocals_2d(double wtt, double wtn, double wnn,
                                                                      double mu) {
  const double det = wtt * wnn - wtn * wtn, forward = wnn - mu * wtn, backward = wnn + mu * wtn;
  // A reciprocal that overflows (a subnormal determinant) is not taken either.
  const auto reciprocal = [](double x, bool taken) {
    const double inverse = taken ? 1.0 / x : 0.0;
    return std::isfinite(inverse) ? inverse : 0.0;
  };
  return {reciprocal(det, det != 0.0), reciprocal(forward, forward > 1e-18),
          reciprocal(backward, backward > 1e-18)};
}

// The enumeration above with the reciprocals `inverse` of (wtt, wtn, wnn, mu): the same case, and
// the same reaction up to round-off. A case whose reciprocal is 0, or NaN data, takes the dividing
// version (its fallbacks and its r = 0 on NaN).
inline bool solve_signorini_coulomb_2d(double wtt, double wtn, double wnn,
                                       const SignoriniCoulombReciprocals2D& inverse, double qt, double qn,
                                       double mu, double& rt, double& rn, ContactStatus& status) {
  rt = rn = 0.0;
  status = ContactStatus::noctc;
  if (qn >= 0.0) return true;
  const double dft = -(wnn * qt - wtn * qn);
  const double dfn = -(-wtn * qt + wtt * qn);
  const double cf = dft + mu * dfn;
  const double cb = dft - mu * dfn;
  if (cf < 0.0 && inverse.forward != 0.0) {
    rn = -qn * inverse.forward;
    rt = -mu * rn;
    status = ContactStatus::slifw;
  } else if (cf >= 0.0 && cb > 0.0 && inverse.backward != 0.0) {
    rn = -qn * inverse.backward;
    rt = mu * rn;
    status = ContactStatus::slibw;
  } else if (cf >= 0.0 && cb <= 0.0 && inverse.det != 0.0) {
    rn = dfn * inverse.det;
    rt = dft * inverse.det;
    status = ContactStatus::stick;
  } else {
    // Through locals of its own: rt, rn and status, never address-taken, stay in registers in a sweep.
    double fallback_rt = 0.0, fallback_rn = 0.0;
    ContactStatus fallback_status = ContactStatus::noctc;
    const bool solved =
        solve_signorini_coulomb_2d(wtt, wtn, wnn, qt, qn, mu, fallback_rt, fallback_rn, fallback_status);
    rt = fallback_rt;
    rn = fallback_rn;
    status = fallback_status;
    return solved;
  }
  return true;
}

// The natural map of one contact (fc3d/FORMAT.md §3, scalar tangent), for u = W r + q:
// F = r - P_K(r - u - (mu |u_t|) e_n), components (t, n); zero exactly at a solution of
// Signorini–Coulomb. The 2D NLGS and the FCLIB solvers measure their error with it; the second
// returns |F|^2.
Eigen::Vector2d natural_map_2d(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu);
double natural_map_residual_squared_2d(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu);

}  // namespace lmgc::solver
