// Local frames and fine geometry of the 3D sphere pairs (SPSPx, SPPLx), as LMGC90 computes them.
#include "solver/detection/pair_geometry_3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kTol = 1e-14;

void expect_near(const Vector3d& a, const Vector3d& b, double tol = kTol) {
  EXPECT_NEAR((a - b).norm(), 0.0, tol)
      << "got (" << a.transpose() << "), expected (" << b.transpose() << ")";
}

// (t, n, s) orthonormal with s = t × n (right-handed in LMGC90's order).
void expect_right_handed(const Vector3d& t, const Vector3d& n, const Vector3d& s) {
  EXPECT_NEAR(t.norm(), 1.0, kTol);
  EXPECT_NEAR(s.norm(), 1.0, kTol);
  EXPECT_NEAR(t.dot(n), 0.0, kTol);
  EXPECT_NEAR(s.dot(n), 0.0, kTol);
  EXPECT_NEAR(t.dot(s), 0.0, kTol);
  expect_near(s, t.cross(n));
}

std::vector<Vector3d> random_unit_normals(std::size_t count) {
  std::mt19937 generator(12345);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vector3d> normals;
  while (normals.size() < count) {
    const Vector3d v(gauss(generator), gauss(generator), gauss(generator));
    if (v.norm() > 1e-3) normals.push_back(v.normalized());
  }
  return normals;
}

const std::array<Vector3d, 6> kAxisNormals = {Vector3d::UnitX(),  -Vector3d::UnitX(), Vector3d::UnitY(),
                                              -Vector3d::UnitY(), Vector3d::UnitZ(),  -Vector3d::UnitZ()};

// PLANx frame as LMGC90 builds it: T = e1, S = −e2, N = e3 of the body frame (S = T × N).
Matrix3d plane_frame_of(const Matrix3d& body_frame) {
  Matrix3d f;
  f.col(0) = body_frame.col(0);
  f.col(1) = -body_frame.col(1);
  f.col(2) = body_frame.col(2);
  return f;
}

// ---- comp_rep -------------------------------------------------------------------------------

TEST(TangentsOfNormal, RandomNormalsGiveRightHandedOrthonormalFrames) {
  for (const Vector3d& n : random_unit_normals(1000)) {
    Vector3d t, s;
    tangents_of_normal(n, t, s);
    expect_right_handed(t, n, s);
  }
}

TEST(TangentsOfNormal, GeneralNormalTakesTangentAlongE1CrossN) {
  const Vector3d n = Vector3d(1.0, 2.0, 2.0) / 3.0;
  Vector3d t, s;
  tangents_of_normal(n, t, s);
  expect_near(t, Vector3d(0.0, -2.0, 2.0).normalized());
  expect_right_handed(t, n, s);
}

TEST(TangentsOfNormal, AxisAlignedNormalsGiveRightHandedOrthonormalFrames) {
  for (const Vector3d& n : kAxisNormals) {
    Vector3d t, s;
    tangents_of_normal(n, t, s);
    expect_right_handed(t, n, s);
  }
}

TEST(TangentsOfNormal, EachCoordinatePlaneBranchTakesItsInPlanePerpendicular) {
  struct Case {
    Vector3d n, t;
  };
  const std::array<Case, 3> cases = {
      Case{Vector3d(0.0, 0.6, 0.8), Vector3d(0.0, -0.8, 0.6)},  // |n1| < 1e-15: t = (n1, -n3, n2)
      Case{Vector3d(0.6, 0.0, 0.8), Vector3d(-0.8, 0.0, 0.6)},  // |n2| < 1e-15: t = (-n3, n2, n1)
      Case{Vector3d(0.6, 0.8, 0.0), Vector3d(-0.8, 0.6, 0.0)},  // |n3| < 1e-15: t = (-n2, n1, n3)
  };
  for (const Case& c : cases) {
    Vector3d t, s;
    tangents_of_normal(c.n, t, s);
    expect_near(t, c.t);
    expect_right_handed(t, c.n, s);
  }
  // The first branch that applies wins: n = e1 falls in the |n2| branch, n = e3 in the |n1| one.
  Vector3d t, s;
  tangents_of_normal(Vector3d::UnitX(), t, s);
  expect_near(t, Vector3d::UnitZ());
  tangents_of_normal(Vector3d::UnitZ(), t, s);
  expect_near(t, -Vector3d::UnitY());
}

// ---- SPSPx tangents ------------------------------------------------------------------------

TEST(SphereSphereTangents, RandomNormalsGiveRightHandedOrthonormalFrames) {
  for (const Vector3d& n : random_unit_normals(1000)) {
    Vector3d t, s;
    sphere_sphere_tangents(n, t, s);
    expect_right_handed(t, n, s);
  }
}

TEST(SphereSphereTangents, GeneralNormalUsesTheProductFormula) {
  const Vector3d n = Vector3d(1.0, 2.0, 2.0) / 3.0;
  Vector3d t, s;
  sphere_sphere_tangents(n, t, s);
  const double n1 = n.x(), n2 = n.y(), n3 = n.z();
  expect_near(t, Vector3d(-n2 * n3, -n3 * n1, 2.0 * n1 * n2).normalized());
  expect_right_handed(t, n, s);
}

TEST(SphereSphereTangents, AxisAlignedNormalsTakeTheCyclicPermutationAndAreRightHandedOrthonormal) {
  for (const Vector3d& n : kAxisNormals) {
    Vector3d t, s;
    sphere_sphere_tangents(n, t, s);
    expect_near(t, Vector3d(n.z(), n.x(), n.y()));
    expect_right_handed(t, n, s);
  }
}

// mod_SPSPx.f90:1217-1224: the "some n_i n_j = 0" branch is t = (n3, n1, n2) whatever the other
// components; with exactly one zero component LMGC90's t is not perpendicular to n. Pinned here so
// that a deliberate change shows up.
TEST(SphereSphereTangents, OneZeroComponentKeepsLmgc90PermutationWhichIsNotPerpendicular) {
  const Vector3d n(0.0, 0.6, 0.8);
  Vector3d t, s;
  sphere_sphere_tangents(n, t, s);
  expect_near(t, Vector3d(0.8, 0.0, 0.6));
  EXPECT_NEAR(t.dot(n), 0.48, kTol);
  expect_near(s, t.cross(n));
}

// ---- SPSPx ---------------------------------------------------------------------------------

TEST(SphereSphere, OverlappingPairGivesGapNormalFromAntagonistAndMidOverlapPoint) {
  const Vector3d antagonist(1.0, 1.0, 1.0);
  const Vector3d direction = Vector3d(2.0, 1.0, 2.0) / 3.0;
  const Vector3d candidate = antagonist + 0.9 * direction;
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_sphere(candidate, 0.45, antagonist, 0.5, 0.1, g));
  EXPECT_NEAR(g.gap, 0.9 - 0.95, kTol);
  expect_near(g.normal, direction);
  // Halfway between the antagonist's surface (0.5) and the candidate's (0.9 − 0.45).
  expect_near(g.point, antagonist + 0.475 * direction);
  expect_right_handed(g.tangent, g.normal, g.second_tangent);
}

TEST(SphereSphere, SeparatedPairGivesPositiveGapAndPointBetweenSurfaces) {
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_sphere(Vector3d(0.0, 0.0, 1.5), 0.5, Vector3d::Zero(), 0.5, 0.5, g));
  EXPECT_EQ(g.gap, 0.5);  // equal to the alert distance: kept
  expect_near(g.normal, Vector3d::UnitZ());
  expect_near(g.point, Vector3d(0.0, 0.0, 0.75));
}

TEST(SphereSphere, GapBeyondAlertIsRejected) {
  ContactGeometry3D g;
  EXPECT_FALSE(detect_sphere_sphere(Vector3d(0.0, 0.0, 1.5), 0.5, Vector3d::Zero(), 0.5, 0.25, g));
}

TEST(SphereSphere, CoincidentCentresAreRejected) {
  ContactGeometry3D g;
  EXPECT_FALSE(detect_sphere_sphere(Vector3d::Ones(), 0.5, Vector3d::Ones(), 0.5, 1.0, g));
}

// ---- SPPLx ---------------------------------------------------------------------------------

const Vector3d kAxes(1.0, 0.5, 0.05);  // axe1 along T, axe2 along S, axe3 (half-thickness) along N

TEST(SpherePlane, SphereAboveFaceGetsGapHeightMinusRadiusMinusHalfThickness) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_plane(Vector3d(0.3, -0.2, 0.5), 0.2, Vector3d::Zero(), frame, kAxes, 0.3, g));
  EXPECT_NEAR(g.gap, 0.5 - 0.2 - 0.05, kTol);
  expect_near(g.normal, Vector3d::UnitZ());
  expect_near(g.tangent, frame.col(0));
  expect_near(g.second_tangent, frame.col(1));
  expect_right_handed(g.tangent, g.normal, g.second_tangent);
  // Halfway between the plate's surface (0.05) and the sphere's lowest point (0.3).
  expect_near(g.point, Vector3d(0.3, -0.2, 0.175));
}

TEST(SpherePlane, SphereBelowFaceFlipsTheWholeFrameSoItIsLeftHanded) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_plane(Vector3d(0.3, -0.2, -0.5), 0.2, Vector3d::Zero(), frame, kAxes, 0.3, g));
  EXPECT_NEAR(g.gap, 0.25, kTol);
  expect_near(g.normal, -Vector3d::UnitZ());
  // mod_SPPLx.f90:796-801: (t, n, s) = (−T, −N, −S), hence s = −(t × n) on this side.
  expect_near(g.tangent, -frame.col(0));
  expect_near(g.second_tangent, -frame.col(1));
  expect_near(g.second_tangent, -g.tangent.cross(g.normal));
  expect_near(g.point, Vector3d(0.3, -0.2, -0.175));
}

TEST(SpherePlane, NormalGapEqualToAlertIsRejected) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  const Vector3d axes(1.0, 1.0, 0.25);
  ContactGeometry3D g;
  // gap = 1 − 0.25 − 0.25 = 0.5 exactly; the test is strict.
  EXPECT_FALSE(detect_sphere_plane(Vector3d(0.0, 0.0, 1.0), 0.25, Vector3d::Zero(), frame, axes, 0.5, g));
  EXPECT_TRUE(detect_sphere_plane(Vector3d(0.0, 0.0, 1.0), 0.25, Vector3d::Zero(), frame, axes, 0.5625, g));
  EXPECT_FALSE(detect_sphere_plane(Vector3d(0.0, 0.0, 1.0), 0.25, Vector3d::Zero(), frame, axes, 0.25, g));
}

TEST(SpherePlane, SphereBeyondEdgeTouchesTheRoundedEdgeAtTheClampedPoint) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_plane(Vector3d(1.1, -0.2, 0.2), 0.2, Vector3d::Zero(), frame, kAxes, 0.01, g));
  const Vector3d closest(1.0, -0.2, 0.0);  // on the mid-plane rectangle
  const Vector3d d = Vector3d(1.1, -0.2, 0.2) - closest;
  EXPECT_NEAR(g.gap, d.norm() - 0.2 - 0.05, kTol);
  EXPECT_LT(g.gap, 0.0);
  expect_near(g.normal, d.normalized());
  Vector3d t, s;
  tangents_of_normal(g.normal, t, s);
  expect_near(g.tangent, t);
  expect_near(g.second_tangent, s);
  expect_right_handed(g.tangent, g.normal, g.second_tangent);
  expect_near(g.point, Vector3d(1.1, -0.2, 0.2) - g.normal * (0.2 + 0.5 * g.gap));
}

TEST(SpherePlane, SphereBeyondEdgeIsKeptByTheNormalTestEvenWhenItsEdgeGapExceedsAlert) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  // Along N: 0.2 − 0.25 < alert; in the plane 1.2 < r + axe1 + axe3 = 1.25; true gap ≈ 0.033.
  ASSERT_TRUE(detect_sphere_plane(Vector3d(1.2, 0.0, 0.2), 0.2, Vector3d::Zero(), frame, kAxes, 0.01, g));
  EXPECT_NEAR(g.gap, std::sqrt(0.08) - 0.25, kTol);
  EXPECT_GT(g.gap, 0.01);
  expect_near(g.normal, Vector3d(1.0, 0.0, 1.0).normalized());
}

TEST(SpherePlane, SphereBelowBeyondEdgeTouchesTheRoundedEdgeFromBelow) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_plane(Vector3d(0.2, 0.6, -0.1), 0.2, Vector3d::Zero(), frame, kAxes, 0.01, g));
  const Vector3d d(0.0, 0.1, -0.1);  // from the clamped point (0.2, 0.5, 0)
  EXPECT_NEAR(g.gap, d.norm() - 0.25, kTol);
  expect_near(g.normal, d.normalized());
}

TEST(SpherePlane, SphereFartherThanRadiusPlusHalfAxesInThePlaneIsIgnored) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  EXPECT_FALSE(detect_sphere_plane(Vector3d(1.3, 0.0, 0.0), 0.2, Vector3d::Zero(), frame, kAxes, 0.1, g));
  EXPECT_FALSE(detect_sphere_plane(Vector3d(0.0, -0.8, 0.0), 0.2, Vector3d::Zero(), frame, kAxes, 0.1, g));
}

TEST(SpherePlane, CentreExactlyAboveTheFaceBorderTakesTheEdgeBranchWithCompRepTangents) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  // |x_T| = axe1: the face test is strict, so the edge branch runs; its normal is still +N.
  ASSERT_TRUE(detect_sphere_plane(Vector3d(1.0, 0.0, 0.5), 0.2, Vector3d::Zero(), frame, kAxes, 0.3, g));
  EXPECT_NEAR(g.gap, 0.25, kTol);
  expect_near(g.normal, Vector3d::UnitZ());
  expect_near(g.tangent, -Vector3d::UnitY());  // comp_rep, not T
  expect_near(g.second_tangent, -Vector3d::UnitX());
}

TEST(SpherePlane, GapBeyondAlertAlongTheNormalIsRejected) {
  const Matrix3d frame = plane_frame_of(Matrix3d::Identity());
  ContactGeometry3D g;
  EXPECT_FALSE(detect_sphere_plane(Vector3d(0.3, -0.2, 0.5), 0.2, Vector3d::Zero(), frame, kAxes, 0.2, g));
  EXPECT_FALSE(detect_sphere_plane(Vector3d(0.3, -0.2, -0.5), 0.2, Vector3d::Zero(), frame, kAxes, 0.2, g));
}

TEST(SpherePlane, TiltedPlaneGivesRotatedFrameAndTheSameGapInPlaneCoordinates) {
  const double angle = std::numbers::pi / 6.0;
  const Matrix3d untilted = plane_frame_of(Matrix3d::Identity());
  const Matrix3d rotation = Eigen::AngleAxisd(angle, untilted.col(1)).toRotationMatrix();
  const Matrix3d frame = rotation * untilted;
  const Vector3d plane_centre(0.5, -1.0, 2.0);
  // Rotation by 30° about S = −e2 takes N = e3 to (−sin 30°, 0, cos 30°).
  expect_near(frame.col(2), Vector3d(-0.5, 0.0, std::sqrt(3.0) / 2.0));
  const std::array<Vector3d, 3> locals = {Vector3d(0.3, -0.2, 0.5), Vector3d(0.3, -0.2, -0.5),
                                          Vector3d(1.1, -0.2, 0.2)};
  for (const Vector3d& local : locals) {
    ContactGeometry3D flat, tilted;
    ASSERT_TRUE(detect_sphere_plane(local, 0.2, Vector3d::Zero(), untilted, kAxes, 0.3, flat));
    ASSERT_TRUE(
        detect_sphere_plane(plane_centre + rotation * local, 0.2, plane_centre, frame, kAxes, 0.3, tilted));
    EXPECT_NEAR(tilted.gap, flat.gap, kTol);
    expect_near(tilted.normal, rotation * flat.normal);
    expect_near(tilted.point, plane_centre + rotation * flat.point);
    if (std::fabs(local.x()) < kAxes.x()) {
      // Face: the tangents are the rotated (±T, ±S).
      expect_near(tilted.tangent, rotation * flat.tangent);
      expect_near(tilted.second_tangent, rotation * flat.second_tangent);
    } else {
      expect_right_handed(tilted.tangent, tilted.normal, tilted.second_tangent);
    }
  }
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_plane(plane_centre + frame * Vector3d(0.3, 0.2, 0.5), 0.2, plane_centre, frame,
                                  kAxes, 0.3, g));
  expect_near(g.normal, Vector3d(-0.5, 0.0, std::sqrt(3.0) / 2.0));
  EXPECT_NEAR(g.gap, 0.25, kTol);
}

}  // namespace
}  // namespace lmgc::solver
