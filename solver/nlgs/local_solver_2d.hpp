#pragma once
// The 2D Signorini–Coulomb problem of one contact, solved exactly by enumerating the cases of
// the friction cone. spec: contact-laws.md §2.1 ("mu_SC_std_solver").
//   u = W r + q,  u_n >= 0, r_n >= 0, u_n r_n = 0,  |r_t| <= mu r_n, Coulomb on (u_t, r_t)
// Vectors are ordered (t, n) as in LMGC90.
#include <Eigen/Core>

#include "solver/model/contact_status.hpp"

namespace lmgc::solver {

struct LocalSolution2D {
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  ContactStatus status = ContactStatus::noctc;
  bool failed = false;  // NaN or a degenerate block: the caller keeps what was computed
};

LocalSolution2D solve_signorini_coulomb_2d(const Eigen::Matrix2d& W, const Eigen::Vector2d& q, double mu);

// Natural-map residual of one contact (fc3d/FORMAT.md §3, scalar tangent), for u = W r + q:
// F = r - P_K(r - u - (mu |u_t|) e_n), returned as |F|^2.
double natural_map_residual_squared_2d(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu);

}  // namespace lmgc::solver
