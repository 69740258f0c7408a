#pragma once
// The operations the contact stages ask of a kind of body, so that detection and the NLGS do not
// know whether a contactor belongs to a rigid body or to a finite-element mesh: a contact's
// relative local velocity from the bodies' velocities, the injection of a local reaction into them
// (V += M⁻¹ H r), and the block of W = Hᵀ M⁻¹ H that couples two contacts through the bodies they
// share (a contact's own Delassus block when both are the same). A deformable body (MAILx) couples
// every pair of contacts on it, a reaction on one node moving the others: hence the coupling of two
// contacts, not only the diagonal block of one. The free velocity and the end of the step are
// stages of the step over the whole body set (solver/integrator/step_2d.hpp, step_3d.hpp).
// RBDY2 and RBDY3 implement them (contact_kinematics_2d.hpp, contact_kinematics_3d.hpp); the
// property test tests/property/solver/body_kind_property_test.cpp holds every kind to them.
#include <Eigen/Core>
#include <concepts>
#include <vector>

#include "solver/bodies/rigid_bodies_2d.hpp"
#include "solver/bodies/rigid_bodies_3d.hpp"
#include "solver/model/contact_kinematics_2d.hpp"
#include "solver/model/contact_kinematics_3d.hpp"

namespace lmgc::solver {

template <class Kind>
concept ContactBodyKind = requires(const typename Kind::Contact& c, const typename Kind::Bodies& bodies,
                                   const typename Kind::Velocities& v, typename Kind::Velocities& w,
                                   const typename Kind::Local& r) {
  { Kind::local_velocity(c, v) } -> std::convertible_to<typename Kind::Local>;
  Kind::inject(c, r, bodies, w);
  { Kind::coupling_block(c, c, bodies) } -> std::convertible_to<typename Kind::Block>;
};

// RBDY2: velocities (vx, vy, ω) per body, local (t, n).
struct RigidBodyKind2D {
  using Contact = Interaction2D;
  using Bodies = RigidBodies2D;
  using Velocities = std::vector<Eigen::Vector3d>;
  using Local = Eigen::Vector2d;
  using Block = Eigen::Matrix2d;
  static Local local_velocity(const Contact& c, const Velocities& v) { return solver::local_velocity(c, v); }
  static void inject(const Contact& c, const Local& r, const Bodies& b, Velocities& v) {
    solver::inject(c, r, b.inverse_mass, v);
  }
  static Block coupling_block(const Contact& c, const Contact& d, const Bodies& b) {
    return solver::coupling_block(c, d, b.inverse_mass);
  }
};

// RBDY3: velocities (v, ω in the body's principal axes) per body, local (t, n, s).
struct RigidBodyKind3D {
  using Contact = Interaction3D;
  using Bodies = RigidBodies3D;
  using Velocities = std::vector<Vector6d>;
  using Local = Eigen::Vector3d;
  using Block = Eigen::Matrix3d;
  static Local local_velocity(const Contact& c, const Velocities& v) { return solver::local_velocity(c, v); }
  static void inject(const Contact& c, const Local& r, const Bodies& b, Velocities& v) {
    solver::inject(c, r, b, v);
  }
  static Block coupling_block(const Contact& c, const Contact& d, const Bodies& b) {
    return solver::coupling_block(c, d, b);
  }
};

static_assert(ContactBodyKind<RigidBodyKind2D>);
static_assert(ContactBodyKind<RigidBodyKind3D>);

}  // namespace lmgc::solver
