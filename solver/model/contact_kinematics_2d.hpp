#pragma once
// How a contact point moves with the rigid 2D bodies it joins, and how its reaction moves them
// (RBDY2): the operations the contact stages ask of a body, on the interaction record. The 2D
// NLGS sweeps carry the same quantities in compact records of their own (nlgs_2d.cpp).
// docs/lmgc90-facts/numerics.md §2-§3.
#include <Eigen/Core>
#include <vector>

#include "solver/model/interaction_2d.hpp"

namespace lmgc::solver {

// The rows of H for one side of a contact: (t, lever_t) and (n, lever_n) against (vx, vy, ω).
inline Eigen::Vector3d h_row(const Interaction2D& c, int side, int component) {
  const Eigen::Vector2d direction = component == 0 ? c.tangent() : c.normal;
  const Eigen::Vector2d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
  return Eigen::Vector3d(direction.x(), direction.y(), lever(component));
}

// Relative local velocity (t, n) of the contact for body velocities V (vx, vy, ω).
inline Eigen::Vector2d local_velocity(const Interaction2D& c, const std::vector<Eigen::Vector3d>& V) {
  const Eigen::Vector3d& vc = V[static_cast<std::size_t>(c.candidate_body)];
  const Eigen::Vector3d& va = V[static_cast<std::size_t>(c.antagonist_body)];
  return Eigen::Vector2d(h_row(c, 0, 0).dot(vc) - h_row(c, 1, 0).dot(va),
                         h_row(c, 0, 1).dot(vc) - h_row(c, 1, 1).dot(va));
}

// V += M⁻¹ H r for an impulse r (t, n) of one contact.
inline void inject(const Interaction2D& c, const Eigen::Vector2d& r,
                   const std::vector<Eigen::Vector3d>& inverse_mass, std::vector<Eigen::Vector3d>& V) {
  for (int side = 0; side < 2; ++side) {
    const auto body = static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body);
    const Eigen::Vector3d impulse = h_row(c, side, 0) * r(0) + h_row(c, side, 1) * r(1);
    V[body] += (side == 0 ? 1.0 : -1.0) * inverse_mass[body].cwiseProduct(impulse);
  }
}

// The block of W = Hᵀ M⁻¹ H that couples contact `c`'s local velocity to contact `d`'s reaction:
// the sum over the bodies they share, signed by the side each contact sees the body from (0 when
// they share none). coupling_block(c, c) is c's Delassus block.
inline Eigen::Matrix2d coupling_block(const Interaction2D& c, const Interaction2D& d,
                                      const std::vector<Eigen::Vector3d>& inverse_mass) {
  Eigen::Matrix2d W = Eigen::Matrix2d::Zero();
  for (int side_c = 0; side_c < 2; ++side_c)
    for (int side_d = 0; side_d < 2; ++side_d) {
      const std::int32_t body = side_c == 0 ? c.candidate_body : c.antagonist_body;
      if (body != (side_d == 0 ? d.candidate_body : d.antagonist_body)) continue;
      const double sign = (side_c == side_d) ? 1.0 : -1.0;
      const Eigen::Vector3d& m = inverse_mass[static_cast<std::size_t>(body)];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          W(i, j) += sign * h_row(c, side_c, i).cwiseProduct(m).dot(h_row(d, side_d, j));
    }
  return W;
}

}  // namespace lmgc::solver
