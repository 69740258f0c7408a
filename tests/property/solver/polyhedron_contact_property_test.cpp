// Properties of the PRPRx common-plane detection on boxes stacked with parallel faces, turned as a
// whole by a random rotation: every point's gap is the distance between the faces, the normal is
// the stacking direction, and the points lie inside both faces.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "solver/bodies/polyhedron.hpp"
#include "solver/detection/polyhedron_contact.hpp"
#include "tests/support/generators.hpp"
#include "tests/support/polyhedra.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

using test::in_range;

RC_GTEST_PROP(PolyhedronContactProperty, StackedBoxesGapEqualsFaceDistanceAtEveryPointInAnyOrientation, ()) {
  const Vector3d lower_half(in_range(0.2, 1.0), in_range(0.2, 1.0), in_range(0.1, 1.0));
  const Vector3d upper_half(in_range(0.05, 0.9) * lower_half.x(), in_range(0.05, 0.9) * lower_half.y(),
                            in_range(0.1, 1.0));
  // The upper box's footprint inside the lower box's top face; a gap in [-1 mm, 5 mm].
  const double dx = in_range(-1.0, 1.0) * (lower_half.x() - upper_half.x());
  const double dy = in_range(-1.0, 1.0) * (lower_half.y() - upper_half.y());
  const double gap = in_range(-0.001, 0.005);
  Eigen::Quaterniond q(in_range(-1.0, 1.0), in_range(-1.0, 1.0), in_range(-1.0, 1.0), in_range(-1.0, 1.0));
  RC_PRE(q.norm() > 1e-2);
  const Matrix3d turn = q.normalized().toRotationMatrix();
  const Vector3d origin(in_range(-5.0, 5.0), in_range(-5.0, 5.0), in_range(-5.0, 5.0));
  const Polyhedron lower = test::box_polyhedron(lower_half), upper = test::box_polyhedron(upper_half);
  const Vector3d upper_centre(dx, dy, lower_half.z() + upper_half.z() + gap);

  std::vector<Vector3d> lv, ln, uv, un;
  for (const Vector3d& v : lower.vertices) lv.push_back(origin + turn * v);
  for (const Vector3d& n : lower.face_normals) ln.push_back(turn * n);
  for (const Vector3d& v : upper.vertices) uv.push_back(origin + turn * (upper_centre + v));
  for (const Vector3d& n : upper.face_normals) un.push_back(turn * n);
  const PlacedPolyhedron an{&lower, lv, ln, origin, lower.radius};
  const PlacedPolyhedron cd{&upper, uv, un, origin + turn * upper_centre, upper.radius};

  PolyhedronContact contact;
  RC_ASSERT(detect_polyhedron_polyhedron(cd, an, 0.01, 0.05, 100, contact));
  const Vector3d up = turn * Vector3d::UnitZ();
  RC_ASSERT(contact.normal.dot(up) > 1.0 - 1e-9);
  RC_ASSERT(contact.count == 4);
  for (int k = 0; k < contact.count; ++k) {
    RC_ASSERT(std::abs(contact.gaps[static_cast<std::size_t>(k)] - gap) < 1e-9);
    // Inside the upper face's footprint (local frame of the lower box).
    const Vector3d local = turn.transpose() * (contact.points[static_cast<std::size_t>(k)] - origin);
    RC_ASSERT(std::abs(local.x() - dx) <= upper_half.x() + 1e-9);
    RC_ASSERT(std::abs(local.y() - dy) <= upper_half.y() + 1e-9);
  }
}

}  // namespace
}  // namespace lmgc::solver
