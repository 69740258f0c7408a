// Properties of the 3D Signorini–Coulomb local solver (one frictional contact, vectors ordered
// normal first, (n, t, s), fc3d/FORMAT.md §1.1) and hand-computed projections on the Coulomb cone.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "solver/nlgs/local_solver_3d.hpp"
#include "tests/support/generators.hpp"
#include "tests/support/random_blocks.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

using test::in_range;

using test::random_q;
using test::random_rotation;
using test::random_spd;

double smallest_eigenvalue_of_symmetric_part(const Matrix3d& W) {
  const Matrix3d S = 0.5 * (W + W.transpose());
  return Eigen::SelfAdjointEigenSolver<Matrix3d>(S, Eigen::EigenvaluesOnly).eigenvalues()(0);
}

// The data of a case, printed when a property fails.
std::string describe(const Matrix3d& W, const Vector3d& q, double mu) {
  std::ostringstream out;
  out.precision(17);
  out << "W =\n" << W << "\nq = " << q.transpose() << "\nmu = " << mu;
  return out.str();
}

// Tolerance asked of the solver in these properties (absolute, on |F(r)|).
double solver_tolerance(const Vector3d& q) {
  return 1e-10 * (1.0 + q.norm());
}

bool in_cone(const Vector3d& r, double mu) {
  return r(0) >= 0.0 && r.tail<2>().norm() <= mu * r(0) * (1.0 + 1e-9) + 1e-300;
}

void check_solves(const Matrix3d& W, const Vector3d& q, double mu) {
  RC_LOG() << describe(W, q, mu) << "\n";
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, Vector3d::Zero(), solver_tolerance(q));
  const Vector3d u = W * s.r + q;
  const double residual = natural_map_3d(s.r, u, mu).norm();
  RC_LOG() << "r = " << s.r.transpose() << ", residual = " << residual << ", failed = " << s.failed << "\n";
  RC_ASSERT(!s.failed);
  RC_ASSERT(residual <= 1e-9 * (1.0 + q.norm()));
  RC_ASSERT(in_cone(s.r, mu));
}

RC_GTEST_PROP(SignoriniCoulomb3D, SolutionHasNaturalMapResidualWithinToleranceAndLiesInTheCone, ()) {
  check_solves(random_spd(), random_q(), in_range(0.0, 2.0));
}

RC_GTEST_PROP(SignoriniCoulomb3D, FrictionNeverDoesPositiveWorkRtDotUtIsNonPositive, ()) {
  const Matrix3d W = random_spd();
  const Vector3d q = random_q();
  const double mu = in_range(0.0, 2.0);
  RC_LOG() << describe(W, q, mu) << "\n";
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, Vector3d::Zero(), solver_tolerance(q));
  const Vector3d u = W * s.r + q;
  RC_LOG() << "r = " << s.r.transpose() << ", u = " << u.transpose() << "\n";
  RC_ASSERT(s.r.tail<2>().dot(u.tail<2>()) <= 1e-9 * (1.0 + q.norm()) * (1.0 + s.r.norm() + u.norm()));
}

// R = blockdiag(1, rot2(theta)) turns the tangent plane about the normal: the law is isotropic, so
// solving (R W Rᵀ, R q) must give R r.
RC_GTEST_PROP(SignoriniCoulomb3D, RotatingTheTangentPlaneAboutTheNormalRotatesTheReaction, ()) {
  const Matrix3d W = random_spd();
  const Vector3d q = random_q();
  const double mu = in_range(0.0, 2.0);
  const double theta = in_range(-M_PI, M_PI);
  Matrix3d R = Matrix3d::Identity();
  R.bottomRightCorner<2, 2>() = Eigen::Rotation2Dd(theta).toRotationMatrix();
  RC_LOG() << describe(W, q, mu) << "\ntheta = " << theta << "\n";
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, Vector3d::Zero(), solver_tolerance(q));
  const LocalSolution3D s_rotated =
      solve_signorini_coulomb_3d(R * W * R.transpose(), R * q, mu, Vector3d::Zero(), solver_tolerance(q));
  RC_LOG() << "R r = " << (R * s.r).transpose() << ", r(rotated data) = " << s_rotated.r.transpose() << "\n";
  RC_ASSERT(!s.failed);
  RC_ASSERT(!s_rotated.failed);
  RC_ASSERT((s_rotated.r - R * s.r).norm() <= 1e-7 * (1.0 + s.r.norm()));
}

RC_GTEST_PROP(SignoriniCoulomb3D, NonNegativeFreeNormalVelocityGivesExactlyZeroReaction, ()) {
  const Matrix3d W = random_spd();
  const Vector3d q(in_range(0.0, 5.0), in_range(-5.0, 5.0), in_range(-5.0, 5.0));
  const double mu = in_range(0.0, 2.0);
  RC_LOG() << describe(W, q, mu) << "\n";
  const LocalSolution3D s =
      solve_signorini_coulomb_3d(W, q, mu, Vector3d(1.0, 0.1, 0.1), solver_tolerance(q));
  RC_ASSERT(!s.failed);
  RC_ASSERT(s.r == Vector3d::Zero());
  RC_ASSERT(s.state == LocalCase3D::take_off);
}

// q = -W r* with r* strictly inside the cone: the answer is r*, with u = 0.
RC_GTEST_PROP(SignoriniCoulomb3D, StickingCaseStrictlyInsideTheConeReturnsZeroVelocity, ()) {
  const Matrix3d W = random_spd();
  const double mu = in_range(0.05, 2.0);
  const double rn = in_range(0.01, 5.0);
  const double angle = in_range(-M_PI, M_PI);
  const double radius = in_range(0.0, 0.9) * mu * rn;
  const Vector3d r_stick(rn, radius * std::cos(angle), radius * std::sin(angle));
  const Vector3d q = -W * r_stick;
  RC_PRE(q(0) < 0.0);  // q_n >= 0 is the take-off case, checked above
  RC_LOG() << describe(W, q, mu) << "\n";
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, Vector3d::Zero(), solver_tolerance(q));
  const Vector3d u = W * s.r + q;
  RC_LOG() << "r = " << s.r.transpose() << ", u = " << u.transpose() << "\n";
  RC_ASSERT(!s.failed);
  RC_ASSERT(s.state == LocalCase3D::stick);
  RC_ASSERT(u.norm() <= 1e-9 * (1.0 + q.norm()));
}

// Blocks of the FCLIB set are not always symmetric: S + K with S symmetric positive definite and a
// skew part K smaller than the smallest eigenvalue of S.
RC_GTEST_PROP(SignoriniCoulomb3D, NonSymmetricPositiveDefiniteBlockStillSolvesToTolerance, ()) {
  const Matrix3d S = random_spd();
  const double lambda_min = smallest_eigenvalue_of_symmetric_part(S);
  Matrix3d K = Matrix3d::Zero();
  K(0, 1) = in_range(-1.0, 1.0);
  K(0, 2) = in_range(-1.0, 1.0);
  K(1, 2) = in_range(-1.0, 1.0);
  K -= Matrix3d(K.transpose());
  if (K.norm() > 0.0) K *= in_range(0.0, 0.5) * lambda_min / K.norm();
  const Matrix3d W = S + K;
  RC_ASSERT(smallest_eigenvalue_of_symmetric_part(W) > 0.0);
  check_solves(W, random_q(), in_range(0.0, 2.0));
}

// Sphere blocks (no normal–tangential coupling, isotropic tangential part, up to a round-off of
// 1e-14) take the closed-form slide: solved to tolerance in the cone, without a Newton iteration.
RC_GTEST_PROP(SignoriniCoulomb3D, UncoupledIsotropicBlockSlidesInClosedFormWithinTolerance, ()) {
  const double normal = in_range(0.1, 10.0), tangential = normal * in_range(0.5, 4.0);
  Matrix3d W = Matrix3d::Zero();
  W.diagonal() << normal, tangential, tangential;
  Matrix3d noise = Matrix3d::Zero();
  noise(0, 1) = noise(1, 0) = in_range(-1.0, 1.0);
  noise(1, 2) = noise(2, 1) = in_range(-1.0, 1.0);
  W += 1e-14 * normal * noise;
  const Vector3d q = random_q();
  const double mu = in_range(0.0, 2.0);
  check_solves(W, q, mu);
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, Vector3d::Zero(), solver_tolerance(q));
  RC_ASSERT(s.newton_iterations == 0);
}

// An inexact solve (forcing > 0, as the scene NLGS asks) stops within forcing times its start's
// residual, or the tolerance; it is never flagged as failed for stopping there, and the exact solve
// of the same data still meets the tolerance.
RC_GTEST_PROP(SignoriniCoulomb3D, InexactSolveEndsWithinForcingTimesTheStartResidual, ()) {
  const Matrix3d W = random_spd();
  const Vector3d q = random_q();
  const double mu = in_range(0.0, 2.0);
  const Vector3d start(in_range(0.01, 2.0), in_range(-1.0, 1.0), in_range(-1.0, 1.0));
  const Vector3d r_start = project_on_coulomb_cone(start, mu);
  RC_PRE(r_start(0) > 0.0);  // the solver's start (a zero one is replaced)
  const double forcing = *rc::gen::element(1e-1, 1e-2, 1e-4);
  const Matrix3d W_inverse = W.inverse();
  const double tolerance = solver_tolerance(q);
  RC_LOG() << describe(W, q, mu) << "\n";
  const LocalSolution3D inexact =
      solve_signorini_coulomb_3d(W, &W_inverse, q, mu, r_start, tolerance, forcing);
  const LocalSolution3D exact = solve_signorini_coulomb_3d(W, &W_inverse, q, mu, r_start, tolerance);
  const double start_residual = natural_map_3d(r_start, W * r_start + q, mu).norm();
  const double residual = natural_map_3d(inexact.r, W * inexact.r + q, mu).norm();
  RC_ASSERT(!inexact.failed);
  RC_ASSERT(residual <= std::max(1e-9 * (1.0 + q.norm()), forcing * start_residual * (1.0 + 1e-9)));
  RC_ASSERT(in_cone(inexact.r, mu));
  RC_ASSERT(inexact.newton_iterations <= exact.newton_iterations);
  RC_ASSERT(natural_map_3d(exact.r, W * exact.r + q, mu).norm() <= 1e-9 * (1.0 + q.norm()));
}

// With a keep tolerance (the scene NLGS's), a sticking problem whose start lies within round-off
// distance of its exact solution returns the start itself, bit for bit; a start farther away gets
// the exact sticking solution; and whatever is returned solves the problem within the keep tolerance
// or the exact solve's round-off.
RC_GTEST_PROP(SignoriniCoulomb3D, StickingStartWithinTheKeepToleranceIsReturnedBitForBit, ()) {
  const Matrix3d W = random_spd();
  const double mu = in_range(0.05, 2.0);
  const double rn = in_range(0.01, 5.0);
  const double angle = in_range(-M_PI, M_PI);
  const Vector3d r_stick(rn, 0.5 * mu * rn * std::cos(angle), 0.5 * mu * rn * std::sin(angle));
  const Vector3d q = -W * r_stick;
  RC_PRE(q(0) < 0.0);
  const double tolerance = solver_tolerance(q), keep = tolerance / 20.0;
  const bool near = *rc::gen::arbitrary<bool>();
  // A start off the exact solution by 1e-3 (near) or 1e2 (far) of the keep tolerance, in velocity.
  const Vector3d direction = random_q().normalized();
  const Matrix3d W_inverse = W.inverse();
  const Vector3d r_start = r_stick + (near ? 1e-3 : 1e2) * keep * (W_inverse * direction);
  RC_LOG() << describe(W, q, mu) << "\nstart " << r_start.transpose() << (near ? " near" : " far") << "\n";
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, &W_inverse, q, mu, r_start, tolerance, 0.0, keep);
  RC_ASSERT(!s.failed);
  RC_ASSERT(s.state == LocalCase3D::stick);
  if (near)
    RC_ASSERT(s.r == r_start);
  else
    RC_ASSERT(s.r != r_start);
  // A kept start is within the keep tolerance; a far one is solved, to the solver's tolerance, up to
  // the round-off of -W⁻¹ q, which W's condition number amplifies and the natural map multiplies by up
  // to 1 + mu (nearly rank-one blocks gave 1.35119e-10 against a tolerance of 1.35102e-10).
  const double promised = near ? keep : tolerance;
  const double round_off =
      256.0 * (1.0 + mu) * std::numeric_limits<double>::epsilon() * W.norm() * W_inverse.norm() * q.norm();
  RC_ASSERT(natural_map_3d(s.r, W * s.r + q, mu).norm() <=
            std::max({promised, round_off, 1e-12 * (1.0 + q.norm())}));
}

// A block whose W_nn is positive but so small that -q_n / W_nn overflows makes the closed-form
// slide non-finite (inf × 0 = NaN in r_T): that candidate is not an answer, and whatever comes back
// is either finite or flagged as failed.
TEST(SignoriniCoulomb3D, OverflowingClosedFormSlideIsNeverReturnedAsSolved) {
  Matrix3d W = Matrix3d::Zero();
  W.diagonal() << 1e-320, 1.0, 1.0;
  const Vector3d q(-1.0, 0.0, 1.0);
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, 0.5, Vector3d::Zero(), 1e-10);
  EXPECT_TRUE(s.failed || s.r.allFinite()) << s.r.transpose();
}

// --- projection on the Coulomb cone, points computed by hand ---

TEST(CoulombConeProjection, PointInsideTheConeIsUnchanged) {
  const Vector3d x(2.0, 0.5, 0.5);  // |x_T| = 0.707 <= 0.5 * 2
  EXPECT_EQ(project_on_coulomb_cone(x, 0.5), x);
  const Vector3d boundary(2.0, 0.6, 0.8);  // |x_T| = 1 = 0.5 * 2
  EXPECT_TRUE(project_on_coulomb_cone(boundary, 0.5).isApprox(boundary, 1e-15));
}

TEST(CoulombConeProjection, PointInThePolarConeProjectsToZero) {
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(-2.0, 0.3, 0.4), 0.5), Vector3d::Zero());  // 0.5 * 0.5 <= 2
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(-1.0, 0.0, 0.0), 0.7), Vector3d::Zero());
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(-1.0, 1.0, 0.0), 0.0), Vector3d::Zero());  // mu = 0: half-line
  EXPECT_EQ(project_on_coulomb_cone(Vector3d::Zero(), 0.3), Vector3d::Zero());
}

TEST(CoulombConeProjection, PointOutsideBothConesFollowsTheProjectionFormula) {
  // x = (1, 3, 4), mu = 1: |x_T| = 5, a = (1 * 5 + 1) / 2 = 3, P = (3, 3 * 3/5, 3 * 4/5).
  const Vector3d p = project_on_coulomb_cone(Vector3d(1.0, 3.0, 4.0), 1.0);
  EXPECT_NEAR(p(0), 3.0, 1e-15);
  EXPECT_NEAR(p(1), 1.8, 1e-15);
  EXPECT_NEAR(p(2), 2.4, 1e-15);
  // x - P is normal to the cone at P.
  EXPECT_NEAR(p.dot(Vector3d(1.0, 3.0, 4.0) - p), 0.0, 1e-14);
  // x = (0, 0, 2), mu = 0.5: a = (0.5 * 2 + 0) / 1.25 = 0.8, P = (0.8, 0, 0.4).
  const Vector3d p2 = project_on_coulomb_cone(Vector3d(0.0, 0.0, 2.0), 0.5);
  EXPECT_NEAR(p2(0), 0.8, 1e-15);
  EXPECT_NEAR(p2(1), 0.0, 1e-15);
  EXPECT_NEAR(p2(2), 0.4, 1e-15);
  // mu = 0: projection on the half-line of normal reactions.
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(2.0, 1.0, -1.0), 0.0), Vector3d(2.0, 0.0, 0.0));
}

}  // namespace
}  // namespace lmgc::solver
