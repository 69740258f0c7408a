// Rigid 2D end to end on tiny scenes whose answer is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::solver {
namespace {

NlgsOptions tight() {
  NlgsOptions o;
  o.norm = NlgsNorm::quad;
  o.tolerance = 1e-8;
  o.gs_it1 = 20;
  o.gs_it2 = 200;
  return o;
}

TEST(Rigid2D, FreeFallFollowsGravityExactly) {
  SceneBuilder2D b;
  b.add_disk(0.0, 1.0, 0.1, 1000.0);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.theta = 0.5;
  state.visibility = build_visibility_index(scene);
  for (int i = 0; i < 100; ++i) step_2d(scene, state, tight());
  const double t = 0.1;
  EXPECT_NEAR(scene.bodies.velocity[0].y(), -9.81 * t, 1e-12);
  // θ = ½ integrates constant acceleration exactly.
  EXPECT_NEAR(scene.bodies.displacement[0].y(), -0.5 * 9.81 * t * t, 1e-12);
}

TEST(Rigid2D, DiskRestingOnWallCarriesItsWeightAndDoesNotSink) {
  SceneBuilder2D b;
  const int disk = b.add_disk(0.0, 0.1, 0.1, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{0.5});
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.01);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  NlgsResult last;
  for (int i = 0; i < 50; ++i) last = step_2d(scene, state, tight());
  ASSERT_EQ(state.contacts.size(), 1u);
  const double weight = scene.bodies.mass[static_cast<std::size_t>(disk)] * 9.81;
  EXPECT_NEAR(state.contacts[0].r(1) / state.h, weight, 1e-9 * weight);
  EXPECT_NEAR(state.contacts[0].r(0), 0.0, 1e-12);
  EXPECT_NEAR(scene.bodies.velocity[0].y(), 0.0, 1e-12);
  EXPECT_LT(last.residual_relative, 1e-10);
  EXPECT_TRUE(last.converged);
}

// Newton restitution at a single impact: the rebound velocity is -e times the approach velocity.
TEST(Rigid2D, RestitutionReversesTheNormalVelocityTimesE) {
  SceneBuilder2D b;
  const int disk = b.add_disk(0.0, 0.1 + 1e-4, 0.1, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("rst08", RstClb{0.8, 0.0, 0.0});
  b.see("DISKx", "BLEUx", "rst08", "JONCx", "WALLx", 0.01);
  b.set_gravity(Eigen::Vector2d::Zero());
  b.set_velocity(disk, Eigen::Vector3d(0.0, -1.0, 0.0));
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  for (int i = 0; i < 5; ++i) step_2d(scene, state, tight());
  EXPECT_NEAR(scene.bodies.velocity[0].y(), 0.8, 1e-12);
}

// A contact without reaction whose free velocity opens it is passed by in the sweeps only when its
// law is plain Signorini–Coulomb: a sound cohesive zone (IQS_MAC_CZM, β = 1 from the first step)
// holds a disk hanging under a wall although gravity pulls it away and it starts without reaction.
TEST(Rigid2D, AnOpeningCohesiveContactIsSolvedNotPassedByAndHoldsItsDisk) {
  SceneBuilder2D b;
  b.add_disk(0.0, -0.1, 0.1, 1000.0);
  b.add_fixed_joncx(0.0, 0.05, 0.0, 1.0, 0.05);
  b.add_law("mac01", IqsMacCzm{0.3, 0.3, 1e9, 1e9, 0.0, 1e6});
  b.see("DISKx", "BLEUx", "mac01", "JONCx", "WALLx", 0.01);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  for (int i = 0; i < 50; ++i) {
    const NlgsResult step = step_2d(scene, state, tight());
    ASSERT_TRUE(step.converged) << "step " << i;
  }
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_LT(state.contacts[0].r(1), 0.0);  // a tensile reaction
  // Free fall would have taken it 1.2 cm down in 50 ms; the zone's stiffness lets it sag 0.3 µm.
  EXPECT_LT(std::abs(scene.bodies.displacement[0].y()), 1e-5);
}

}  // namespace
}  // namespace lmgc::solver
