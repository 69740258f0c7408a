// Properties of 2D detection on random scenes: the list comes out in sweep order, disk pairs are
// found exactly when their gap is within the alert distance, and each interaction carries the
// relative velocity of its bodies at the start of the step.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

#include "solver/detection/detection_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using test::in_range;

constexpr double kAlert = 0.002;

struct RandomScene {
  Scene2D scene;
  std::vector<Vector3d> coordinates;               // per body: x, y, θ
  std::vector<std::pair<Vector2d, double>> disks;  // centre and radius of each disk contactor, by body
};

// Disks and squares at random places (bodies numbered in no spatial order), a floor and a wall.
RandomScene random_scene() {
  SceneBuilder2D b;
  RandomScene s;
  const int disks = *rc::gen::inRange(2, 60);
  const int squares = *rc::gen::inRange(0, 8);
  for (int k = 0; k < disks; ++k) {
    const Vector2d centre(in_range(0.0, 0.1), in_range(0.0, 0.1));
    const double radius = in_range(0.004, 0.01);
    const int body = b.add_disk(centre.x(), centre.y(), radius, 1000.0);
    b.set_velocity(body, Vector3d(in_range(-1.0, 1.0), in_range(-1.0, 1.0), in_range(-10.0, 10.0)));
    s.disks.emplace_back(centre, radius);
    s.coordinates.emplace_back(centre.x(), centre.y(), 0.0);
  }
  for (int k = 0; k < squares; ++k) {
    const Vector2d centre(in_range(0.0, 0.1), in_range(0.0, 0.1));
    const double half = in_range(0.003, 0.008), angle = in_range(0.0, 1.5);
    std::vector<Vector2d> vertices;
    for (int v = 0; v < 4; ++v) {
      const double a = angle + v * M_PI / 2;
      vertices.emplace_back(half * std::sqrt(2.0) * std::cos(a + M_PI / 4),
                            half * std::sqrt(2.0) * std::sin(a + M_PI / 4));
    }
    const int body = b.add_polygon(centre.x(), centre.y(), vertices, 1000.0);
    b.set_velocity(body, Vector3d(in_range(-1.0, 1.0), in_range(-1.0, 1.0), in_range(-10.0, 10.0)));
    s.coordinates.emplace_back(centre.x(), centre.y(), 0.0);
  }
  b.add_fixed_joncx(0.05, -0.005, 0.0, 0.06, 0.005);
  s.coordinates.emplace_back(0.05, -0.005, 0.0);
  b.add_fixed_joncx(-0.005, 0.05, M_PI / 2, 0.06, 0.005);
  s.coordinates.emplace_back(-0.005, 0.05, M_PI / 2);
  b.add_law("iqsc0", IqsClb{0.3});
  for (const char* antagonist : {"DISKx", "POLYG"}) {
    b.see("DISKx", "BLEUx", "iqsc0", antagonist, "BLEUx", kAlert);
    b.see("POLYG", "BLEUx", "iqsc0", antagonist, "BLEUx", kAlert);
  }
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", kAlert);
  b.see("POLYG", "BLEUx", "iqsc0", "JONCx", "WALLx", kAlert);
  s.scene = b.build();
  return s;
}

auto sweep_key(const Interaction2D& c) {
  return std::make_tuple(c.family, c.candidate, c.antagonist, c.candidate_vertex);
}

RC_GTEST_PROP(Detection2D, ListIsInSweepOrderAndFindsEveryDiskPairWithinTheAlertDistance, ()) {
  RandomScene s = random_scene();
  const VisibilityIndex2D index = build_visibility_index(s.scene);
  LargeArray<Interaction2D> found;
  detect_contacts_2d(s.scene, index, s.coordinates, found);
  for (std::size_t k = 1; k < found.size(); ++k) RC_ASSERT(!(sweep_key(found[k]) < sweep_key(found[k - 1])));

  std::set<std::pair<int, int>> detected, expected;
  for (const Interaction2D& c : found)
    if (c.family == PairFamily2D::DKDKx)
      detected.insert(
          {std::min(c.candidate_body, c.antagonist_body), std::max(c.candidate_body, c.antagonist_body)});
  for (std::size_t i = 0; i < s.disks.size(); ++i)
    for (std::size_t j = i + 1; j < s.disks.size(); ++j) {
      const double gap = (s.disks[i].first - s.disks[j].first).norm() - s.disks[i].second - s.disks[j].second;
      // Pairs within round-off of the alert distance may go either way; disks on the same centre
      // have no normal.
      const double distance = (s.disks[i].first - s.disks[j].first).norm();
      if (std::fabs(gap - kAlert) < 1e-12 || distance < 1e-9) {
        detected.erase({int(i), int(j)});
        continue;
      }
      if (gap <= kAlert) expected.insert({int(i), int(j)});
    }
  RC_ASSERT(detected == expected);
}

RC_GTEST_PROP(Detection2D, PeriodicListIsInSweepOrderAndFindsDiskPairsAcrossTheSides, ()) {
  // Disks in [0, P) x [0, P) with P far above their reach, so that a pair meets either directly or
  // across the side x = 0 = P, not both.
  constexpr double period = 0.1;
  SceneBuilder2D b;
  std::vector<std::pair<Vector2d, double>> disks;
  std::vector<Vector3d> coordinates;
  const int count = *rc::gen::inRange(2, 60);
  for (int k = 0; k < count; ++k) {
    const Vector2d centre(in_range(0.0, period * (1.0 - 1e-9)), in_range(0.0, period));
    const double radius = in_range(0.004, 0.01);
    b.add_disk(centre.x(), centre.y(), radius, 1000.0);
    disks.emplace_back(centre, radius);
    coordinates.emplace_back(centre.x(), centre.y(), 0.0);
  }
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", kAlert);
  Scene2D scene = b.build();
  scene.x_period = period;
  const VisibilityIndex2D index = build_visibility_index(scene);
  LargeArray<Interaction2D> found;
  detect_contacts_2d(scene, index, coordinates, found);
  for (std::size_t k = 1; k < found.size(); ++k) RC_ASSERT(!(sweep_key(found[k]) < sweep_key(found[k - 1])));

  std::multiset<std::pair<int, int>> detected, expected;
  std::set<std::pair<int, int>> undecided;
  for (const Interaction2D& c : found)
    detected.insert(
        {std::min(c.candidate_body, c.antagonist_body), std::max(c.candidate_body, c.antagonist_body)});
  for (std::size_t i = 0; i < disks.size(); ++i)
    for (std::size_t j = i + 1; j < disks.size(); ++j)
      for (const double shift : {0.0, period, -period}) {
        const Vector2d d = disks[j].first + Vector2d(shift, 0.0) - disks[i].first;
        const double gap = d.norm() - disks[i].second - disks[j].second;
        if (std::fabs(gap - kAlert) < 1e-12 || d.norm() < 1e-9)
          undecided.insert({int(i), int(j)});
        else if (gap <= kAlert)
          expected.insert({int(i), int(j)});
      }
  for (const auto& pair : undecided) {
    detected.erase(pair);
    expected.erase(pair);
  }
  RC_ASSERT(detected == expected);
}

// (PLJCx: the bodies of the case's first POLYG and first JONCx, as LMGC90's detection has them.)
RC_GTEST_PROP(Detection2D, EachInteractionCarriesTheRelativeVelocityOfItsBodiesAtTheStartOfTheStep, ()) {
  RandomScene s = random_scene();
  const VisibilityIndex2D index = build_visibility_index(s.scene);
  LargeArray<Interaction2D> found;
  detect_contacts_2d(s.scene, index, s.coordinates, found);
  const std::vector<Vector3d>& v = s.scene.bodies.velocity_begin;
  std::int32_t first_polygon_body = -1, first_joncx_body = -1;
  for (std::size_t k = 0; k < index.contactor_shape.size(); ++k) {
    if (first_polygon_body < 0 && index.contactor_shape[k] == ContactorShape2D::polygon)
      first_polygon_body = index.contactor_body[k];
    if (first_joncx_body < 0 && index.contactor_shape[k] == ContactorShape2D::joncx)
      first_joncx_body = index.contactor_body[k];
  }
  for (const Interaction2D& c : found) {
    const bool pljcx = c.family == PairFamily2D::PLJCx;
    const Vector3d& a = v[static_cast<std::size_t>(pljcx ? first_polygon_body : c.candidate_body)];
    const Vector3d& b = v[static_cast<std::size_t>(pljcx ? first_joncx_body : c.antagonist_body)];
    const Vector2d relative = a.head<2>() - b.head<2>();
    const double ut =
        c.tangent().dot(relative) + c.lever_candidate(0) * a.z() - c.lever_antagonist(0) * b.z();
    const double un = c.normal.dot(relative) + c.lever_candidate(1) * a.z() - c.lever_antagonist(1) * b.z();
    const double scale = 1.0 + a.norm() + b.norm();
    RC_ASSERT(std::fabs(c.velocity_begin(0) - ut) <= 1e-12 * scale);
    RC_ASSERT(std::fabs(c.velocity_begin(1) - un) <= 1e-12 * scale);
  }
}

}  // namespace
}  // namespace lmgc::solver
