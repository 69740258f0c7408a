// Numerical stability on hard 2D cases: a tall column, large mass ratios, long bouncing runs.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;

NlgsOptions options(double tolerance) {
  NlgsOptions o;
  o.tolerance = tolerance;
  o.gs_it1 = 50;
  o.gs_it2 = 400;
  return o;
}

// 50 disks stacked: after settling the column neither sinks nor drifts and the bottom contact
// carries the whole weight within 0.1%.
TEST(Rigid2DStability, FiftyDiskColumnStaysStraightAndCarriesItsWeight) {
  const int n = 50;
  const double r = 0.05;
  SceneBuilder2D b;
  for (int k = 0; k < n; ++k) b.add_disk(0.0, r + 2.0 * r * k, r, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 0.001);
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.001);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  NlgsResult last;
  for (int i = 0; i < 200; ++i) last = step_2d(scene, state, options(1e-6));
  double max_drift = 0.0, max_sink = 0.0;
  for (int k = 0; k < n; ++k) {
    max_drift = std::max(max_drift, std::fabs(scene.bodies.displacement[static_cast<std::size_t>(k)].x()));
    max_sink = std::max(max_sink, -scene.bodies.displacement[static_cast<std::size_t>(k)].y());
  }
  EXPECT_LT(max_drift, 1e-9);
  EXPECT_LT(max_sink, 1e-6);
  double bottom = 0.0;
  for (const Interaction2D& c : state.contacts)
    if (c.family == PairFamily2D::DKJCx) bottom = c.r(1) / state.h;
  const double weight = n * scene.bodies.mass[0] * 9.81;
  EXPECT_NEAR(bottom, weight, 1e-3 * weight);
  EXPECT_LT(last.residual_relative, 1e-3);
}

// A light disk under a heavy one (mass ratio 1e4) on a wall: the light disk carries the heavy
// one's weight without being crushed through.
TEST(Rigid2DStability, MassRatioTenThousandIsCarried) {
  const double r = 0.05;
  SceneBuilder2D b;
  b.add_disk(0.0, r, r, 1.0);
  b.add_disk(0.0, 3 * r, r, 1e4);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 0.001);
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.001);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  NlgsResult last;
  for (int i = 0; i < 500; ++i) last = step_2d(scene, state, options(1e-8));
  EXPECT_GT(scene.bodies.reference[0].y() + scene.bodies.displacement[0].y(), r - 1e-6);
  // Gauss–Seidel converges slowly at this mass ratio: the residual velocity of the heavy disk
  // stays below 1e-4 of the velocity gravity adds in one step, and the error is reported.
  EXPECT_LT(std::fabs(scene.bodies.velocity[1].y()), 1e-4 * 9.81 * state.h);
  EXPECT_LT(last.residual_relative, 1e-3);
}

// Perfectly elastic bounces (e = 1) repeated for 20 s: the energy never grows beyond the
// initial one (1e-9 relative), the discrete scheme only loses energy at impacts.
TEST(Rigid2DStability, LongBouncingRunCreatesNoEnergy) {
  const double r = 0.1;
  SceneBuilder2D b;
  b.add_disk(0.0, 1.0 + r, r, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("rst10", RstClb{1.0, 0.0, 0.0});
  b.see("DISKx", "BLEUx", "rst10", "JONCx", "WALLx", 0.01);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 5e-4;
  state.visibility = build_visibility_index(scene);
  auto energy = [&] {
    const double y = scene.bodies.reference[0].y() + scene.bodies.displacement[0].y();
    return kinetic_energy(scene.bodies) + scene.bodies.mass[0] * 9.81 * y;
  };
  scene.bodies.velocity = scene.bodies.velocity_begin;
  const double initial = energy();
  double worst = 0.0;
  for (int i = 0; i < 40000; ++i) {
    step_2d(scene, state, options(1e-8));
    worst = std::max(worst, energy() - initial);
  }
  EXPECT_LE(worst, 1e-9 * initial);
}

}  // namespace
}  // namespace lmgc::solver
