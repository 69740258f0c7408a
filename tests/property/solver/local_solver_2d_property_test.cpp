// Properties of the 2D local solvers and of converged NLGS steps.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "solver/nlgs/local_solver_2d.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;

using test::in_range;

// A random symmetric positive definite block, as H M⁻¹ Hᵀ of a contact between rigid bodies.
Matrix2d random_spd() {
  const double a = in_range(0.05, 10.0), c = in_range(0.05, 10.0);
  const double b = in_range(-0.95, 0.95) * std::sqrt(a * c);
  Matrix2d W;
  W << a, b, b, c;
  return W;
}

RC_GTEST_PROP(SignoriniCoulomb2D, SolutionSatisfiesComplementarityWithinRoundOff, ()) {
  const Matrix2d W = random_spd();
  const Vector2d q(in_range(-5.0, 5.0), in_range(-5.0, 5.0));
  const double mu = in_range(0.0, 2.0);
  const LocalSolution2D s = solve_signorini_coulomb_2d(W, q, mu);
  RC_ASSERT(!s.failed);
  const Vector2d u = W * s.r + q;
  const double scale = 1.0 + q.norm();
  RC_ASSERT(std::sqrt(natural_map_residual_squared_2d(s.r, u, mu)) <= 1e-10 * scale);
  RC_ASSERT(s.r(1) >= 0.0);
  RC_ASSERT(std::fabs(s.r(0)) <= mu * s.r(1) * (1.0 + 1e-12) + 1e-15);
  RC_ASSERT(u(1) >= -1e-10 * scale);
  RC_ASSERT(std::fabs(s.r(1) * u(1)) <= 1e-10 * scale * scale);
}

RC_GTEST_PROP(SignoriniCoulomb2D, ReciprocalsGiveTheSameCaseAndTheReactionToRoundOff, ()) {
  const Matrix2d W = random_spd();
  const Vector2d q(in_range(-5.0, 5.0), in_range(-5.0, 5.0));
  const double mu = *rc::gen::element(0.0, in_range(0.0, 2.0));
  double rt, rn, rt_inverse, rn_inverse;
  ContactStatus status, status_inverse;
  const bool solved = solve_signorini_coulomb_2d(W(0, 0), W(0, 1), W(1, 1), q(0), q(1), mu, rt, rn, status);
  const SignoriniCoulombReciprocals2D inverse =
      signorini_coulomb_reciprocals_2d(W(0, 0), W(0, 1), W(1, 1), mu);
  RC_ASSERT(solve_signorini_coulomb_2d(W(0, 0), W(0, 1), W(1, 1), inverse, q(0), q(1), mu, rt_inverse,
                                       rn_inverse, status_inverse) == solved);
  RC_ASSERT(status_inverse == status);
  const double scale = 1e-14 * (1.0 + std::fabs(rt) + std::fabs(rn));
  RC_ASSERT(std::fabs(rt_inverse - rt) <= scale);
  RC_ASSERT(std::fabs(rn_inverse - rn) <= scale);
}

TEST(SignoriniCoulomb2D, ReciprocalsKeepTheFallbacksAndReturnNoReactionOnNaN) {
  // The forward slide's denominator is negative here (see the test below): the backward slide.
  const double wtt = 5.18966, wtn = 0.837049, wnn = 0.278671, mu = 0.45707;
  const SignoriniCoulombReciprocals2D inverse = signorini_coulomb_reciprocals_2d(wtt, wtn, wnn, mu);
  EXPECT_EQ(inverse.forward, 0.0);
  double rt, rn;
  ContactStatus status;
  ASSERT_TRUE(solve_signorini_coulomb_2d(wtt, wtn, wnn, inverse, -5.0, -0.3385, mu, rt, rn, status));
  EXPECT_EQ(status, ContactStatus::slibw);
  EXPECT_GT(rn, 0.0);
  EXPECT_FALSE(solve_signorini_coulomb_2d(wtt, wtn, wnn, inverse, std::nan(""), -1.0, mu, rt, rn, status));
  EXPECT_EQ(rt, 0.0);
  EXPECT_EQ(rn, 0.0);
}

TEST(SignoriniCoulomb2D, ReciprocalThatOverflowsIsNotTaken) {
  // det = 1e-320 (subnormal): 1/det overflows, so the stick case divides as the enumeration does.
  const double wtt = 1e-160, wtn = 0.0, wnn = 1e-160, mu = 0.3;
  const SignoriniCoulombReciprocals2D inverse = signorini_coulomb_reciprocals_2d(wtt, wtn, wnn, mu);
  EXPECT_EQ(inverse.det, 0.0);
  double rt, rn, rt_dividing, rn_dividing;
  ContactStatus status, status_dividing;
  const bool solved = solve_signorini_coulomb_2d(wtt, wtn, wnn, inverse, 0.0, -1e-170, mu, rt, rn, status);
  EXPECT_EQ(solved, solve_signorini_coulomb_2d(wtt, wtn, wnn, 0.0, -1e-170, mu, rt_dividing, rn_dividing,
                                               status_dividing));
  EXPECT_EQ(status, status_dividing);
  EXPECT_EQ(rt, rt_dividing);
  EXPECT_EQ(rn, rn_dividing);
  EXPECT_TRUE(std::isfinite(rn));
}

RC_GTEST_PROP(SignoriniCoulomb2D, FrictionDissipatesRtTimesUtIsNonPositive, ()) {
  const Matrix2d W = random_spd();
  const Vector2d q(in_range(-5.0, 5.0), in_range(-5.0, 0.0));
  const double mu = in_range(0.0, 2.0);
  const LocalSolution2D s = solve_signorini_coulomb_2d(W, q, mu);
  const Vector2d u = W * s.r + q;
  RC_ASSERT(s.r(0) * u(0) <= 1e-12 * (1.0 + q.squaredNorm()));
}

RC_GTEST_PROP(SignoriniCoulomb2D, StatusMatchesTheRegime, ()) {
  const Matrix2d W = random_spd();
  const Vector2d q(in_range(-5.0, 5.0), in_range(-5.0, 5.0));
  const double mu = in_range(0.0, 2.0);
  const LocalSolution2D s = solve_signorini_coulomb_2d(W, q, mu);
  const Vector2d u = W * s.r + q;
  if (s.status == ContactStatus::noctc) RC_ASSERT(s.r.isZero(0.0));
  if (s.status == ContactStatus::stick) RC_ASSERT(u.norm() <= 1e-10 * (1.0 + q.norm()));
  if (s.status == ContactStatus::slifw) RC_ASSERT(u(0) >= -1e-10 * (1.0 + q.norm()));
  if (s.status == ContactStatus::slibw) RC_ASSERT(u(0) <= 1e-10 * (1.0 + q.norm()));
}

// Two disks colliding head on with restitution e: the kinetic energy never grows.
RC_GTEST_PROP(Restitution2D, BinaryImpactNeverCreatesEnergy, ()) {
  const double e = in_range(0.0, 1.0);
  const double r1 = in_range(0.05, 0.2), r2 = in_range(0.05, 0.2);
  const double v1 = in_range(0.1, 5.0), v2 = in_range(-5.0, 0.0);
  SceneBuilder2D b;
  const double gap = 1e-5;
  b.add_disk(0.0, 0.0, r1, in_range(100.0, 10000.0));
  b.add_disk(r1 + r2 + gap, in_range(-0.5, 0.5) * r2, r2, in_range(100.0, 10000.0));
  b.add_law("rstxx", RstClb{e, 0.0, in_range(0.0, 1.0)});
  b.see("DISKx", "BLEUx", "rstxx", "DISKx", "BLEUx", 0.01);
  b.set_gravity(Vector2d::Zero());
  b.set_velocity(0, Eigen::Vector3d(v1, 0.0, 0.0));
  b.set_velocity(1, Eigen::Vector3d(v2, 0.0, 0.0));
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-4;
  state.visibility = build_visibility_index(scene);
  NlgsOptions options;
  options.tolerance = 1e-10;
  const double before = [&] {
    scene.bodies.velocity = scene.bodies.velocity_begin;
    return kinetic_energy(scene.bodies);
  }();
  for (int i = 0; i < 20; ++i) step_2d(scene, state, options);
  RC_ASSERT(kinetic_energy(scene.bodies) <= before * (1.0 + 1e-9));
}

// On random small piles, a converged step satisfies every contact law within its residual.
RC_GTEST_PROP(Nlgs2D, ConvergedStepSatisfiesEveryContactLaw, ()) {
  SceneBuilder2D b;
  const int n = *rc::gen::inRange(2, 12);
  for (int i = 0; i < n; ++i) b.add_disk(in_range(-0.3, 0.3), 0.1 + 0.19 * i, in_range(0.06, 0.1), 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{in_range(0.0, 1.0)});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 0.05);
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.05);
  Scene2D scene = b.build();
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  NlgsOptions options;
  options.tolerance = 1e-12;
  options.gs_it1 = 50;
  options.gs_it2 = 400;
  options.residual_target = 1e-12;
  NlgsResult result;
  for (int i = 0; i < 30; ++i) result = step_2d(scene, state, options);
  RC_ASSERT(result.converged);
  RC_ASSERT(result.residual_relative <= 1e-10);
  for (const Interaction2D& c : state.contacts) {
    RC_ASSERT(c.r(1) >= 0.0);
    RC_ASSERT(std::fabs(c.r(0)) <= c.mu * c.r(1) * (1.0 + 1e-9) + 1e-14);
  }
}

}  // namespace
}  // namespace lmgc::solver

namespace lmgc::solver {
namespace {

// RapidCheck counterexample (sanitizer run of stop 9): the sign test picks the forward slide,
// whose denominator Wnn - μ Wnt is negative; the problem is solved by the backward slide.
TEST(SignoriniCoulomb2D, ForwardBranchWithNegativeDenominatorFallsBackToTheConsistentCase) {
  Matrix2d W;
  W << 5.18966, 0.837049, 0.837049, 0.278671;
  const Vector2d q(-5.0, -0.3385);
  const double mu = 0.45707;
  const LocalSolution2D s = solve_signorini_coulomb_2d(W, q, mu);
  ASSERT_FALSE(s.failed);
  EXPECT_EQ(s.status, ContactStatus::slibw);
  const Vector2d u = W * s.r + q;
  EXPECT_LE(std::sqrt(natural_map_residual_squared_2d(s.r, u, mu)), 1e-12);
  double rt, rn;
  ContactStatus status;
  ASSERT_TRUE(solve_signorini_coulomb_2d(W(0, 0), W(0, 1), W(1, 1), q(0), q(1), mu, rt, rn, status));
  EXPECT_NEAR(rt, s.r(0), 1e-14);
  EXPECT_NEAR(rn, s.r(1), 1e-14);
}

}  // namespace
}  // namespace lmgc::solver
