// The rows of H of a mesh side (solver/model/mesh_contact_2d.hpp mesh_side_rows): a point's (CLxxx,
// PT2DL, ALpxx) velocity and reaction rows are one and the same, its nodes' weights times the
// direction; a DISKL's are mod_DISKL's get_vlocy and add_reac. A translation of the edge moves the
// disk with it, and the nodes' shares of an impulse add up to it: both maps agree on the rigid
// translation; on rotation they are LMGC90's own (docs/lmgc90-facts/mailx-2d-contact.md §7c).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/model/mesh_contact_2d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;

Scene2D scene_with(const MeshContactor& tactor) {
  Scene2D scene;
  scene.deformable.meshes.contactors.push_back(tactor);
  return scene;
}

// The side's local velocity for the nodes' velocities va, vb (the side's nodes are 0 and 1 here, or
// any two nodes given the same velocities).
Vector2d side_velocity(const MeshSideRows& rows, const Vector2d& va, const Vector2d& vb) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(2 * (std::max(rows.side.nodes[0], rows.side.nodes[1]) + 1));
  v.segment<2>(2 * rows.side.nodes[0]) = va;
  v.segment<2>(2 * rows.side.nodes[1]) = vb;
  return mesh_side_local_velocity(rows, v);
}

TEST(MeshSideRows, APointsVelocityAndReactionRowsAreItsWeightsTimesTheDirection) {
  MeshContactor pt;
  pt.shape = MeshContactorShape::point;
  pt.type = "PT2DL";
  pt.nodes = {3, 7};
  pt.apab = 0.25;
  const Scene2D scene = scene_with(pt);
  Interaction2D c;
  c.family = PairFamily2D::P2P2L;
  c.normal = Vector2d(0.6, 0.8);
  c.lever_candidate = Vector2d(0.75, 0.25);
  c.lever_antagonist = Vector2d(0.75, 0.25);
  const MeshSideRows rows = mesh_side_rows(scene, c, 1);
  EXPECT_EQ(rows.side.nodes[0], 3);
  EXPECT_EQ(rows.side.nodes[1], 7);
  EXPECT_EQ(rows.velocity, rows.reaction);
  const Vector2d u = side_velocity(rows, Vector2d(1.0, 2.0), Vector2d(-3.0, 0.5));
  const Vector2d v = 0.75 * Vector2d(1.0, 2.0) + 0.25 * Vector2d(-3.0, 0.5);
  EXPECT_NEAR(u(0), v.dot(c.tangent()), 1e-15);
  EXPECT_NEAR(u(1), v.dot(c.normal), 1e-15);
}

class DisklRows : public ::testing::Test {
 protected:
  void SetUp() override {
    MeshContactor dl;
    dl.shape = MeshContactorShape::disk;
    dl.type = "DISKL";
    dl.nodes = {0, 1};
    dl.apab = 0.3;
    dl.arc_height = 0.04;
    dl.arc_half_chord = 0.05;
    scene = scene_with(dl);
    c.family = PairFamily2D::DKDKL;
    c.antagonist = 0;
    const double angle = 0.4;  // the contact's normal, from the DISKL's centre to the disk's
    c.normal = Vector2d(std::sin(angle), std::cos(angle));
    c.lever_antagonist = Vector2d(0.1, 0.02);  // the edge b − a
  }
  Scene2D scene;
  Interaction2D c;
};

TEST_F(DisklRows, ATranslationOfTheEdgeMovesTheDiskWithIt) {
  const MeshSideRows rows = mesh_side_rows(scene, c, 1);
  const Vector2d v(0.7, -1.3);
  const Vector2d u = side_velocity(rows, v, v);
  EXPECT_NEAR(u(0), v.dot(c.tangent()), 1e-14);
  EXPECT_NEAR(u(1), v.dot(c.normal), 1e-14);
}

TEST_F(DisklRows, TheNodesSharesOfAnImpulseAddUpToIt) {
  const MeshSideRows rows = mesh_side_rows(scene, c, 1);
  // The antagonist receives −(rows · r): the force −(RT t + RN n), split on the two nodes.
  const Vector2d directions[2] = {c.tangent(), c.normal};
  for (std::size_t k = 0; k < 2; ++k) {
    const Vector2d sum(rows.reaction[k][0] + rows.reaction[k][2], rows.reaction[k][1] + rows.reaction[k][3]);
    EXPECT_NEAR((sum - directions[k]).norm(), 0.0, 1e-14) << k;
  }
}

// mod_DISKL add_reac_DISKL: the moment of the nodes' forces about the edge's point is the impulse's
// moment r RT less Ft (r − h), Ft its force along the edge (LMGC90's sign; the moment of a force at the
// centre about that point would be + Ft (r − h)).
TEST_F(DisklRows, TheNodesForcesCarryLmgc90sMomentAboutTheEdgesPoint) {
  const MeshSideRows rows = mesh_side_rows(scene, c, 1);
  const MeshContactor& dl = scene.deformable.meshes.contactors[0];
  const Vector2d edge = c.lever_antagonist, te = edge / edge.norm();
  const Vector2d a = -dl.apab * edge, b = (1.0 - dl.apab) * edge;  // from the edge's point
  const double radius = dl.disk_radius(), offset = radius - dl.arc_height;
  EXPECT_NEAR(radius, (0.04 * 0.04 + 0.05 * 0.05) / 0.08, 1e-15);
  const auto cross = [](const Vector2d& p, const Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); };
  const Vector2d directions[2] = {c.tangent(), c.normal};
  for (std::size_t k = 0; k < 2; ++k) {
    const Vector2d fa(-rows.reaction[k][0], -rows.reaction[k][1]),
        fb(-rows.reaction[k][2], -rows.reaction[k][3]);
    const Vector2d force = -directions[k];
    const double moment = k == 0 ? radius : 0.0;
    EXPECT_NEAR(cross(a, fa) + cross(b, fb), moment - te.dot(force) * offset, 1e-14) << k;
  }
}

}  // namespace
}  // namespace lmgc::solver
