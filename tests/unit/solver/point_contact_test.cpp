// PTPT3 links (solver/detection/point_contact): which PT3Dx pairs are linked, and the frame of a
// link as mod_PTPT3 builds it. docs/lmgc90-facts/contact-laws.md §3.4; mod_PTPT3.f90 compute_box,
// compute_contact.
#include "solver/detection/point_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string>
#include <vector>

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

// Two bodies with a point each at their centres, one PT3Dx row of alert 0.3.
Scene3D two_points(const Vector3d& a, const Vector3d& b_at) {
  SceneBuilder3D b;
  b.add_point(b.add_sphere(a, 0.05, 1000.0), Vector3d::Zero(), "BLEUx");
  b.add_point(b.add_sphere(b_at, 0.05, 1000.0), Vector3d::Zero(), "BLEUx");
  b.add_law("rod01", ElasticWire{1000.0, 0.0});
  b.see("PT3Dx", "BLEUx", "rod01", "PT3Dx", "BLEUx", 0.3);
  return b.build();
}

using Periods = std::array<std::int32_t, 2>;

TEST(LinkPoints3D, APeriodicSideLinksPointsAcrossItWithTheAntagonistShifted) {
  Scene3D scene = two_points(Vector3d(0.1, 0, 0), Vector3d(0.9, 0, 0));
  EXPECT_TRUE(scene.point_links.empty());  // 0.8 apart without the period
  scene.x_period = 1.0;
  const std::vector<PointLink3D> links = link_points_3d(scene);
  ASSERT_EQ(links.size(), 1u);
  // The antagonist (x = 0.9) is seen one period to the left, 0.2 from the candidate. LMGC90 tries
  // only +period and misses this pair.
  EXPECT_EQ(links[0].periods, (Periods{-1, 0}));
  EXPECT_NEAR(links[0].reference_length, 0.2, 1e-15);

  Scene3D reversed = two_points(Vector3d(0.9, 0, 0), Vector3d(0.1, 0, 0));
  reversed.x_period = 1.0;
  const std::vector<PointLink3D> other = link_points_3d(reversed);
  ASSERT_EQ(other.size(), 1u);
  EXPECT_EQ(other[0].periods, (Periods{1, 0}));
}

TEST(LinkPoints3D, PointsOutsideThePeriodicCellLinkAsTheyAreAndAcrossTheCorner) {
  // x = 1.1 lies in the next cell: it is 0.2 from x = 0.9 directly, not across a side.
  Scene3D scene = two_points(Vector3d(1.1, 0, 0), Vector3d(0.9, 0, 0));
  scene.x_period = 1.0;
  std::vector<PointLink3D> links = link_points_3d(scene);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0].periods, (Periods{0, 0}));
  EXPECT_NEAR(links[0].reference_length, 0.2, 1e-15);
  // Across both sides: (0.1, 0.1) and (0.9, 0.9) in a unit cell are 0.2·√2 apart.
  Scene3D corner = two_points(Vector3d(0.1, 0.1, 0), Vector3d(0.9, 0.9, 0));
  corner.x_period = corner.y_period = 1.0;
  links = link_points_3d(corner);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0].periods, (Periods{-1, -1}));
  EXPECT_NEAR(links[0].reference_length, 0.2 * std::sqrt(2.0), 1e-15);
}

TEST(LinkPoints3D, APairWithinTheAlertDirectlyAndAcrossTheSideHasOneLinkForEachRankedInOrder) {
  Scene3D scene = two_points(Vector3d(0.2, 0, 0), Vector3d(0.45, 0, 0));
  scene.x_period = 0.5;  // 0.25 directly, 0.25 across
  const std::vector<PointLink3D> links = link_points_3d(scene);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(links[0].periods, (Periods{0, 0}));
  EXPECT_EQ(links[0].pair_rank, 0);
  EXPECT_EQ(links[1].periods, (Periods{-1, 0}));
  EXPECT_EQ(links[1].pair_rank, 1);
}

TEST(LinkPoints3D, ARowNamingTheColoursTheOtherWayRoundLinksAsGetIseeReadsIt) {
  SceneBuilder3D b;
  b.add_point(b.add_sphere(Vector3d::Zero(), 0.05, 1000.0), Vector3d::Zero(), "BLEUx");
  b.add_point(b.add_sphere(Vector3d(0.2, 0, 0), 0.05, 1000.0), Vector3d::Zero(), "REDxx");
  b.add_law("rod01", ElasticWire{1000.0, 0.0});
  b.see("PT3Dx", "REDxx", "rod01", "PT3Dx", "BLEUx", 0.3);
  const Scene3D scene = b.build();
  ASSERT_EQ(scene.point_links.size(), 1u);
  EXPECT_EQ(scene.point_links[0].candidate, 1);  // the first point stays the candidate
  EXPECT_EQ(scene.point_links[0].antagonist, 3);
}

TEST(LinkPoints3D, CurrentLengthsAreMeasuredAtTheStartingPositions) {
  Scene3D scene = two_points(Vector3d(0, 0, 0), Vector3d(0.2, 0, 0));
  scene.bodies.displacement_begin[1](0) = 0.05;  // DOF.INI moved the second body
  EXPECT_NEAR(link_points_3d(scene, LinkLength::reference_configuration)[0].reference_length, 0.2, 1e-15);
  EXPECT_NEAR(link_points_3d(scene, LinkLength::current)[0].reference_length, 0.25, 1e-15);
}

// PTPT3_NETWORK.DAT: links in file order between points numbered over the PT3Dx contactors.
grammar::Ptpt3NetworkFile network(std::initializer_list<std::array<double, 6>> rows) {
  grammar::Ptpt3NetworkFile file;
  for (const auto& r : rows) {
    grammar::Ptpt3Link link;
    link.candidate = grammar::Integer{static_cast<std::int64_t>(r[0])};
    link.antagonist = grammar::Integer{static_cast<std::int64_t>(r[1])};
    link.x_periods = grammar::Integer{static_cast<std::int64_t>(r[2])};
    link.y_periods = grammar::Integer{static_cast<std::int64_t>(r[3])};
    link.loop = grammar::Integer{static_cast<std::int64_t>(r[4])};
    link.reference_length = grammar::Real{r[5]};
    file.links.push_back(link);
  }
  return file;
}

TEST(NetworkLinks3D, LinksTheListedPointsWhateverTheirDistanceWithPeriodShifts) {
  Scene3D scene = two_points(Vector3d(0.1, 0, 0), Vector3d(0.9, 0, 0));
  scene.x_period = 1.0;
  std::vector<PointLink3D> links;
  std::string error;
  // Direct (0.8 apart: beyond the alert, listed all the same); the antagonist shifted by -1 period;
  // iloop = 1 shifts the candidate by +1 period, the same link.
  ASSERT_TRUE(network_links_3d(scene,
                               network({{1, 2, 0, 0, 0, 9.0}, {1, 2, -1, 0, 0, 9.0}, {1, 2, 1, 0, 1, 9.0}}),
                               LinkLength::reference_configuration, links, error))
      << error;
  ASSERT_EQ(links.size(), 3u);
  // Contactors: 0 sphere, 1 point, 2 sphere, 3 point.
  EXPECT_EQ(links[0].candidate, 1);
  EXPECT_EQ(links[0].antagonist, 3);
  EXPECT_NEAR(links[0].reference_length, 0.8, 1e-15);
  EXPECT_EQ(links[1].periods, (Periods{-1, 0}));
  EXPECT_NEAR(links[1].reference_length, 0.2, 1e-15);
  EXPECT_EQ(links[2].periods, (Periods{-1, 0}));
  EXPECT_FALSE(links[1].shift_candidate);
  EXPECT_TRUE(links[2].shift_candidate);  // where LMGC90 puts the contact point
  EXPECT_NEAR(links[2].reference_length, 0.2, 1e-15);
  EXPECT_EQ((std::array{links[0].pair_rank, links[1].pair_rank, links[2].pair_rank}),
            (std::array<std::int32_t, 3>{0, 1, 2}));
  // PTPT3_UseCurrentNonuc0(1): the file's nonuc0.
  ASSERT_TRUE(network_links_3d(scene, network({{2, 1, 0, 0, 0, 0.05}}), LinkLength::current, links, error));
  EXPECT_EQ(links[0].candidate, 3);
  EXPECT_DOUBLE_EQ(links[0].reference_length, 0.05);
}

TEST(NetworkLinks3D, RefusesUnknownPointsPointsOfOneBodyAndLinksWithoutARow) {
  SceneBuilder3D b;
  const int body = b.add_sphere(Vector3d::Zero(), 0.05, 1000.0);
  b.add_point(body, Vector3d::Zero(), "BLEUx");
  b.add_point(body, Vector3d(0.01, 0, 0), "BLEUx");
  b.add_point(b.add_sphere(Vector3d(1, 0, 0), 0.05, 1000.0), Vector3d::Zero(), "REDxx");
  b.add_law("rod01", ElasticWire{1000.0, 0.0});
  b.see("PT3Dx", "BLEUx", "rod01", "PT3Dx", "BLEUx", 0.3);
  const Scene3D scene = b.build();
  std::vector<PointLink3D> links;
  std::string error;
  EXPECT_FALSE(network_links_3d(scene, network({{1, 4, 0, 0, 0, 0.0}}), LinkLength::reference_configuration,
                                links, error));
  EXPECT_NE(error.find("point 4 does not exist"), std::string::npos) << error;
  EXPECT_FALSE(network_links_3d(scene, network({{1, 2, 0, 0, 0, 0.0}}), LinkLength::reference_configuration,
                                links, error));
  EXPECT_NE(error.find("both points are on body 1"), std::string::npos) << error;
  EXPECT_FALSE(network_links_3d(scene, network({{1, 3, 0, 0, 0, 0.0}}), LinkLength::reference_configuration,
                                links, error));
  EXPECT_NE(error.find("no PTPT3 visibility row"), std::string::npos) << error;
}

}  // namespace
}  // namespace lmgc::solver
