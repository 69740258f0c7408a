// Properties of 2D detection on random scenes: the list comes out in LMGC90's order (its families'
// order, and in a family the order its box grid enumerates the pairs), disk pairs are found exactly
// when their gap is within the alert distance, and each interaction carries the relative velocity
// of its bodies at the start of the step.
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

// LMGC90's DKDKx enumeration written out as its loops (docs/lmgc90-facts/rigid-2d.md §3.2,
// mod_DKDKx creation_tab_visu), for disks 0..n-1 (contactor index = disk index): boxes of side
// Lbox = 1.01 (2 max radius + alert) from the lowest centres, i1 outer, i2 inner, candidates by
// index, the 3 x 3 neighbouring boxes i1an outer, antagonists of larger index. With a period, the
// grid starts at x = 0 and, after the grid pairs, the disks of the last two columns meet those of
// the first two, moved by a period, as (lower index, higher index).
std::vector<std::pair<int, int>> lmgc90_disk_pairs(const std::vector<std::pair<Vector2d, double>>& disks,
                                                   double period, bool periodic_part) {
  double ray = 0.0, left = 1e300, down = 1e300, right = -1e300, up = -1e300;
  for (const auto& [c, r] : disks) {
    ray = std::max(ray, r);
    left = std::min(left, c.x());
    down = std::min(down, c.y());
    right = std::max(right, c.x());
    up = std::max(up, c.y());
  }
  if (period > 0.0) left = 0.0, right = period;
  const double inverse = 1.0 / (1.01 * (2.0 * ray + kAlert));
  const auto box = [&](const Vector2d& c) {
    return std::pair<long, long>{1 + static_cast<long>((c.x() - left) * inverse),
                                 1 + static_cast<long>((c.y() - down) * inverse)};
  };
  const long columns = 1 + static_cast<long>((right - left) * inverse),
             rows = 1 + static_cast<long>((up - down) * inverse);
  std::vector<std::pair<int, int>> out;
  const int n = static_cast<int>(disks.size());
  if (!periodic_part) {
    for (long i1 = 1; i1 <= columns; ++i1)
      for (long i2 = 1; i2 <= rows; ++i2)
        for (int cd = 0; cd < n; ++cd) {
          if (box(disks[static_cast<std::size_t>(cd)].first) != std::pair{i1, i2}) continue;
          for (long a1 = i1 - 1; a1 <= i1 + 1; ++a1)
            for (long a2 = i2 - 1; a2 <= i2 + 1; ++a2)
              for (int an = cd + 1; an < n; ++an)
                if (box(disks[static_cast<std::size_t>(an)].first) == std::pair{a1, a2})
                  out.emplace_back(cd, an);
        }
    return out;
  }
  for (long i1 = std::max(1L, columns - 1); i1 <= columns; ++i1)
    for (long i2 = 1; i2 <= rows; ++i2)
      for (int cd = 0; cd < n; ++cd) {
        if (box(disks[static_cast<std::size_t>(cd)].first) != std::pair{i1, i2}) continue;
        for (long a1 = 1; a1 <= 2; ++a1)
          for (long a2 = i2 - 1; a2 <= i2 + 1; ++a2)
            for (int an = 0; an < n; ++an)
              if (an != cd && box(disks[static_cast<std::size_t>(an)].first) == std::pair{a1, a2})
                out.emplace_back(std::min(cd, an), std::max(cd, an));
      }
  return out;
}

// `found`'s DKDKx pairs (those of `periodic` images or not) are `reference`'s, in its order, where
// the reference is kept to the pairs found.
bool in_lmgc90_order(const LargeArray<Interaction2D>& found,
                     const std::vector<std::pair<int, int>>& reference, bool periodic) {
  std::vector<std::pair<int, int>> got;
  std::set<std::pair<int, int>> pairs;
  for (const Interaction2D& c : found)
    if (c.family == PairFamily2D::DKDKx && (c.periodic_shift != 0) == periodic) {
      got.emplace_back(c.candidate, c.antagonist);
      pairs.insert(got.back());
    }
  std::vector<std::pair<int, int>> expected;
  for (const auto& p : reference)
    if (pairs.count(p) && std::find(expected.begin(), expected.end(), p) == expected.end())
      expected.push_back(p);
  return got == expected;
}

bool families_in_order(const LargeArray<Interaction2D>& found) {
  for (std::size_t k = 1; k < found.size(); ++k)
    if (found[k].family < found[k - 1].family) return false;
  return true;
}

RC_GTEST_PROP(Detection2D, ListIsInLmgc90sBoxOrderAndFindsEveryDiskPairWithinTheAlertDistance, ()) {
  RandomScene s = random_scene();
  const VisibilityIndex2D index = build_visibility_index(s.scene);
  LargeArray<Interaction2D> found;
  detect_contacts_2d(s.scene, index, s.coordinates, found);
  RC_ASSERT(families_in_order(found));
  RC_ASSERT(in_lmgc90_order(found, lmgc90_disk_pairs(s.disks, 0.0, false), false));

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

RC_GTEST_PROP(Detection2D, PeriodicListIsInLmgc90sBoxOrderAndFindsDiskPairsAcrossTheSides, ()) {
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
  // The grid's pairs first, then those across the sides, each in LMGC90's order.
  bool across = false;
  for (const Interaction2D& c : found) {
    RC_ASSERT(!(across && c.periodic_shift == 0));
    across |= c.periodic_shift != 0;
  }
  RC_ASSERT(in_lmgc90_order(found, lmgc90_disk_pairs(disks, period, false), false));
  RC_ASSERT(in_lmgc90_order(found, lmgc90_disk_pairs(disks, period, true), true));

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
