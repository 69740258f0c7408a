// Rigid 3D scenes with closed-form answers, run through the step pipeline (step_3d). Each test
// states the formula, its source and the tolerance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "solver/bodies/rigid_3d_properties.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"
#include "tests/support/nlgs_options.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double g = 9.81;

RunState3D run_state(double h, double theta = 0.5) {
  RunState3D s;
  s.h = h;
  s.theta = theta;
  return s;
}

Vector3d centre_of(const Scene3D& scene, int body) {
  const auto b = static_cast<std::size_t>(body);
  return scene.bodies.reference[b] + scene.bodies.displacement[b].head<3>();
}

// A horizontal ground: PLANx 2 m × 2 m, 0.1 m thick, top face at z = 0.
int add_ground(SceneBuilder3D& b, const Matrix3d& frame = Matrix3d::Identity()) {
  return b.add_fixed_plane(-0.05 * frame.col(2), frame, Vector3d(1.0, 1.0, 0.05));
}

// Newton restitution e against a fixed plane: the n-th apex height is e^(2n) h0 (rigid-body impact
// theory). Tolerance 1% of h0: the impact is resolved within one step of 1e-4 s.
TEST(Rigid3DAnalytic, SphereBounceHeightsFollowRestitutionSquared) {
  const double e = 0.8, h0 = 1.0, r = 0.1;
  SceneBuilder3D b;
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, h0 + r), r, 1000.0);
  add_ground(b);
  b.add_law("rst08", RstClb{e, 0.0, 0.0});
  b.see("SPHER", "BLEUx", "rst08", "PLANx", "VERTx", 0.01);
  Scene3D scene = b.build();
  RunState3D state = run_state(1e-4);
  std::vector<double> apexes;
  double previous_vz = 0.0;
  for (int i = 0; i < 60000 && apexes.size() < 3; ++i) {
    const NlgsResult result = step_3d(scene, state, test::converged_nlgs_options(10));
    ASSERT_FALSE(result.diverged);
    const double vz = scene.bodies.velocity[static_cast<std::size_t>(ball)](2);
    if (previous_vz > 0.0 && vz <= 0.0) apexes.push_back(centre_of(scene, ball).z() - r);
    previous_vz = vz;
  }
  ASSERT_EQ(apexes.size(), 3u);
  for (std::size_t n = 0; n < apexes.size(); ++n)
    EXPECT_NEAR(apexes[n], std::pow(e, 2.0 * static_cast<double>(n + 1)) * h0, 0.01 * h0)
        << "bounce " << n + 1;
}

// A sphere on a slope of angle α with enough friction (μ ≥ 2/7 tan α; here μ = 1) rolls without
// slipping: a = 5/7 g sin α (solid sphere, I = 2/5 m r²). Measured after 0.5 s from rest; tolerance
// 0.5 % (the θ-scheme is exact for constant acceleration up to the contact's O(h) start).
TEST(Rigid3DAnalytic, SphereRollsDownASlopeWithFiveSeventhsGSinAlpha) {
  const double alpha = 20.0 * std::numbers::pi / 180.0, r = 0.05;
  // Slope: rotate the ground about the global y axis by -α so that "down the slope" is +x.
  Matrix3d slope;
  slope << std::cos(alpha), 0.0, std::sin(alpha), 0.0, 1.0, 0.0, -std::sin(alpha), 0.0, std::cos(alpha);
  SceneBuilder3D b;
  const Vector3d normal = slope.col(2);
  const int ball = b.add_sphere(r * normal, r, 2000.0);
  add_ground(b, slope);
  b.add_law("iqs10", IqsClb{1.0});
  b.see("SPHER", "BLEUx", "iqs10", "PLANx", "VERTx", 0.01);
  Scene3D scene = b.build();
  RunState3D state = run_state(1e-3);
  const int steps = 500;
  for (int i = 0; i < steps; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  const Vector3d v = scene.bodies.velocity[static_cast<std::size_t>(ball)].head<3>();
  const Vector3d down = slope.col(0);
  const double expected = 5.0 / 7.0 * g * std::sin(alpha) * steps * 1e-3;
  EXPECT_NEAR(v.dot(down), expected, 5e-3 * expected);
  EXPECT_NEAR(v.dot(normal), 0.0, 1e-6);
  // Rolling without slip: the contact point is at rest, |ω| r = |v|.
  const Vector3d omega = scene.bodies.frame[static_cast<std::size_t>(ball)] *
                         scene.bodies.velocity[static_cast<std::size_t>(ball)].tail<3>();
  EXPECT_NEAR(omega.norm() * r, v.norm(), 1e-6 * v.norm());
}

// Low friction: the sphere slides, a = g (sin α − μ cos α) along the slope (Coulomb).
TEST(Rigid3DAnalytic, SphereSlidesDownASlopeWithCoulombAcceleration) {
  const double alpha = 30.0 * std::numbers::pi / 180.0, r = 0.05, mu = 0.05;
  Matrix3d slope;
  slope << std::cos(alpha), 0.0, std::sin(alpha), 0.0, 1.0, 0.0, -std::sin(alpha), 0.0, std::cos(alpha);
  SceneBuilder3D b;
  const int ball = b.add_sphere(r * slope.col(2), r, 2000.0);
  add_ground(b, slope);
  b.add_law("iqs05", IqsClb{mu});
  b.see("SPHER", "BLEUx", "iqs05", "PLANx", "VERTx", 0.01);
  Scene3D scene = b.build();
  RunState3D state = run_state(1e-3);
  for (int i = 0; i < 300; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  // Still sliding at 0.3 s: friction spins the sphere up at 5/2 μ g cos α / r, too slowly to roll yet.
  const double expected = g * (std::sin(alpha) - mu * std::cos(alpha)) * 0.3;
  EXPECT_NEAR(scene.bodies.velocity[static_cast<std::size_t>(ball)].head<3>().dot(slope.col(0)), expected,
              5e-3 * expected);
}

// A column of 10 equal spheres on the ground at rest: the impulse through contact k (counted from the
// top) is k m g h over a step (statics). Tolerance 1e-6 relative after 200 steps.
TEST(Rigid3DAnalytic, ColumnOfTenSpheresCarriesTheWeightAboveWithEitherLocalSolve) {
  // The exact 3×3 local solve and LMGC90's diagonal resolution reach the same static answer.
  for (const bool diagonal : {false, true}) {
    SCOPED_TRACE(diagonal ? "diagonal resolution" : "exact local solve");
    const double r = 0.05, density = 1000.0, h = 1e-3;
    SceneBuilder3D b;
    std::vector<int> balls;
    for (int k = 0; k < 10; ++k)
      balls.push_back(b.add_sphere(Vector3d(0.0, 0.0, r + 2.0 * r * k), r, density));
    add_ground(b);
    b.add_law("iqs05", IqsClb{0.5});
    b.see("SPHER", "BLEUx", "iqs05", "PLANx", "VERTx", 0.001);
    b.see("SPHER", "BLEUx", "iqs05", "SPHER", "BLEUx", 0.001);
    Scene3D scene = b.build();
    RunState3D state = run_state(h);
    NlgsOptions options = test::converged_nlgs_options(10);
    options.diagonal_resolution = diagonal;
    for (int i = 0; i < 200; ++i) step_3d(scene, state, options);
    const double mass = scene.bodies.mass[0];
    ASSERT_EQ(state.contacts.size(), 10u);
    EXPECT_TRUE(state.law_states.empty());  // IQS_CLB keeps no law state beside the interactions
    for (const Interaction3D& c : state.contacts) {
      // Spheres above the contact: all of them for the ground, else those above the lower sphere.
      const int lower_body =
          c.family == PairFamily3D::SPPLx ? -1 : std::min(c.candidate_body, c.antagonist_body);
      const int above = 10 - (lower_body + 1);
      EXPECT_NEAR(c.r(1), above * mass * g * h, 1e-6 * above * mass * g * h)
          << "contact between bodies " << c.candidate_body << " and " << c.antagonist_body;
      EXPECT_NEAR(std::hypot(c.r(0), c.r(2)), 0.0, 1e-9);
    }
    EXPECT_NEAR(centre_of(scene, balls.back()).z(), r + 18.0 * r, 1e-6);
  }
}

// A flat cluster of three spheres dropped level onto the ground lands on all three at once and
// does not start to turn; at rest each contact carries a third of the weight.
TEST(Rigid3DAnalytic, FlatSphereClusterFallsFlatAndSharesItsWeight) {
  const double r = 0.01, h = 1e-3;
  const std::vector<Vector3d> offsets{Vector3d(0.02, 0.0, 0.0), Vector3d(-0.01, 0.01 * std::sqrt(3.0), 0.0),
                                      Vector3d(-0.01, -0.01 * std::sqrt(3.0), 0.0)};
  SceneBuilder3D b;
  const int cluster = b.add_sphere_cluster(Vector3d(0.0, 0.0, r + 0.05), offsets, r, 1000.0);
  add_ground(b);
  b.add_law("iqs05", IqsClb{0.5});
  b.see("SPHER", "BLEUx", "iqs05", "PLANx", "VERTx", 0.001);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  for (int i = 0; i < 400; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  const auto c = static_cast<std::size_t>(cluster);
  EXPECT_NEAR(centre_of(scene, cluster).z(), r, 1e-6);
  EXPECT_LT(scene.bodies.velocity[c].tail<3>().norm(), 1e-9);
  ASSERT_EQ(state.contacts.size(), 3u);
  for (const Interaction3D& k : state.contacts)
    EXPECT_NEAR(k.r(1), scene.bodies.mass[c] * g * h / 3.0, 1e-6 * scene.bodies.mass[c] * g * h);
}

// Without contact, the step pipeline conserves the kinetic energy of a torque-free asymmetric
// body to first order in h (explicit gyroscopic torque, numerics.md §1.2): drift below 3e-4 over
// 10^4 steps of 1e-3 s near the stable axis (measured 1.9e-4 with the stand-alone integrator of
// rigid_3d_torque_free_test.cpp).
TEST(Rigid3DAnalytic, TorqueFreeRotationKeepsEnergyThroughThePipeline) {
  SceneBuilder3D b;
  b.set_gravity(Vector3d::Zero());
  b.set_rotation_scheme(FrameUpdate::cayley);
  // A sphere given an asymmetric inertia by hand: no contact, so its shape does not matter.
  const auto body = static_cast<std::size_t>(b.add_sphere(Vector3d::Zero(), 0.1, 1000.0));
  Scene3D scene = b.build();
  scene.bodies.inertia[body] = Vector3d(1.0, 2.0, 3.0);
  scene.bodies.inverse_mass[body].tail<3>() = Vector3d(1.0, 0.5, 1.0 / 3.0);
  Vector6d v0;
  v0 << 0.0, 0.0, 0.0, 1.0, 0.1, 0.1;
  scene.bodies.velocity_begin[body] = scene.bodies.velocity[body] = v0;
  const double e0 = kinetic_energy(scene.bodies);
  RunState3D state = run_state(1e-3);
  for (int i = 0; i < 10000; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  EXPECT_NEAR(kinetic_energy(scene.bodies), e0, 3e-4 * e0);
}

// Source point (RBDY3_SetSourcePointWithIni): the first sphere starts at the point and falls
// freely; the second waits, invisible, and enters at the point at the end of the first step where
// the first one is farther than the radius R from it. With the θ-scheme (θ = 1/2) a free fall from
// rest covers g t²/2 exactly, so it enters after the step n = ceil(sqrt(2R/g)/h) (strict >).
TEST(Rigid3DAnalytic, SourcePointReleasesTheNextBodyWhenTheLastIsOneRadiusAway) {
  const double radius = 0.5, h = 1e-3;
  const Vector3d point(1.0, 2.0, 3.0);
  SceneBuilder3D b;
  const int first = b.add_sphere(Vector3d(-5.0, 0.0, 0.0), 0.1, 1000.0);
  const int second = b.add_sphere(Vector3d(7.0, 0.0, 0.0), 0.1, 1000.0);
  Scene3D scene = b.build();
  init_source_point(scene, static_cast<std::size_t>(first), radius, point);
  EXPECT_EQ(scene.bodies.visible[static_cast<std::size_t>(second)], 0);
  EXPECT_TRUE(centre_of(scene, first).isApprox(point));
  RunState3D state = run_state(h);
  long entered = 0;
  for (long step = 1; step <= 1000 && entered == 0; ++step) {
    step_3d(scene, state, test::converged_nlgs_options(10));
    if (scene.bodies.visible[static_cast<std::size_t>(second)])
      entered = step;
    else
      EXPECT_TRUE(centre_of(scene, second).isZero()) << "a waiting body stays at 0";
  }
  const long expected = static_cast<long>(std::ceil(std::sqrt(2.0 * radius / g) / h));
  EXPECT_EQ(entered, expected);
  EXPECT_TRUE(centre_of(scene, second).isApprox(point));
}

// Source point without Ini (RBDY3_SetSourcePoint, COMMAND.DAT's INIT SOURCE POINT): the point is a
// translation from each body's own reference: the first sphere starts at its reference + point, the
// second waits at its reference and enters there + point.
TEST(Rigid3DAnalytic, RelativeSourcePointTranslatesEachBodyFromItsReference) {
  const double radius = 0.5, h = 1e-3;
  const Vector3d point(1.0, 2.0, 3.0), first_at(-5.0, 0.0, 0.0), second_at(7.0, 0.0, 0.0);
  SceneBuilder3D b;
  const int first = b.add_sphere(first_at, 0.1, 1000.0);
  const int second = b.add_sphere(second_at, 0.1, 1000.0);
  Scene3D scene = b.build();
  init_source_point(scene, static_cast<std::size_t>(first), radius, point, /*absolute=*/false);
  EXPECT_EQ(scene.bodies.visible[static_cast<std::size_t>(second)], 0);
  RunState3D state = run_state(h);
  step_3d(scene, state, test::converged_nlgs_options(10));
  EXPECT_NEAR((centre_of(scene, first) - (first_at + point)).head<2>().norm(), 0.0, 1e-12);
  long entered = 0;
  for (long step = 2; step <= 1000 && entered == 0; ++step) {
    step_3d(scene, state, test::converged_nlgs_options(10));
    if (scene.bodies.visible[static_cast<std::size_t>(second)]) entered = step;
  }
  EXPECT_EQ(entered, static_cast<long>(std::ceil(std::sqrt(2.0 * radius / g) / h)));
  EXPECT_TRUE(centre_of(scene, second).isApprox(second_at + point));
}

// Periodic sides: a sphere moving in +x towards the side x = L meets the image of a sphere resting
// just inside x = 0, one period away: a head-on impact across the side. With restitution e = 1
// between equal masses (RST_CLB) the velocities swap.
TEST(Rigid3DAnalytic, SpheresMeetAcrossAPeriodicSide) {
  const double period = 2.0, r = 0.1, h = 1e-4;
  SceneBuilder3D b;
  const int moving = b.add_sphere(Vector3d(period - 0.3, 1.0, 0.0), r, 1000.0);
  const int resting = b.add_sphere(Vector3d(0.15, 1.0, 0.0), r, 1000.0);
  b.set_velocity(moving, (Vector6d() << 1.0, 0.0, 0.0, 0.0, 0.0, 0.0).finished());
  b.add_law("rst10", RstClb{1.0, 0.0, 0.0});
  b.see("SPHER", "BLEUx", "rst10", "SPHER", "BLEUx", 0.05);
  Scene3D scene = b.build();
  scene.gravity.setZero();
  scene.x_period = period;
  RunState3D state = run_state(h);
  // Gap 0.3 + 0.15 - 0.2 = 0.25 m at 1 m/s: the impact happens near t = 0.25 s.
  for (int step = 0; step < 4000; ++step) step_3d(scene, state, test::converged_nlgs_options(10));
  EXPECT_NEAR(scene.bodies.velocity[static_cast<std::size_t>(moving)](0), 0.0, 1e-9);
  EXPECT_NEAR(scene.bodies.velocity[static_cast<std::size_t>(resting)](0), 1.0, 1e-9);
}

// A sphere hanging under a fixed plane (bottom face z = 0), released touching it. Cohesive laws
// (contact-laws.md §3.2) hold it while their cohesion force exceeds its weight m g = 5.136 N
// (r = 0.05 m, 1000 kg/m³): the normal force is then the tension −m g; otherwise it falls.
struct Hanging {
  double z_after = 0.0;
  double normal_force = 0.0;
  ContactStatus status = ContactStatus::nknow;
};
Hanging hang_under_a_plane(const ContactLaw& law, double h = 1e-3, int steps = 200) {
  const double r = 0.05;
  SceneBuilder3D b;
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, -r), r, 1000.0);
  b.add_fixed_plane(Vector3d(0.0, 0.0, 0.05), Matrix3d::Identity(), Vector3d(1.0, 1.0, 0.05));
  b.add_law("coh01", law);
  b.see("SPHER", "BLEUx", "coh01", "PLANx", "VERTx", 0.001);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  Hanging out;
  for (int i = 0; i < steps; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  out.z_after = centre_of(scene, ball).z();
  if (!state.contacts.empty()) {
    out.normal_force = state.contacts.front().r(1) / h;
    out.status = state.contacts.front().status;
  }
  return out;
}

TEST(Rigid3DAnalytic, WetCohesionHoldsAHangingSphereOnlyWhenStrongerThanItsWeight) {
  const double weight = 1000.0 * 4.0 / 3.0 * lmgc_pi * std::pow(0.05, 3) * g;
  const Hanging held = hang_under_a_plane(IqsWetDsClb{10.0, 0.0, 0.001, 0.3, 0.3});
  EXPECT_NEAR(held.z_after, -0.05, 1e-9);
  EXPECT_NEAR(held.normal_force, -weight, 1e-6 * weight);  // tension: the sphere's weight
  EXPECT_EQ(held.status, ContactStatus::Wstck);
  const Hanging fallen = hang_under_a_plane(IqsWetDsClb{2.0, 0.0, 0.001, 0.3, 0.3});
  EXPECT_LT(fallen.z_after, -0.1);
}

// Mohr–Coulomb cohesion: cohen × the SPPLx contact surface π r² (7.85 N for 1000 Pa) holds the
// sphere (status Mstck); 300 Pa (2.36 N) does not, and once the contact has opened the cohesion is
// gone for good.
TEST(Rigid3DAnalytic, MohrCohesionHoldsAHangingSphereOnlyWhenStrongerThanItsWeight) {
  const double weight = 1000.0 * 4.0 / 3.0 * lmgc_pi * std::pow(0.05, 3) * g;
  const Hanging held = hang_under_a_plane(IqsMohrDsClb{1000.0, 1000.0, 0.3, 0.3});
  EXPECT_NEAR(held.z_after, -0.05, 1e-9);
  EXPECT_NEAR(held.normal_force, -weight, 1e-6 * weight);
  EXPECT_EQ(held.status, ContactStatus::Mstck);
  const Hanging fallen = hang_under_a_plane(IqsMohrDsClb{300.0, 300.0, 0.3, 0.3});
  EXPECT_LT(fallen.z_after, -0.1);
}

// Cylinders at rest (CYLND: CDPLx, SPCDx, CDCDx). Statics: every contact set carries the weight
// of what lies on it. Tolerance 1e-6 relative: NLGS Quad 1e-10 after 200 steps at rest.
Matrix3d axis_along(const Vector3d& axis) {
  Matrix3d f;
  f.col(2) = axis.normalized();
  f.col(0) =
      (std::abs(f.col(2).x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(f.col(2)).normalized();
  f.col(1) = f.col(2).cross(f.col(0));
  return f;
}

TEST(Rigid3DAnalytic, CylindersAtRestCarryTheWeightAbove) {
  const double r = 0.05, H = 0.2, h = 1e-3, density = 1000.0;
  SceneBuilder3D b;
  // A cylinder lying along x on the ground, a second one across it along y, a sphere on top.
  const int lower = b.add_cylinder(Vector3d(0.0, 0.0, r), axis_along(Vector3d::UnitX()), H, r, density);
  const int upper = b.add_cylinder(Vector3d(0.0, 0.0, 3.0 * r), axis_along(Vector3d::UnitY()), H, r, density);
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, 5.0 * r), r, density);
  add_ground(b);
  b.add_law("iqs05", IqsClb{0.5});
  b.see("CYLND", "BLEUx", "iqs05", "PLANx", "VERTx", 0.001);
  b.see("CYLND", "BLEUx", "iqs05", "CYLND", "BLEUx", 0.001);
  b.see("SPHER", "BLEUx", "iqs05", "CYLND", "BLEUx", 0.001);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  for (int i = 0; i < 200; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  const auto weight = [&](int body) { return scene.bodies.mass[static_cast<std::size_t>(body)] * g; };
  int ground_points = 0, crossing_points = 0, sphere_points = 0;
  double ground = 0.0, crossing = 0.0, sphere = 0.0;
  for (const Interaction3D& c : state.contacts) {
    const double f = c.r(1) / h;
    if (c.family == PairFamily3D::CDPLx) ground += f, ++ground_points;
    if (c.family == PairFamily3D::CDCDx) crossing += f, ++crossing_points;
    if (c.family == PairFamily3D::SPCDx) sphere += f, ++sphere_points;
  }
  EXPECT_EQ(ground_points, 2);    // the two cap spheres of the lower cylinder
  EXPECT_EQ(crossing_points, 1);  // crossed axes: one point
  EXPECT_EQ(sphere_points, 1);
  EXPECT_NEAR(sphere, weight(ball), 1e-6 * weight(ball));
  EXPECT_NEAR(crossing, weight(ball) + weight(upper), 1e-6 * weight(upper));
  const double total = weight(ball) + weight(upper) + weight(lower);
  EXPECT_NEAR(ground, total, 1e-6 * total);
  EXPECT_NEAR(centre_of(scene, ball).z(), 5.0 * r, 1e-7);
}

// Parallel cylinders stacked (CDCDx, parallel branch): two points, one per cap, sharing the weight.
TEST(Rigid3DAnalytic, ParallelCylindersTouchAtTwoPointsSharingTheWeight) {
  const double r = 0.05, H = 0.2, h = 1e-3;
  SceneBuilder3D b;
  b.add_cylinder(Vector3d(0.0, 0.0, r), axis_along(Vector3d::UnitX()), H, r, 1000.0);
  const int upper = b.add_cylinder(Vector3d(0.0, 0.0, 3.0 * r), axis_along(Vector3d::UnitX()), H, r, 1000.0);
  add_ground(b);
  b.add_law("iqs05", IqsClb{0.5});
  b.see("CYLND", "BLEUx", "iqs05", "PLANx", "VERTx", 0.001);
  b.see("CYLND", "BLEUx", "iqs05", "CYLND", "BLEUx", 0.001);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  for (int i = 0; i < 200; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  const double weight = scene.bodies.mass[static_cast<std::size_t>(upper)] * g;
  std::vector<double> forces;
  for (const Interaction3D& c : state.contacts)
    if (c.family == PairFamily3D::CDCDx) forces.push_back(c.r(1) / h);
  ASSERT_EQ(forces.size(), 2u);
  EXPECT_NEAR(forces[0] + forces[1], weight, 1e-6 * weight);
  EXPECT_NEAR(centre_of(scene, upper).z(), 3.0 * r, 1e-7);
}

// A sphere resting at the bottom of a fixed horizontal drum (DNLYC, SPDCx): the inner wall carries
// its weight, the normal points from the wall to the axis (up), and it stays put.
TEST(Rigid3DAnalytic, SphereInsideADrumRestsOnItsInnerWall) {
  const double R = 0.5, r = 0.1, h = 1e-3;
  SceneBuilder3D b;
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, -(R - r)), r, 1000.0);
  b.add_fixed_tube(Vector3d::Zero(), axis_along(Vector3d::UnitX()), 1.0, R);
  b.add_law("iqs05", IqsClb{0.5});
  b.see("SPHER", "BLEUx", "iqs05", "DNLYC", "VERTx", 0.001);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  for (int i = 0; i < 100; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  const Interaction3D& c = state.contacts.front();
  EXPECT_EQ(c.family, PairFamily3D::SPDCx);
  EXPECT_TRUE(c.frame.row(1).transpose().isApprox(Vector3d::UnitZ()));
  const double weight = scene.bodies.mass[static_cast<std::size_t>(ball)] * g;
  EXPECT_NEAR(c.r(1) / h, weight, 1e-6 * weight);
  EXPECT_NEAR(centre_of(scene, ball).z(), -(R - r), 1e-8);
}

// A sphere of radius 0.1 m (density 1000) hanging by a PTPT3 link from a fixed point at the
// origin: the anchor is a fixed PLANx body (not seen by anything) carrying a PT3Dx; the sphere
// carries a PT3Dx at its centre, `length` below the origin in the reference configuration, then
// moved by `offset` along z. Link law `law`.
struct PointLinkScene {
  Scene3D scene;
  int ball = 0;
};
PointLinkScene hanging_by_a_link(const ContactLaw& law, double length, double offset, double side = -1.0) {
  SceneBuilder3D b;
  const int anchor = b.add_fixed_plane(Vector3d::Zero(), Matrix3d::Identity(), Vector3d(0.1, 0.1, 0.01));
  b.add_point(anchor, Vector3d::Zero(), "ANCRx");
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, side * length), 0.1, 1000.0);
  b.add_point(ball, Vector3d::Zero(), "BLEUx");
  b.add_law("link1", law);
  // The anchor's point comes first: it is the candidate (mod_PTPT3 pairs points in order).
  b.see("PT3Dx", "ANCRx", "link1", "PT3Dx", "BLEUx", 2.0 * length);
  PointLinkScene s{b.build(), ball};
  const auto i = static_cast<std::size_t>(ball);
  s.scene.bodies.displacement_begin[i].z() = offset;
  s.scene.bodies.displacement[i].z() = offset;
  return s;
}

// ELASTIC_WIRE of stiffness k per unit strain and reference length L0 at its static elongation
// δ = m g L0 / k (Hooke): the implicit spring impulse −h k ε_end equals the weight's −m g h, so the
// mass stays put (tolerance: round-off over 1000 steps) and the link reports a stick traction.
TEST(Rigid3DAnalytic, ElasticWireHoldsAHangingMassAtItsStaticElongation) {
  const double L0 = 1.0, k = 2000.0, h = 1e-3;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
  const double delta = m * g * L0 / k;
  PointLinkScene s = hanging_by_a_link(ElasticWire{k, 0.0}, L0, -delta);
  ASSERT_EQ(s.scene.point_links.size(), 1u);
  EXPECT_DOUBLE_EQ(s.scene.point_links.front().reference_length, L0);
  RunState3D state = run_state(h);
  for (int i = 0; i < 1000; ++i) step_3d(s.scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  const Interaction3D& c = state.contacts.front();
  EXPECT_EQ(c.family, PairFamily3D::PTPT3);
  EXPECT_EQ(c.status, ContactStatus::stick);
  ASSERT_EQ(state.law_states.size(), 1u);                               // the rod keeps a law state
  EXPECT_EQ(state.law_states.front().internal[0], L0);                  // gapREF
  EXPECT_TRUE(c.frame.row(1).transpose().isApprox(Vector3d::UnitZ()));  // from the mass to the anchor
  EXPECT_NEAR(c.r(1) / h, -s.scene.bodies.mass[static_cast<std::size_t>(s.ball)] * g, 1e-9 * m * g);
  EXPECT_NEAR(centre_of(s.scene, s.ball).z(), -L0 - delta, 1e-10);
}

// The same wire across a periodic side: period 3 m along x, gravity along −x, the anchor at
// x = 0.2 m and the mass at x = 2.2 m, 1 m from the anchor's image at 3.2 m (2 m from the anchor:
// beyond the alert of 1.5 m). Detection links them across the side with L0 = 1 m, and the wire
// holds the mass at its static elongation δ = m g L0 / k as above; without the period nothing
// links them and the mass falls.
TEST(Rigid3DAnalytic, ElasticWireAcrossAPeriodicSideHoldsTheMassAtItsStaticElongation) {
  const double L0 = 1.0, k = 2000.0, h = 1e-3, period = 3.0;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
  const double delta = m * g * L0 / k;
  for (const bool periodic : {true, false}) {
    SceneBuilder3D b;
    b.set_gravity(Vector3d(-g, 0.0, 0.0));
    const int anchor =
        b.add_fixed_plane(Vector3d(0.2, 0.0, 0.0), Matrix3d::Identity(), Vector3d(0.1, 0.1, 0.01));
    b.add_point(anchor, Vector3d::Zero(), "ANCRx");
    const int ball = b.add_sphere(Vector3d(2.2, 0.0, 0.0), 0.1, 1000.0);
    b.add_point(ball, Vector3d::Zero(), "BLEUx");
    b.add_law("wire1", ElasticWire{k, 0.0});
    b.see("PT3Dx", "ANCRx", "wire1", "PT3Dx", "BLEUx", 1.5);
    Scene3D scene = b.build();
    if (periodic) scene.x_period = period;
    scene.point_links = link_points_3d(scene);
    const auto i = static_cast<std::size_t>(ball);
    scene.bodies.displacement_begin[i].x() = scene.bodies.displacement[i].x() = -delta;
    RunState3D state = run_state(h);
    for (int n = 0; n < 300; ++n) step_3d(scene, state, test::converged_nlgs_options(10));
    if (!periodic) {
      EXPECT_TRUE(state.contacts.empty());
      EXPECT_LT(centre_of(scene, ball).x(), 2.2 - 0.4);  // fell freely: 0.44 m in 0.3 s
      continue;
    }
    ASSERT_EQ(state.contacts.size(), 1u);
    const Interaction3D& c = state.contacts.front();
    EXPECT_EQ(c.status, ContactStatus::stick);
    EXPECT_EQ(state.law_states.at(0).internal[0], L0);  // gapREF across the side
    EXPECT_TRUE(
        c.frame.row(1).transpose().isApprox(Vector3d::UnitX()));  // from the mass's image to the anchor
    EXPECT_NEAR(c.r(1) / h, -m * g, 1e-9 * m * g);
    EXPECT_NEAR(centre_of(scene, ball).x(), 2.2 - delta, 1e-10);
  }
}

// A slack wire (points closer than L0) carries nothing: the mass falls freely, z = z0 − g t²/2
// (θ = 1/2 integrates a constant acceleration exactly), while the link stays 'vnish'.
TEST(Rigid3DAnalytic, SlackElasticWireLetsTheMassFallFreely) {
  const double L0 = 1.0, h = 1e-3;
  PointLinkScene s = hanging_by_a_link(ElasticWire{2000.0, 0.0}, L0, 0.5 * L0);
  RunState3D state = run_state(h);
  for (int i = 0; i < 200; ++i) step_3d(s.scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_EQ(state.contacts.front().status, ContactStatus::vnish);
  EXPECT_EQ(state.contacts.front().r, Vector3d::Zero());
  EXPECT_NEAR(centre_of(s.scene, s.ball).z(), -0.5 * L0 - 0.5 * g * 0.2 * 0.2, 1e-12);
}

// ELASTIC_ROD is bilateral: a mass standing on a rod, compressed by δ = m g L0 / k, stays put.
TEST(Rigid3DAnalytic, ElasticRodCarriesAMassInCompression) {
  const double L0 = 1.0, k = 2000.0, h = 1e-3;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * 1e-3;
  const double delta = m * g * L0 / k;
  PointLinkScene s = hanging_by_a_link(ElasticRod{k, 0.0}, L0, -delta, +1.0);
  RunState3D state = run_state(h);
  for (int i = 0; i < 1000; ++i) step_3d(s.scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_NEAR(state.contacts.front().r(1) / h, m * g, 1e-9 * m * g);  // push
  EXPECT_NEAR(centre_of(s.scene, s.ball).z(), L0 - delta, 1e-10);
}

// A sphere of radius 0.1 m `opening` below the bottom face (z = 0) of a fixed plane, seen by it
// with `law` (SPPLx, contact surface π r²).
Scene3D sphere_under_a_plane(const ContactLaw& law, double opening, int& ball) {
  SceneBuilder3D b;
  Matrix3d down;  // plane axes (T, S, N) with N = −z: the bottom face at z = 0 faces down
  down << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  b.add_fixed_plane(Vector3d(0.0, 0.0, 0.05), down, Vector3d(1.0, 1.0, 0.05));
  ball = b.add_sphere(Vector3d(0.0, 0.0, -0.1 - opening), 0.1, 1000.0);
  b.add_law("law01", law);
  b.see("SPHER", "BLEUx", "law01", "PLANx", "VERTx", 0.01);
  return b.build();
}

// IQS_MAC_CZM: a sound interface (β = 1) holds the weight with the opening δn = m g / (π r² cn), where
// the cohesive impulse −π r² cn h δn equals −m g h; started there, the sphere stays put and the
// interface stays sound (its stored energy cn δn² is far below dupre).
TEST(Rigid3DAnalytic, SoundCohesiveZoneHoldsASphereUnderAPlaneAtItsElasticOpening) {
  const double r = 0.1, cn = 1e8, h = 1e-3;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double opening = m * g / (lmgc_pi * r * r * cn);
  int ball = 0;
  Scene3D scene = sphere_under_a_plane(IqsMacCzm{0.3, 0.3, cn, cn, 0.0, 1e6}, opening, ball);
  RunState3D state = run_state(h);
  for (int i = 0; i < 500; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  const Interaction3D& c = state.contacts.front();
  EXPECT_EQ(state.law_states.at(0).internal[4], 1.0);  // β
  EXPECT_EQ(c.status, ContactStatus::Cstck);
  EXPECT_NEAR(c.r(1) / h, -m * g, 1e-6 * m * g);
  EXPECT_NEAR(centre_of(scene, ball).z(), -r - opening, 1e-10);
}

// A weak interface (dupre 1e-3 J/m²) damages as soon as it opens: β = w / (cn δn²) once the stored
// energy exceeds w, the cohesive traction β² cn δn vanishes, and the sphere falls almost freely:
// after 0.2 s it has dropped at least 95% of g t²/2 and β is below 1e-2.
TEST(Rigid3DAnalytic, WeakCohesiveZoneBreaksAndLetsTheSphereFall) {
  const double r = 0.1, h = 1e-3;
  int ball = 0;
  Scene3D scene = sphere_under_a_plane(IqsMacCzm{0.3, 0.3, 1e8, 1e8, 0.0, 1e-3}, 0.0, ball);
  RunState3D state = run_state(h);
  double beta = 1.0;
  for (int i = 0; i < 200; ++i) {
    step_3d(scene, state, test::converged_nlgs_options(10));
    if (!state.contacts.empty()) beta = state.law_states.at(0).internal[4];
  }
  EXPECT_LT(beta, 1e-2);
  EXPECT_LT(centre_of(scene, ball).z(), -r - 0.95 * 0.5 * g * 0.2 * 0.2);
}

// Two spheres hanging in a chain from a ceiling, both interfaces sound IQS_MAC_CZM (ceiling–upper
// SPPLx, upper–lower SPSPx); the lower sphere leaves at 1 m/s, which tears its interface in the first
// step (it stores cn δn² ≫ w). The chain takes several sweeps to converge, and LMGC90 re-evaluates β
// at each convergence check (updt_CZM_3D(.false.)), the sweeps after it using the new β; so at
// convergence an open interface's reaction is the cohesive traction of the β the step stores,
// r_n = −L β² h cn δn_end. With β held at 1 through the step it would be that of the sound
// interface, 1/β² times larger.
TEST(Rigid3DAnalytic, CohesiveZoneTornInOneStepReactsWithTheBetaItStores) {
  const double h = 1e-3, cn = 1e8;
  SceneBuilder3D b;
  Matrix3d down;  // the plane's bottom face (z = 0) faces down
  down << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  b.add_fixed_plane(Vector3d(0.0, 0.0, 0.05), down, Vector3d(1.0, 1.0, 0.05));
  b.add_sphere(Vector3d(0.0, 0.0, -0.1), 0.1, 1000.0);
  const int lower = b.add_sphere(Vector3d(0.0, 0.0, -0.3), 0.1, 1000.0);
  b.add_law("mac01", IqsMacCzm{0.3, 0.3, cn, cn, 0.0, 10.0});
  b.see("SPHER", "BLEUx", "mac01", "PLANx", "VERTx", 0.01);
  b.see("SPHER", "BLEUx", "mac01", "SPHER", "BLEUx", 0.01);
  Vector6d leaving = Vector6d::Zero();
  leaving(2) = -1.0;
  b.set_velocity(lower, leaving);
  Scene3D scene = b.build();
  NlgsOptions options = test::converged_nlgs_options(10);
  options.gs_it1 = 1;  // a check after every sweep
  RunState3D state = run_state(h);
  const NlgsResult result = step_3d(scene, state, options);
  EXPECT_TRUE(result.converged);
  EXPECT_GT(result.iterations, 2);
  ASSERT_EQ(state.contacts.size(), 2u);
  int torn = 0;
  ASSERT_EQ(state.law_states.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const Interaction3D& c = state.contacts[k];
    const std::array<double, 6>& internal = state.law_states[k].internal;
    const double beta = internal[4], opening = internal[2];
    if (beta == 1.0) continue;
    ++torn;
    EXPECT_GT(opening, 0.0);
    EXPECT_NEAR(c.r(1), -internal[0] * beta * beta * h * cn * opening, 1e-3 * std::abs(c.r(1)));
  }
  EXPECT_GE(torn, 1);
}

// ELASTIC_REPELL_CLB in 3D: a sphere on a plane sinks into its spring until k δ = m g (the implicit
// impulse −h k γ_end carries the weight); started at δ = m g / k it stays there.
TEST(Rigid3DAnalytic, ElasticRepellSphereRestsAtItsSpringPenetration) {
  const double r = 0.1, k = 1e6, h = 1e-3;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double depth = m * g / k;
  SceneBuilder3D b;
  const int ball = b.add_sphere(Vector3d(0.0, 0.0, r - depth), r, 1000.0);
  add_ground(b);
  b.add_law("rep01", ElasticRepellClb{k, 0.3});
  b.see("SPHER", "BLEUx", "rep01", "PLANx", "VERTx", 0.01);
  Scene3D scene = b.build();
  RunState3D state = run_state(h);
  for (int i = 0; i < 500; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_NEAR(state.contacts.front().r(1) / h, m * g, 1e-6 * m * g);
  EXPECT_NEAR(centre_of(scene, ball).z(), r - depth, 1e-10);
}

// COUPLED_DOF in 3D glues every component: a sphere glued under a plane stays put, the link pulling
// with its weight.
TEST(Rigid3DAnalytic, CoupledDofHoldsASphereUnderAPlane) {
  const double r = 0.1, h = 1e-3;
  const double m = 1000.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  int ball = 0;
  Scene3D scene = sphere_under_a_plane(CoupledDof{}, 0.0, ball);
  RunState3D state = run_state(h);
  for (int i = 0; i < 200; ++i) step_3d(scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_EQ(state.contacts.front().status, ContactStatus::stick);
  EXPECT_NEAR(state.contacts.front().r(1) / h, -m * g, 1e-9 * m * g);
  EXPECT_NEAR(centre_of(scene, ball).z(), -r, 1e-12);
}

}  // namespace
}  // namespace lmgc::solver
