// POLYR geometry and detection: exact volume integrals, LMGC90's face orientation, PRPLx vertex
// contacts and PRPRx common-plane contacts (points, gaps, frame) on boxes whose answers are known.
#include "solver/detection/polyhedron_contact.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/bodies/polyhedron.hpp"
#include "tests/support/polyhedra.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Polyhedron box(const Vector3d& h) {
  return test::box_polyhedron(h);
}

struct Placed {
  std::vector<Vector3d> vertices, normals;
  PlacedPolyhedron view;
};
Placed place(const Polyhedron& p, const Vector3d& centre, const Matrix3d& frame = Matrix3d::Identity()) {
  Placed out;
  for (const Vector3d& v : p.vertices) out.vertices.push_back(centre + frame * v);
  for (const Vector3d& n : p.face_normals) out.normals.push_back(frame * n);
  out.view.shape = &p;
  out.view.vertices = out.vertices;
  out.view.normals = out.normals;
  out.view.centre = centre;
  out.view.radius = p.radius;
  return out;
}

TEST(Polyhedron, BoxVolumeCentroidAndInertiaAreExact) {
  Polyhedron p = box(Vector3d(0.5, 1.0, 1.5));
  for (Vector3d& v : p.vertices) v += Vector3d(1.0, -2.0, 3.0);
  const PolyhedronMass m = polyhedron_mass(p);
  const double V = 1.0 * 2.0 * 3.0;
  EXPECT_NEAR(m.volume, V, 1e-12);
  EXPECT_TRUE(m.centroid.isApprox(Vector3d(1.0, -2.0, 3.0), 1e-12));
  // Box: I_xx = V (b² + c²)/12 with full sides (a, b, c) = (1, 2, 3).
  EXPECT_NEAR(m.inertia(0, 0), V * (4.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia(1, 1), V * (1.0 + 9.0) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia(2, 2), V * (1.0 + 4.0) / 12.0, 1e-12);
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-12);
}

TEST(Polyhedron, OrientationMakesEveryFaceOutwardWhateverTheInputOrder) {
  Polyhedron p = box(Vector3d(1.0, 1.0, 1.0));
  // Flip some faces of the input and orient again: all outward, volume positive.
  for (std::size_t f = 0; f < p.faces.size(); f += 3) std::swap(p.faces[f][0], p.faces[f][1]);
  orient_faces(p.vertices, p.faces);
  finish_polyhedron(p);
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const Vector3d& a = p.vertices[static_cast<std::size_t>(p.faces[f][0])];
    EXPECT_GT(p.face_normals[f].dot(a), 0.0) << "face " << f;
  }
  EXPECT_NEAR(polyhedron_mass(p).volume, 8.0, 1e-12);
}

TEST(PolyhedronPlane, CubeResting1mmAboveAPlaneHasFourVertexContacts) {
  const Polyhedron cube = box(Vector3d::Constant(0.5));
  const Placed c = place(cube, Vector3d(0.0, 0.0, 0.501));
  Matrix3d plane = Matrix3d::Identity();
  plane.col(1) = -plane.col(1);  // (T, S, N) = (e1, -e2, e3)
  PolyhedronContact contact;
  ASSERT_TRUE(detect_polyhedron_plane(c.view, Vector3d(0.0, 0.0, -0.1), plane, Vector3d(2.0, 2.0, 0.1), 0.01,
                                      contact));
  ASSERT_EQ(contact.count, 4);
  EXPECT_TRUE(contact.normal.isApprox(Vector3d::UnitZ()));
  EXPECT_TRUE(contact.tangent.cross(contact.normal).isApprox(contact.second_tangent));
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(contact.gaps[static_cast<std::size_t>(k)], 0.001, 1e-12);
    EXPECT_NEAR(contact.points[static_cast<std::size_t>(k)].z(), 0.001, 1e-12);
    EXPECT_LT(contact.vertices[static_cast<std::size_t>(k)], 4);  // the bottom vertices 0..3
  }
  // Lifted beyond the alert distance: nothing.
  const Placed far = place(cube, Vector3d(0.0, 0.0, 0.52));
  EXPECT_FALSE(detect_polyhedron_plane(far.view, Vector3d(0.0, 0.0, -0.1), plane, Vector3d(2.0, 2.0, 0.1),
                                       0.01, contact));
}

TEST(PolyhedronPolyhedron, StackedCubesTouchAtTheFourCornersOfTheSmallerFace) {
  const Polyhedron big = box(Vector3d::Constant(0.5)), small = box(Vector3d::Constant(0.25));
  // Candidate on top, 2 mm above; shifted sideways so its face lies inside the lower one.
  const Placed top = place(small, Vector3d(0.1, -0.05, 0.5 + 0.25 + 0.002));
  const Placed bottom = place(big, Vector3d::Zero());
  PolyhedronContact contact;
  ASSERT_TRUE(detect_polyhedron_polyhedron(top.view, bottom.view, 0.01, 0.25, 100, contact));
  EXPECT_TRUE(contact.normal.isApprox(Vector3d::UnitZ(), 1e-9));
  ASSERT_EQ(contact.count, 4);
  std::vector<Vector3d> points(contact.points.begin(), contact.points.end());
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(contact.gaps[static_cast<std::size_t>(k)], 0.002, 1e-9);
    const Vector3d& p = points[static_cast<std::size_t>(k)];
    EXPECT_NEAR(std::abs(p.x() - 0.1), 0.25, 1e-9);
    EXPECT_NEAR(std::abs(p.y() + 0.05), 0.25, 1e-9);
    EXPECT_NEAR(p.z(), 0.501, 1e-9);  // midway between the two faces
  }
  // Interpenetrating by 3 mm: negative gaps.
  const Placed sunk = place(small, Vector3d(0.1, -0.05, 0.5 + 0.25 - 0.003));
  ASSERT_TRUE(detect_polyhedron_polyhedron(sunk.view, bottom.view, 0.01, 0.25, 100, contact));
  for (int k = 0; k < contact.count; ++k)
    EXPECT_NEAR(contact.gaps[static_cast<std::size_t>(k)], -0.003, 1e-9);
  // Apart by more than the alert distance: no contact.
  const Placed apart = place(small, Vector3d(0.1, -0.05, 0.5 + 0.25 + 0.02));
  EXPECT_FALSE(detect_polyhedron_polyhedron(apart.view, bottom.view, 0.01, 0.25, 100, contact));
}

// Blocks that share a whole face, as a bridge's voussoirs do: the two projected faces coincide up to
// round-off, edge on edge. Every point must lie on the shared face (a clip of coinciding edges once
// put a point metres outside both blocks, and the warm start then lost it from step to step).
TEST(PolyhedronPolyhedron, BlocksSharingAFaceTouchOnlyWithinIt) {
  const Vector3d half(2.4, 0.9, 0.6);
  const Polyhedron block = box(half);
  int checked = 0;
  for (int turn = 0; turn < 40; ++turn) {
    const Matrix3d frame =
        Eigen::AngleAxisd(0.05 + 0.37 * turn, Vector3d(1.0, 2.0 + turn, 3.0).normalized()).toRotationMatrix();
    const Vector3d below = Vector3d(1.0, -2.0, 0.5) * turn;
    const Placed bottom = place(block, below, frame);
    const Placed top = place(block, below + frame * Vector3d(0.0, 0.0, 2.0 * half.z()), frame);
    PolyhedronContact contact;
    ASSERT_TRUE(detect_polyhedron_polyhedron(top.view, bottom.view, 0.01, 0.6, 100, contact)) << turn;
    ASSERT_GE(contact.count, 1) << turn;
    for (int k = 0; k < contact.count; ++k) {
      const Vector3d local = frame.transpose() * (contact.points[static_cast<std::size_t>(k)] - below);
      EXPECT_LE(std::abs(local.x()), half.x() + 1e-6) << turn << " point " << k;
      EXPECT_LE(std::abs(local.y()), half.y() + 1e-6) << turn << " point " << k;
      EXPECT_NEAR(local.z(), half.z(), 1e-6) << turn << " point " << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  // Edge beside edge within the detection's tolerance (1e-9 of the radius), slightly turned: the
  // subject's edge runs from just inside that tolerance to just beyond it, on each side in turn.
  const double tolerance = 1e-9 * block.radius;
  const Vector3d sides[] = {Vector3d::UnitX(), -Vector3d::UnitX(), Vector3d::UnitY(), -Vector3d::UnitY()};
  for (const Vector3d& side : sides)
    for (const double offset : {0.95, 1.0, 1.05}) {
      const double along = side.x() != 0.0 ? half.y() : half.x();  // the edge's half length
      const Matrix3d turned =
          Eigen::AngleAxisd(0.1 * tolerance / along, Vector3d::UnitZ()).toRotationMatrix();
      const Placed bottom = place(block, Vector3d::Zero());
      const Placed top = place(block, offset * tolerance * side + Vector3d(0.0, 0.0, 2.0 * half.z()), turned);
      PolyhedronContact contact;
      ASSERT_TRUE(detect_polyhedron_polyhedron(top.view, bottom.view, 0.01, 0.6, 100, contact)) << offset;
      for (int k = 0; k < contact.count; ++k) {
        const Vector3d& point = contact.points[static_cast<std::size_t>(k)];
        EXPECT_LE(std::abs(point.x()), half.x() + 1e-6)
            << side.transpose() << " " << offset << " point " << k;
        EXPECT_LE(std::abs(point.y()), half.y() + 1e-6)
            << side.transpose() << " " << offset << " point " << k;
      }
    }
}

TEST(PolyhedronPolyhedron, TiltedFaceGivesEachPointItsOwnGap) {
  // The upper cube turned by 0.02 rad about y: its lower face rises along +x, so the points at
  // x = +0.5 are farther than those at x = -0.5 by sin(0.02) (the common plane follows the lowest
  // corner).
  const Polyhedron cube = box(Vector3d::Constant(0.5));
  const double angle = 0.02;
  const Matrix3d turn = Eigen::AngleAxisd(-angle, Vector3d::UnitY()).toRotationMatrix();
  const double lowest = 0.5 * (std::cos(angle) + std::sin(angle));  // centre height above the lowest corner
  const Placed top = place(cube, Vector3d(0.0, 0.0, 0.5 + lowest + 0.001), turn);
  const Placed bottom = place(cube, Vector3d::Zero());
  PolyhedronContact contact;
  ASSERT_TRUE(detect_polyhedron_polyhedron(top.view, bottom.view, 0.05, 0.5, 100, contact));
  ASSERT_GE(contact.count, 2);
  double low = 1.0, high = -1.0;
  for (int k = 0; k < contact.count; ++k) {
    low = std::min(low, contact.gaps[static_cast<std::size_t>(k)]);
    high = std::max(high, contact.gaps[static_cast<std::size_t>(k)]);
  }
  EXPECT_NEAR(low, 0.001, 1e-6);
  EXPECT_GT(high - low, 0.5 * std::sin(angle));
}

TEST(PolyhedronPolyhedron, CrossedEdgesMeetAtOnePoint) {
  // Two cubes turned by 45° about x and about y, edge on edge: one contact point at the crossing.
  const Polyhedron cube = box(Vector3d::Constant(0.5));
  const Matrix3d about_x = Eigen::AngleAxisd(M_PI / 4.0, Vector3d::UnitX()).toRotationMatrix();
  const Matrix3d about_y = Eigen::AngleAxisd(M_PI / 4.0, Vector3d::UnitY()).toRotationMatrix();
  const double reach = 0.5 * std::sqrt(2.0);
  const Placed top = place(cube, Vector3d(0.0, 0.0, 2.0 * reach + 0.001), about_x);
  const Placed bottom = place(cube, Vector3d::Zero(), about_y);
  PolyhedronContact contact;
  ASSERT_TRUE(detect_polyhedron_polyhedron(top.view, bottom.view, 0.01, 0.5, 100, contact));
  ASSERT_EQ(contact.count, 1);
  EXPECT_TRUE(contact.normal.isApprox(Vector3d::UnitZ(), 1e-6));
  EXPECT_NEAR(contact.gaps[0], 0.001, 1e-6);
  EXPECT_TRUE(contact.points[0].isApprox(Vector3d(0.0, 0.0, reach + 0.0005), 1e-6));
}

// SPPRx on a unit half-size cube at the origin: the nearest surface point, its distance and the
// normal from the polyhedron to the sphere, for a centre in front of a face, of an edge and of a
// vertex, and inside (least deep face); nothing beyond the alert.
TEST(SpherePolyhedron, NearestSurfacePointGivesTheGapAndTheNormal) {
  const Polyhedron cube = test::box_polyhedron(Vector3d(0.5, 0.5, 0.5));
  std::vector<Vector3d> vertices = cube.vertices, normals = cube.face_normals;
  PlacedPolyhedron view{&cube, vertices, normals, Vector3d::Zero(), cube.radius};
  const double r = 0.1;
  ContactGeometry3D g;
  ASSERT_TRUE(detect_sphere_polyhedron(Vector3d(0.2, -0.1, 0.65), r, view, 0.1, g));
  EXPECT_NEAR(g.gap, 0.05, 1e-15);
  EXPECT_TRUE(g.normal.isApprox(Vector3d::UnitZ()));
  EXPECT_TRUE(g.point.isApprox(Vector3d(0.2, -0.1, 0.5)));
  EXPECT_NEAR(g.tangent.dot(g.normal), 0.0, 1e-15);
  EXPECT_TRUE(g.second_tangent.isApprox(g.tangent.cross(g.normal)));
  // In front of the edge x = z = 0.5: along the diagonal.
  ASSERT_TRUE(detect_sphere_polyhedron(Vector3d(0.6, 0.0, 0.6), r, view, 0.1, g));
  EXPECT_NEAR(g.gap, std::sqrt(0.02) - r, 1e-15);
  EXPECT_TRUE(g.normal.isApprox(Vector3d(1.0, 0.0, 1.0).normalized()));
  EXPECT_TRUE(g.point.isApprox(Vector3d(0.5, 0.0, 0.5)));
  // In front of the vertex (0.5, 0.5, 0.5).
  ASSERT_TRUE(detect_sphere_polyhedron(Vector3d(0.55, 0.55, 0.55), r, view, 0.1, g));
  EXPECT_NEAR(g.gap, std::sqrt(3.0) * 0.05 - r, 1e-15);
  EXPECT_TRUE(g.point.isApprox(Vector3d(0.5, 0.5, 0.5)));
  // Centre inside, 0.1 below the top face and deeper below the others: the top face.
  ASSERT_TRUE(detect_sphere_polyhedron(Vector3d(0.0, 0.1, 0.4), r, view, 0.1, g));
  EXPECT_NEAR(g.gap, -0.1 - r, 1e-15);
  EXPECT_TRUE(g.normal.isApprox(Vector3d::UnitZ()));
  EXPECT_FALSE(detect_sphere_polyhedron(Vector3d(0.0, 0.0, 0.75), r, view, 0.1, g));
}

}  // namespace
}  // namespace lmgc::solver
