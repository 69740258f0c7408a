#include "solver/bodies/rigid_bodies_3d.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace lmgc::solver {

// Keeps the first bodies; new ones start at rest, unit frame, visible.
void RigidBodies3D::resize(std::size_t n) {
  const Vector6d zero6 = Vector6d::Zero();
  reference.resize(n, Eigen::Vector3d::Zero());
  for (auto* v : {&displacement_begin, &displacement, &velocity_begin, &velocity, &velocity_free,
                  &inverse_mass, &external_force, &impulse})
    v->resize(n, zero6);
  for (auto* f : {&frame_initial, &frame_detection, &frame}) f->resize(n, Eigen::Matrix3d::Identity());
  mass.resize(n, 0.0);
  inertia.resize(n, Eigen::Vector3d::Zero());
  bulk_behav.resize(n, 0);
  driven_mask.resize(n, 0);
  visible.resize(n, 1);
}

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d s;
  s << 0.0, -w.z(), w.y(),  //
      w.z(), 0.0, -w.x(),   //
      -w.y(), w.x(), 0.0;
  return s;
}

// Classical Gram–Schmidt on the columns, in LMGC90's order (`GRAMM_SCHMIDT`, mod_algebra.f90):
// u1 = v1/|v1|; u2 = normalised(v2 − (v2·u1)u1); u3 = normalised(v3 − (v3·u1)u1 − (v3·u2)u2).
// LMGC90 obtains e3 by projection, not as e1 × e2; both agree to rounding whenever the input is
// right-handed, which the linearised update guarantees (det(I + h[w]×) = 1 + h²|w|² > 0).
Eigen::Matrix3d gram_schmidt(const Eigen::Matrix3d& v) {
  Eigen::Matrix3d u;
  u.col(0) = v.col(0) / v.col(0).norm();
  const Eigen::Vector3d w2 = v.col(1) - v.col(1).dot(u.col(0)) * u.col(0);
  u.col(1) = w2 / w2.norm();
  const Eigen::Vector3d w3 = v.col(2) - v.col(2).dot(u.col(0)) * u.col(0) - v.col(2).dot(u.col(1)) * u.col(1);
  u.col(2) = w3 / w3.norm();
  return u;
}

}  // namespace

Eigen::Matrix3d update_frame(const Eigen::Matrix3d& frame, const Eigen::Vector3d& spin_body_axes, double h,
                             FrameUpdate method) {
  // Spin in body axes → global rotation vector w = Σ spin_i e_i.
  const Eigen::Vector3d w = frame * spin_body_axes;
  switch (method) {
    case FrameUpdate::linearised: {
      const Eigen::Vector3d hw = h * w;
      Eigen::Matrix3d moved;
      for (int i = 0; i < 3; ++i) moved.col(i) = frame.col(i) + hw.cross(frame.col(i));
      return gram_schmidt(moved);
    }
    case FrameUpdate::cayley: {
      // Q = (I − h/2 Ω)⁻¹ (I + h/2 Ω); I − h/2 Ω is never singular (det = 1 + h²|w|²/4).
      const Eigen::Matrix3d half = (0.5 * h) * skew(w);
      const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
      const Eigen::Matrix3d q = (identity - half).inverse() * (identity + half);
      return q * frame;
    }
  }
  return frame;
}

Eigen::Vector3d gyroscopic_torque(const Eigen::Vector3d& inertia, const Eigen::Vector3d& omega) {
  return {-(inertia.z() - inertia.y()) * omega.y() * omega.z(),  //
          -(inertia.x() - inertia.z()) * omega.x() * omega.z(),  //
          -(inertia.y() - inertia.x()) * omega.x() * omega.y()};
}

double kinetic_energy(const RigidBodies3D& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vector6d& v = b.velocity[i];
    const Eigen::Vector3d& in = b.inertia[i];
    e += 0.5 * b.mass[i] * v.head<3>().squaredNorm() +
         0.5 * (in.x() * v(3) * v(3) + in.y() * v(4) * v(4) + in.z() * v(5) * v(5));
  }
  return e;
}

}  // namespace lmgc::solver
