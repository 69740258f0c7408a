// PTPT3 links (solver/detection/point_contact): which PT3Dx pairs are linked, and the frame of a
// link as mod_PTPT3 builds it. spec: contact-laws.md §3.4; mod_PTPT3.f90 compute_box,
// compute_contact.
#include "solver/detection/point_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

void expect_right_handed_orthonormal(const ContactGeometry3D& g) {
  EXPECT_NEAR(g.tangent.norm(), 1.0, 1e-15);
  EXPECT_NEAR(g.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(g.tangent.dot(g.normal), 0.0, 1e-15);
  EXPECT_TRUE(g.second_tangent.isApprox(g.tangent.cross(g.normal), 1e-15));
}

TEST(PointPointGeometry, NormalGoesFromAntagonistToCandidateAndGapIsTheDistance) {
  const Vector3d cd(1.0, 2.0, 3.0), an(0.5, -1.0, 2.0);
  const ContactGeometry3D g = point_point_geometry(cd, an);
  EXPECT_NEAR(g.gap, (cd - an).norm(), 1e-15);
  EXPECT_TRUE(g.normal.isApprox((cd - an).normalized()));
  EXPECT_TRUE(g.point.isApprox(0.5 * (cd + an)));
  expect_right_handed_orthonormal(g);
  // mod_PTPT3's rule off the axes: t = (f, 1, 1)/|.| with f = −(n2 + n3)/n1.
  EXPECT_DOUBLE_EQ(g.tangent.y(), g.tangent.z());
}

TEST(PointPointGeometry, AxisAlignedNormalsTakeLmgc90sFixedTangents) {
  EXPECT_EQ(point_point_geometry(Vector3d(2, 0, 0), Vector3d::Zero()).tangent, Vector3d::UnitZ());
  EXPECT_EQ(point_point_geometry(Vector3d(0, -2, 0), Vector3d::Zero()).tangent, Vector3d::UnitX());
  EXPECT_EQ(point_point_geometry(Vector3d(0, 0, 2), Vector3d::Zero()).tangent, Vector3d::UnitY());
  // n in the (y, z) plane: t = (1, 1, f)/|.| with f = −n2/n3.
  const ContactGeometry3D g = point_point_geometry(Vector3d(0, 1, 2), Vector3d::Zero());
  expect_right_handed_orthonormal(g);
  EXPECT_DOUBLE_EQ(g.tangent.x(), g.tangent.y());
  for (const Vector3d& d : {Vector3d(1, 0, 0), Vector3d(0, 0, -1), Vector3d(1, 1, 0), Vector3d(-1, 0, 3)})
    expect_right_handed_orthonormal(point_point_geometry(d, Vector3d::Zero()));
}

TEST(PointPointGeometry, CoincidentPointsGiveTheGlobalAxesAndZeroGap) {
  const ContactGeometry3D g = point_point_geometry(Vector3d(1, 1, 1), Vector3d(1, 1, 1));
  EXPECT_EQ(g.gap, 0.0);
  expect_right_handed_orthonormal(g);
}

// Three spheres with a PT3Dx each, 1 m apart on a line, and a second point on the first body:
// links join points of different bodies within the alert, in candidate order, with the row read
// candidate → antagonist.
TEST(LinkPoints3D, LinksPointsOfOtherBodiesWithinTheAlertInCandidateOrder) {
  SceneBuilder3D b;
  for (int k = 0; k < 3; ++k) {
    const int body = b.add_sphere(Vector3d(k, 0.0, 0.0), 0.1, 1000.0);
    b.add_point(body, Vector3d::Zero(), k == 2 ? "REDxx" : "BLEUx");
  }
  b.add_point(0, Vector3d(0.0, 0.5, 0.0), "BLEUx");  // same body as the first point: never linked
  b.add_law("wire1", ElasticWire{1000.0, 0.0});
  b.see("PT3Dx", "BLEUx", "wire1", "PT3Dx", "BLEUx", 1.2);
  b.see("PT3Dx", "BLEUx", "wire1", "PT3Dx", "REDxx", 1.5);
  const Scene3D scene = b.build();
  // Contactors: 0 sphere, 1 point (body 0), 2 sphere, 3 point (body 1), 4 sphere, 5 point (body 2),
  // 6 point (body 0, offset).
  ASSERT_EQ(scene.point_links.size(), 3u);
  EXPECT_EQ(scene.point_links[0].candidate, 1);
  EXPECT_EQ(scene.point_links[0].antagonist, 3);
  EXPECT_DOUBLE_EQ(scene.point_links[0].reference_length, 1.0);
  EXPECT_EQ(scene.point_links[1].candidate, 3);  // body 0 → body 2 is 2 m: beyond 1.5
  EXPECT_EQ(scene.point_links[1].antagonist, 5);
  EXPECT_EQ(scene.point_links[1].visibility, 1);
  EXPECT_EQ(scene.point_links[2].candidate, 3);  // body 1 → the offset point of body 0
  EXPECT_EQ(scene.point_links[2].antagonist, 6);
  EXPECT_NEAR(scene.point_links[2].reference_length, std::hypot(1.0, 0.5), 1e-15);
}

}  // namespace
}  // namespace lmgc::solver
