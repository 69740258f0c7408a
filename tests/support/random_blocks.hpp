#pragma once
// Random 3D contact data for the RapidCheck properties of the local solvers: rotations, Delassus
// blocks, free velocities (drawn with test::in_range, so that they shrink).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "tests/support/generators.hpp"

namespace lmgc::test {

// A random rotation of R^3 (normalised quaternion).
inline Eigen::Matrix3d random_rotation() {
  Eigen::Quaterniond rotation(in_range(-1.0, 1.0), in_range(-1.0, 1.0), in_range(-1.0, 1.0),
                              in_range(-1.0, 1.0));
  if (rotation.norm() < 1e-3) return Eigen::Matrix3d::Identity();
  rotation.normalize();
  return rotation.toRotationMatrix();
}

// A random symmetric positive definite block Q diag(lambda) Qᵀ: largest eigenvalue in [0.1, 10],
// the others down to 1e-4 of it (condition number up to 1e4).
inline Eigen::Matrix3d random_spd() {
  const double scale = in_range(0.1, 10.0);
  const Eigen::Vector3d lambda(scale, scale * std::pow(10.0, -in_range(0.0, 4.0)),
                               scale * std::pow(10.0, -in_range(0.0, 4.0)));
  const Eigen::Matrix3d Q = random_rotation();
  const Eigen::Matrix3d W = Q * lambda.asDiagonal() * Q.transpose();
  return 0.5 * (W + W.transpose());
}

// A free velocity with components in [-5, 5].
inline Eigen::Vector3d random_q() {
  return Eigen::Vector3d(in_range(-5.0, 5.0), in_range(-5.0, 5.0), in_range(-5.0, 5.0));
}

}  // namespace lmgc::test
