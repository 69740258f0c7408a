#include "solver/nlgs/law_local_problem_3d.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "solver/nlgs/local_solver_3d.hpp"

namespace lmgc::solver {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// Cohesive zone (contact-laws.md §3.5): r = rr + shift + K uu with uu = q + W r gives
// uu = A (q + W shift) + A W rr, A = (I − W K)⁻¹.
struct CohesiveProblem {
  Matrix3d W;  // A W
  Vector3d q;  // A (q + W shift)
};
CohesiveProblem cohesive_problem(const Interaction3D& c, const LawState3D& s, const Vector3d& q) {
  const Matrix3d A = (Matrix3d::Identity() - c.W * s.cohesive_slope.asDiagonal()).inverse();
  return {A * c.W, A * (q + c.W * s.cohesive_shift)};
}

}  // namespace

Vector3d solve_law_form_3d(const Interaction3D& c, const LawState3D& law_state, const Vector3d& q,
                           const Vector3d& r_previous, double tolerance) {
  switch (c.form) {
    case LocalForm3D::rod:
      return Vector3d(0.0, -q(1) / (c.W(1, 1) + c.normal_compliance), 0.0);
    case LocalForm3D::wire:
      // Tension only: the link pulls when, free of it, it would stretch (uu_n > 0).
      return Vector3d(0.0, q(1) > 0.0 ? -q(1) / (c.W(1, 1) + c.normal_compliance) : 0.0, 0.0);
    case LocalForm3D::cohesive: {
      const CohesiveProblem p = cohesive_problem(c, law_state, q);
      const Vector3d rr_previous =
          r_previous - law_state.cohesive_shift - law_state.cohesive_slope.cwiseProduct(q + c.W * r_previous);
      const LocalSolution3D s = solve_signorini_coulomb_3d(swap_normal_first(p.W), swap_normal_first(p.q),
                                                           c.mu, swap_normal_first(rr_previous), tolerance);
      const Vector3d rr = swap_normal_first(s.r);
      const Vector3d uu = p.q + p.W * rr;
      return rr + law_state.cohesive_shift + law_state.cohesive_slope.cwiseProduct(uu);
    }
    case LocalForm3D::glued:
      return c.W.partialPivLu().solve(-q);
    case LocalForm3D::coulomb:
      break;
  }
  return r_previous;
}

ContactStatus law_form_status_3d(const Interaction3D& c, const LawState3D& law_state, const Vector3d& r,
                                 const Vector3d& uu) {
  switch (c.form) {
    case LocalForm3D::rod:
    case LocalForm3D::glued:
      return ContactStatus::stick;
    case LocalForm3D::wire:
      return r(1) < 0.0 ? ContactStatus::stick : ContactStatus::vnish;
    case LocalForm3D::cohesive: {
      // rr at round-off of r (the cohesion carries it all) counts as no contact force.
      const Vector3d rr = r - law_state.cohesive_shift - law_state.cohesive_slope.cwiseProduct(uu);
      if (rr(1) <= 1e-12 * r.norm()) return r(1) != 0.0 ? ContactStatus::stick : ContactStatus::noctc;
      return std::hypot(rr(0), rr(2)) < c.mu * rr(1) * (1.0 - 1e-10) ? ContactStatus::stick
                                                                     : ContactStatus::slide;
    }
    case LocalForm3D::coulomb:
      break;
  }
  return ContactStatus::noctc;
}

Vector3d law_form_residual_3d(const Interaction3D& c, const LawState3D& law_state, const Vector3d& r,
                              const Vector3d& uu) {
  switch (c.form) {
    case LocalForm3D::rod:
      return Vector3d(uu(1) + c.normal_compliance * r(1), r(0), r(2));
    case LocalForm3D::wire:
      return Vector3d(std::min(-r(1), -(uu(1) + c.normal_compliance * r(1))), r(0), r(2));
    case LocalForm3D::cohesive: {
      const Vector3d rr = r - law_state.cohesive_shift - law_state.cohesive_slope.cwiseProduct(uu);
      return natural_map_3d(swap_normal_first(rr), swap_normal_first(uu), c.mu);
    }
    case LocalForm3D::glued:
      return swap_normal_first(uu);
    case LocalForm3D::coulomb:
      break;
  }
  return Vector3d::Zero();
}

}  // namespace lmgc::solver
