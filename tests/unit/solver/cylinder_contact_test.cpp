// CYLND detection: a sphere beside, over an end and off the rim of a cylinder (SPCDx), and capsule
// pairs (CDCDx) skew, parallel side by side and end to end, on cases whose answers are known.
#include "solver/detection/cylinder_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace lmgc::solver {
namespace {

using Eigen::Vector3d;

PlacedCylinder upright() {  // axis z, half-length 1, radius 0.5, centred at the origin
  PlacedCylinder c;
  c.axis = Vector3d::UnitZ();
  c.half_length = 1.0;
  c.radius = 0.5;
  return c;
}

TEST(SphereCylinder, BesideOverAnEndAndOffTheRim) {
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_cylinder(Vector3d(0.8, 0.0, 0.3), 0.2, upright(), 0.5, g));
  EXPECT_NEAR(g.gap, 0.1, 1e-14);
  EXPECT_TRUE(g.normal.isApprox(Vector3d::UnitX()));
  EXPECT_TRUE(g.point.isApprox(Vector3d(0.6, 0.0, 0.3)));
  EXPECT_NEAR(g.second_tangent.dot(g.normal.cross(g.tangent)), 1.0, 1e-12);  // s = n × t (SPCDx)

  ASSERT_TRUE(detect_sphere_cylinder(Vector3d(0.3, 0.0, -1.25), 0.2, upright(), 0.5, g));
  EXPECT_NEAR(g.gap, 0.05, 1e-14);
  EXPECT_TRUE(g.normal.isApprox(-Vector3d::UnitZ()));

  // Off the rim at 45°: distance from the rim circle sqrt(2)·0.1, minus the radius.
  ASSERT_TRUE(detect_sphere_cylinder(Vector3d(0.6, 0.0, 1.1), 0.1, upright(), 0.5, g));
  EXPECT_NEAR(g.gap, std::sqrt(2.0) * 0.1 - 0.1, 1e-14);
  EXPECT_TRUE(g.normal.isApprox(Vector3d(1.0, 0.0, 1.0).normalized()));

  EXPECT_FALSE(detect_sphere_cylinder(Vector3d(2.0, 0.0, 0.0), 0.2, upright(), 0.5, g));
}

TEST(CylinderCylinder, SkewAxesMeetAtTheirClosestPoints) {
  PlacedCylinder lower = upright(), upper = upright();
  lower.axis = Vector3d::UnitX();
  upper.axis = Vector3d::UnitY();
  upper.centre = Vector3d(0.3, -0.2, 1.05);  // 5 cm above touching, crossing inside both lengths
  CylinderContact contact;
  ASSERT_TRUE(detect_cylinder_cylinder(upper, lower, 0.1, contact));
  ASSERT_EQ(contact.count, 1);
  EXPECT_NEAR(contact.points[0].gap, 0.05, 1e-14);
  EXPECT_TRUE(contact.points[0].normal.isApprox(Vector3d::UnitZ()));
  EXPECT_TRUE(contact.points[0].point.isApprox(Vector3d(0.3, 0.0, 0.525)));
}

TEST(CylinderCylinder, ParallelAxesSideBySideGiveTwoPointsAndEndToEndOne) {
  PlacedCylinder a = upright(), b = upright();
  a.axis = b.axis = Vector3d::UnitX();
  b.centre = Vector3d(0.5, 0.0, 1.0);  // side by side, overlapping over x in [-0.5, 1]
  CylinderContact contact;
  ASSERT_TRUE(detect_cylinder_cylinder(b, a, 0.1, contact));
  ASSERT_EQ(contact.count, 2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(contact.points[static_cast<std::size_t>(k)].gap, 0.0, 1e-14);
    EXPECT_TRUE(contact.points[static_cast<std::size_t>(k)].normal.isApprox(Vector3d::UnitZ()));
  }
  b.centre = Vector3d(3.02, 0.0, 0.0);  // end to end, capsule caps 2 cm apart
  ASSERT_TRUE(detect_cylinder_cylinder(b, a, 0.1, contact));
  ASSERT_EQ(contact.count, 1);
  EXPECT_NEAR(contact.points[0].gap, 0.02, 1e-12);
  EXPECT_TRUE(contact.points[0].normal.isApprox(Vector3d::UnitX()));
}

}  // namespace
}  // namespace lmgc::solver

namespace lmgc::solver {
namespace {

TEST(SphereTube, InnerWallWithinTheLengthOnly) {
  PlacedCylinder tube;
  tube.axis = Eigen::Vector3d::UnitZ();
  tube.half_length = 1.0;
  tube.radius = 0.5;
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_tube(Eigen::Vector3d(0.35, 0.0, 0.2), 0.1, tube, 0.1, g));
  EXPECT_NEAR(g.gap, 0.05, 1e-14);
  EXPECT_TRUE(g.normal.isApprox(-Eigen::Vector3d::UnitX()));  // towards the axis
  EXPECT_TRUE(g.point.isApprox(Eigen::Vector3d(0.45, 0.0, 0.2)));
  EXPECT_FALSE(detect_sphere_tube(Eigen::Vector3d(0.35, 0.0, 1.2), 0.1, tube, 0.1, g));  // beyond an end
  EXPECT_FALSE(detect_sphere_tube(Eigen::Vector3d(0.1, 0.0, 0.0), 0.1, tube, 0.1, g));   // near the axis
}

}  // namespace
}  // namespace lmgc::solver
