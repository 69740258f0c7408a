#pragma once
// How a contact point moves with the rigid bodies it joins, and how its reaction moves them (RBDY3):
// the operations the 3D detection and NLGS ask of a body. docs/lmgc90-facts/numerics.md §2-§3.
#include <Eigen/Core>
#include <vector>

#include "solver/bodies/rigid_bodies_3d.hpp"
#include "solver/model/interaction_3d.hpp"

namespace lmgc::solver {

// Relative local velocity (t, n, s) of the contact for body velocities V (numerics.md §2, 3D).
inline Eigen::Vector3d local_velocity(const Interaction3D& c, const std::vector<Vector6d>& V) {
  const Vector6d& vc = V[static_cast<std::size_t>(c.candidate_body)];
  const Vector6d& va = V[static_cast<std::size_t>(c.antagonist_body)];
  return c.frame * (vc.head<3>() - va.head<3>()) + c.lever_candidate * vc.tail<3>() -
         c.lever_antagonist * va.tail<3>();
}

// H r of one contact's impulse r (t, n, s): the force and each body's moment in its own axes.
struct ContactImpulse {
  Eigen::Vector3d force, torque_candidate, torque_antagonist;
};
inline ContactImpulse impulse_of(const Interaction3D& c, const Eigen::Vector3d& r) {
  return {c.frame.transpose() * r, c.lever_candidate.transpose() * r, c.lever_antagonist.transpose() * r};
}

// V += M⁻¹ H r for an impulse r (t, n, s) of one contact.
inline void inject(const Interaction3D& c, const Eigen::Vector3d& r, const RigidBodies3D& b,
                   std::vector<Vector6d>& V) {
  // Fixed-size halves throughout: this runs once per contact and sweep.
  const ContactImpulse f = impulse_of(c, r);
  const auto cd = static_cast<std::size_t>(c.candidate_body),
             an = static_cast<std::size_t>(c.antagonist_body);
  const Vector6d& m_cd = b.inverse_mass[cd];
  const Vector6d& m_an = b.inverse_mass[an];
  V[cd].head<3>() += m_cd.head<3>().cwiseProduct(f.force);
  V[cd].tail<3>() += m_cd.tail<3>().cwiseProduct(f.torque_candidate);
  V[an].head<3>() -= m_an.head<3>().cwiseProduct(f.force);
  V[an].tail<3>() -= m_an.tail<3>().cwiseProduct(f.torque_antagonist);
}

// Ireac += H r of one contact (the end of the solve sums it from the final reactions).
inline void add_impulse(const Interaction3D& c, const Eigen::Vector3d& r, std::vector<Vector6d>& impulse) {
  const ContactImpulse f = impulse_of(c, r);
  const auto cd = static_cast<std::size_t>(c.candidate_body),
             an = static_cast<std::size_t>(c.antagonist_body);
  impulse[cd].head<3>() += f.force;
  impulse[cd].tail<3>() += f.torque_candidate;
  impulse[an].head<3>() -= f.force;
  impulse[an].tail<3>() -= f.torque_antagonist;
}

// Delassus block Hᵀ M⁻¹ H of one contact (rigid bodies: exact, numerics.md §3).
inline Eigen::Matrix3d delassus_block(const Interaction3D& c, const RigidBodies3D& b) {
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (int side = 0; side < 2; ++side) {
    const auto body = static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body);
    const Eigen::Matrix3d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
    const Vector6d& inverse = b.inverse_mass[body];
    W += c.frame * inverse.head<3>().asDiagonal() * c.frame.transpose() +
         lever * inverse.tail<3>().asDiagonal() * lever.transpose();
  }
  return W;
}

// The block of W = Hᵀ M⁻¹ H that couples contact `c`'s local velocity to contact `d`'s reaction:
// the sum over the bodies they share, signed by the side each contact sees the body from (0 when
// they share none). coupling_block(c, c) is c's Delassus block (delassus_block, summed in another
// order).
inline Eigen::Matrix3d coupling_block(const Interaction3D& c, const Interaction3D& d,
                                      const RigidBodies3D& b) {
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (int side_c = 0; side_c < 2; ++side_c)
    for (int side_d = 0; side_d < 2; ++side_d) {
      const std::int32_t body = side_c == 0 ? c.candidate_body : c.antagonist_body;
      if (body != (side_d == 0 ? d.candidate_body : d.antagonist_body)) continue;
      const double sign = side_c == side_d ? 1.0 : -1.0;
      const Vector6d& m = b.inverse_mass[static_cast<std::size_t>(body)];
      const Eigen::Matrix3d& lever_c = side_c == 0 ? c.lever_candidate : c.lever_antagonist;
      const Eigen::Matrix3d& lever_d = side_d == 0 ? d.lever_candidate : d.lever_antagonist;
      W += sign * (c.frame * m.head<3>().asDiagonal() * d.frame.transpose() +
                   lever_c * m.tail<3>().asDiagonal() * lever_d.transpose());
    }
  return W;
}

}  // namespace lmgc::solver
