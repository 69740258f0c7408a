// RBDY3 kinematics: principal-frame update (linearised + Gram–Schmidt, Cayley), explicit
// gyroscopic torque, kinetic energy. docs/lmgc90-facts/numerics.md §1.2.
#include "solver/bodies/rigid_bodies_3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

double orthonormality_error(const Matrix3d& f) {
  return (f.transpose() * f - Matrix3d::Identity()).norm();
}

double angle_between(const Vector3d& a, const Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

class FrameUpdateMethods : public ::testing::TestWithParam<FrameUpdate> {};

TEST_P(FrameUpdateMethods, KeepsTheFrameOrthonormalAndRightHandedForRandomSpins) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Matrix3d f = random_rotation(rng);
    const Vector3d spin(u(rng), u(rng), u(rng));
    const Matrix3d g = update_frame(f, spin, 1e-2, GetParam());
    EXPECT_LT(orthonormality_error(g), 1e-12);
    EXPECT_GT(g.determinant(), 0.0);
  }
  // Repeated updates do not accumulate a loss of orthonormality.
  Matrix3d g = random_rotation(rng);
  for (int step = 0; step < 10000; ++step)
    g = update_frame(g, Vector3d(u(rng), u(rng), u(rng)), 1e-3, GetParam());
  EXPECT_LT(orthonormality_error(g), 1e-12);
  EXPECT_NEAR(g.determinant(), 1.0, 1e-12);
}

TEST_P(FrameUpdateMethods, ZeroSpinLeavesTheFrameUnchanged) {
  std::mt19937 rng(7);
  const Matrix3d f = random_rotation(rng);
  const Matrix3d g = update_frame(f, Vector3d::Zero(), 1e-2, GetParam());
  if (GetParam() == FrameUpdate::cayley)
    EXPECT_EQ(g, f);  // the Cayley factor is exactly the identity
  else
    EXPECT_LT((g - f).cwiseAbs().maxCoeff(), 4e-16);  // Gram–Schmidt renormalises to rounding
}

TEST_P(FrameUpdateMethods, SpinIsExpressedInBodyAxes) {
  // A spin about body axis 3 rotates e1 and e2 about e3 and leaves e3 fixed, whatever the frame.
  std::mt19937 rng(3);
  const Matrix3d f = random_rotation(rng);
  const Matrix3d g = update_frame(f, Vector3d(0.0, 0.0, 2.0), 1e-2, GetParam());
  EXPECT_LT((g.col(2) - f.col(2)).norm(), 1e-15);
  EXPECT_NEAR(g.col(0).dot(f.col(2)), 0.0, 1e-15);
  EXPECT_GT(g.col(0).dot(f.col(1)), 0.0);  // positive sense: e1 turns towards e2
}

INSTANTIATE_TEST_SUITE_P(RigidBodies3D, FrameUpdateMethods,
                         ::testing::Values(FrameUpdate::linearised, FrameUpdate::cayley),
                         [](const ::testing::TestParamInfo<FrameUpdate>& info) {
                           return info.param == FrameUpdate::linearised ? std::string("Linearised")
                                                                        : std::string("Cayley");
                         });

TEST(RigidBodies3D, CayleySpinAboutE3RotatesE1ByTwiceAtanOfHalfAngle) {
  std::mt19937 rng(11);
  const Matrix3d f = random_rotation(rng);
  for (const double hw : {1e-4, 1e-2, 0.3, 1.0, 3.0}) {
    const double h = 1e-2;
    const Matrix3d g = update_frame(f, Vector3d(0.0, 0.0, hw / h), h, FrameUpdate::cayley);
    EXPECT_NEAR(angle_between(f.col(0), g.col(0)), 2.0 * std::atan(hw / 2.0), 1e-14) << "h|w| = " << hw;
  }
}

TEST(RigidBodies3D, LinearisedSpinAboutE3RotatesE1ByAtanOfHW) {
  // e1' = e1 + h|w| e2 before normalisation: its direction makes atan(h|w|) with e1.
  std::mt19937 rng(13);
  const Matrix3d f = random_rotation(rng);
  for (const double hw : {1e-4, 1e-2, 0.3, 1.0, 3.0}) {
    const double h = 1e-2;
    const Matrix3d g = update_frame(f, Vector3d(0.0, 0.0, hw / h), h, FrameUpdate::linearised);
    EXPECT_NEAR(angle_between(f.col(0), g.col(0)), std::atan(hw), 1e-14) << "h|w| = " << hw;
  }
}

TEST(RigidBodies3D, GyroscopicTorqueVanishesForASphere) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int k = 0; k < 20; ++k)
    EXPECT_EQ(gyroscopic_torque(Vector3d(0.4, 0.4, 0.4), Vector3d(u(rng), u(rng), u(rng))), Vector3d::Zero());
}

TEST(RigidBodies3D, GyroscopicTorqueMatchesEulerEquationsOnAHandExample) {
  // I = (1, 2, 3), ω = (1, 2, 3): −(I3−I2)ω2ω3 = −6, −(I1−I3)ω1ω3 = 6, −(I2−I1)ω1ω2 = −2,
  // i.e. (Iω) × ω = (1, 4, 9) × (1, 2, 3).
  const Vector3d inertia(1.0, 2.0, 3.0), omega(1.0, 2.0, 3.0);
  const Vector3d t = gyroscopic_torque(inertia, omega);
  EXPECT_EQ(t, Vector3d(-6.0, 6.0, -2.0));
  EXPECT_EQ(t, inertia.cwiseProduct(omega).cross(omega));
  EXPECT_EQ(t.dot(omega), 0.0);  // it does no work
}

TEST(RigidBodies3D, KineticEnergySumsTranslationAndRotationAtTheEndOfTheStep) {
  RigidBodies3D b;
  b.resize(2);
  b.mass = {2.0, 0.5};
  b.inertia = {Vector3d(1.0, 2.0, 3.0), Vector3d(0.1, 0.1, 0.1)};
  b.velocity[0] << 1.0, 2.0, 3.0, 1.0, 1.0, 2.0;          // ½·2·14 + ½(1 + 2 + 12) = 14 + 7.5
  b.velocity[1] << 0.0, 0.0, -2.0, 10.0, 0.0, 0.0;        // ½·0.5·4 + ½·0.1·100 = 1 + 5
  b.velocity_begin[0] << 100.0, 0.0, 0.0, 0.0, 0.0, 0.0;  // not used
  EXPECT_DOUBLE_EQ(kinetic_energy(b), 27.5);
}

TEST(RigidBodies3D, ResizeGivesIdentityFramesAndVisibleBodiesAtRest) {
  RigidBodies3D b;
  b.resize(3);
  EXPECT_EQ(b.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(b.frame[i], Matrix3d::Identity());
    EXPECT_EQ(b.frame_initial[i], Matrix3d::Identity());
    EXPECT_EQ(b.frame_detection[i], Matrix3d::Identity());
    EXPECT_EQ(b.velocity[i], Vector6d::Zero());
    EXPECT_EQ(b.visible[i], 1);
  }
}

}  // namespace
}  // namespace lmgc::solver
