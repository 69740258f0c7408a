// Rigid 2D scenes with closed-form answers. Each test states the formula, its source and the
// tolerance; the scenes are built in code (their DATBOX twins live in reference_cases/).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "tests/support/nlgs_options.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
constexpr double g = 9.81;

RunState2D run_state(const Scene2D& scene, double h, double theta = 0.5) {
  RunState2D s;
  s.h = h;
  s.theta = theta;
  s.visibility = build_visibility_index(scene);
  return s;
}

// Newton restitution e on a fixed wall: the n-th apex height is e^(2n) h0 (rigid-body impact
// theory). Tolerance 1% of h0: the impact happens within one step of 1e-4 s.
TEST(Rigid2DAnalytic, BounceHeightsFollowRestitutionSquared) {
  const double e = 0.8, h0 = 1.0, r = 0.1;
  SceneBuilder2D b;
  b.add_disk(0.0, h0 + r, r, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("rst08", RstClb{e, 0.0, 0.0});
  b.see("DISKx", "BLEUx", "rst08", "JONCx", "WALLx", 0.01);
  Scene2D scene = b.build();
  RunState2D state = run_state(scene, 1e-4);
  std::vector<double> apexes;
  double previous_vy = 0.0;
  for (int i = 0; i < 60000 && apexes.size() < 3; ++i) {
    step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
    const double vy = scene.bodies.velocity[0].y();
    if (previous_vy > 0.0 && vy <= 0.0)
      apexes.push_back(scene.bodies.reference[0].y() + scene.bodies.displacement[0].y() - r);
    previous_vy = vy;
  }
  ASSERT_EQ(apexes.size(), 3u);
  for (std::size_t n = 0; n < apexes.size(); ++n)
    EXPECT_NEAR(apexes[n], std::pow(e, 2.0 * static_cast<double>(n + 1)) * h0, 0.01 * h0)
        << "bounce " << n + 1;
}

// A square block on a plane inclined by α: it slides with a = g (sin α − μ cos α) when
// tan α > μ and stays at rest otherwise (Coulomb friction). Tolerance 1e-6 relative.
void block_on_slope(double alpha, double mu, double& acceleration, double& speed) {
  SceneBuilder2D b;
  const double half = 0.05;
  const std::vector<Vector2d> square = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  // Build horizontally, then tilt gravity: the slope frame is the world frame.
  b.add_polygon(0.0, half + 1e-9, square, 2000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 5.0, 0.05);
  b.add_law("iqsc0", IqsClb{mu});
  b.see("POLYG", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.01);
  b.set_gravity(Vector2d(g * std::sin(alpha), -g * std::cos(alpha)));
  Scene2D scene = b.build();
  RunState2D state = run_state(scene, 1e-3);
  for (int i = 0; i < 200; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double v1 = scene.bodies.velocity[0].x();
  for (int i = 0; i < 200; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double v2 = scene.bodies.velocity[0].x();
  acceleration = (v2 - v1) / (200 * 1e-3);
  speed = v2;
}

TEST(Rigid2DAnalytic, BlockSlidesWithCoulombAcceleration) {
  const double alpha = 30.0 * M_PI / 180.0, mu = 0.3;
  double a, v;
  block_on_slope(alpha, mu, a, v);
  const double expected = g * (std::sin(alpha) - mu * std::cos(alpha));
  EXPECT_NEAR(a, expected, 1e-6 * expected);
}

TEST(Rigid2DAnalytic, BlockSticksWhenTanAlphaBelowMu) {
  const double alpha = 20.0 * M_PI / 180.0, mu = 0.5;  // tan 20° = 0.364 < 0.5
  double a, v;
  block_on_slope(alpha, mu, a, v);
  EXPECT_NEAR(v, 0.0, 1e-9);
  EXPECT_NEAR(a, 0.0, 1e-7);
}

// A disk rolling without slip on a slope: a = (2/3) g sin α (solid disk, I = m r²/2).
// Tolerance 1e-6 relative.
TEST(Rigid2DAnalytic, DiskRollsWithTwoThirdsGSinAlpha) {
  const double alpha = 15.0 * M_PI / 180.0, mu = 0.8, r = 0.1;
  SceneBuilder2D b;
  b.add_disk(0.0, r + 1e-9, r, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 10.0, 0.05);
  b.add_law("iqsc0", IqsClb{mu});
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.01);
  b.set_gravity(Vector2d(g * std::sin(alpha), -g * std::cos(alpha)));
  Scene2D scene = b.build();
  RunState2D state = run_state(scene, 1e-3);
  for (int i = 0; i < 100; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double v1 = scene.bodies.velocity[0].x();
  for (int i = 0; i < 300; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double v2 = scene.bodies.velocity[0].x();
  const double a = (v2 - v1) / 0.3;
  EXPECT_NEAR(a, 2.0 / 3.0 * g * std::sin(alpha), 1e-6 * g);
  // Rolling without slip: v = -ω r.
  EXPECT_NEAR(scene.bodies.velocity[0].x(), -scene.bodies.velocity[0].z() * r, 1e-9);
}

// A column of 20 disks at rest on a wall: the reaction under disk k carries the weight of the
// disks above it (statics). Tolerance 1e-8 relative.
TEST(Rigid2DAnalytic, ColumnOfTwentyDisksCarriesTheWeightAbove) {
  const int n = 20;
  const double r = 0.05;
  SceneBuilder2D b;
  for (int k = 0; k < n; ++k) b.add_disk(0.0, r + 2.0 * r * k, r, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 0.001);
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.001);
  Scene2D scene = b.build();
  RunState2D state = run_state(scene, 1e-3);
  for (int i = 0; i < 20; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double weight = scene.bodies.mass[0] * g;
  ASSERT_EQ(state.contacts.size(), static_cast<std::size_t>(n));
  for (const Interaction2D& c : state.contacts) {
    // Disks above the contact: all disks whose index is >= the candidate's (the candidate is the
    // lower-index disk of a disk pair, or the disk on the wall).
    const int above = c.family == PairFamily2D::DKJCx ? n : n - c.antagonist_body;
    EXPECT_NEAR(c.r(1) / state.h, above * weight, 1e-8 * n * weight);
  }
}

// Head-on impact of two disks with restitution e: the relative velocity reverses times e and
// momentum is conserved (Newton's impact law). Tolerance 1e-10.
TEST(Rigid2DAnalytic, HeadOnCollisionConservesMomentumAndReversesTimesE) {
  const double e = 0.6, r = 0.1;
  SceneBuilder2D b;
  b.add_disk(0.0, 0.0, r, 1000.0);
  b.add_disk(2 * r + 1e-4, 0.0, r, 3000.0);
  b.add_law("rst06", RstClb{e, 0.0, 0.0});
  b.see("DISKx", "BLEUx", "rst06", "DISKx", "BLEUx", 0.01);
  b.set_gravity(Vector2d::Zero());
  b.set_velocity(0, Vector3d(2.0, 0.0, 0.0));
  b.set_velocity(1, Vector3d(-1.0, 0.0, 0.0));
  Scene2D scene = b.build();
  const double m1 = scene.bodies.mass[0], m2 = scene.bodies.mass[1];
  RunState2D state = run_state(scene, 1e-4);
  for (int i = 0; i < 10; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
  const double v1 = scene.bodies.velocity[0].x(), v2 = scene.bodies.velocity[1].x();
  EXPECT_NEAR(m1 * v1 + m2 * v2, m1 * 2.0 + m2 * -1.0, 1e-10 * m2);
  EXPECT_NEAR(v2 - v1, e * 3.0, 1e-10);
}

// A disk glued under a fixed JONCx by a sound IQS_MAC_CZM interface (β = 1 from the run's first
// preparation, LMGC90's init_CZM): the cohesive traction holds its weight, so after 0.2 s it has
// moved by less than 1e-4 m (free fall: 0.196 m) and β is still 1. The same disk created after the
// first step (the interface is then born broken, β = 0) falls.
TEST(Rigid2DAnalytic, SoundCohesiveInterfaceHoldsAHangingDiskFromTheFirstStepOnly) {
  const double r = 0.1, h = 1e-3;
  for (const bool from_start : {true, false}) {
    SCOPED_TRACE(from_start ? "interface present at the first step" : "interface created later");
    SceneBuilder2D b;
    b.add_disk(0.0, -r, r, 1000.0);
    b.add_fixed_joncx(0.0, 0.05, 0.0, 1.0, 0.05);
    b.add_law("mac01", IqsMacCzm{0.3, 0.3, 1e9, 1e9, 0.0, 1e6});
    b.see("DISKx", "BLEUx", "mac01", "JONCx", "WALLx", 0.01);
    Scene2D scene = b.build();
    RunState2D state = run_state(scene, h);
    if (!from_start) state.laws_initialized = true;  // as if an earlier step had had contacts
    for (int i = 0; i < 200; ++i) step_2d(scene, state, test::converged_nlgs_options(20, 1e-12));
    const double moved = std::abs(scene.bodies.displacement[0].y());
    if (from_start) {
      ASSERT_EQ(state.contacts.size(), 1u);
      ASSERT_EQ(state.law_states.size(), 1u);  // IQS_MAC_CZM's internals beside the interaction
      EXPECT_EQ(state.law_states.front().internal[3], 1.0);
      EXPECT_LT(moved, 1e-4);
    } else {
      EXPECT_GT(moved, 0.15);
    }
  }
}

// As in 3D (Rigid3DAnalytic.CohesiveZoneTornInOneStepReactsWithTheBetaItStores): two disks hanging
// in a chain under a JONCx, both interfaces sound IQS_MAC_CZM; the lower disk leaves at 1 m/s and
// tears its interface in the first step. β is re-evaluated at each convergence check (mod_nlgs
// updt_CZM(.false.)) and the sweeps after it use it, so at convergence the torn interface's
// reaction is the cohesive traction of the β the step stores: r_n = −L β² h cn δn_end.
TEST(Rigid2DAnalytic, CohesiveInterfaceTornInOneStepReactsWithTheBetaItStores) {
  const double r = 0.1, h = 1e-3, cn = 1e8;
  SceneBuilder2D b;
  b.add_disk(0.0, -r, r, 1000.0);
  const int lower = b.add_disk(0.0, -3.0 * r, r, 1000.0);
  b.add_fixed_joncx(0.0, 0.05, 0.0, 1.0, 0.05);
  b.add_law("mac01", IqsMacCzm{0.3, 0.3, cn, cn, 0.0, 1.0});  // w = 1 J/m² (contact length 1)
  b.see("DISKx", "BLEUx", "mac01", "JONCx", "WALLx", 0.01);
  b.see("DISKx", "BLEUx", "mac01", "DISKx", "BLEUx", 0.01);
  b.set_velocity(lower, Eigen::Vector3d(0.0, -1.0, 0.0));
  Scene2D scene = b.build();
  RunState2D state = run_state(scene, h);
  NlgsOptions options = test::converged_nlgs_options(20, 1e-12);
  options.gs_it1 = 1;  // a check after every sweep
  options.residual_target = 0.0;
  const NlgsResult result = step_2d(scene, state, options);
  EXPECT_TRUE(result.converged);
  EXPECT_GT(result.iterations, 2);
  ASSERT_EQ(state.contacts.size(), 2u);
  ASSERT_EQ(state.law_states.size(), 2u);
  int torn = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    const Interaction2D& c = state.contacts[k];
    const std::array<double, 6>& internal = state.law_states[k].internal;
    const double beta = internal[3], opening = internal[2];
    if (beta == 1.0) continue;
    ++torn;
    EXPECT_GT(opening, 0.0);
    EXPECT_NEAR(c.r(1), -internal[0] * beta * beta * h * cn * opening, 1e-3 * std::abs(c.r(1)));
  }
  EXPECT_GE(torn, 1);
}

}  // namespace
}  // namespace lmgc::solver
