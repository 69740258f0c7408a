// Properties of the 3D law local problems that are not plain Signorini–Coulomb
// (solver/nlgs/law_local_problem_3d): tension-only wires, bilateral rods and cohesive zones, each
// solved with random Delassus blocks, free velocities and law data. docs/lmgc90-facts/contact-laws.md §3.4,
// §3.5.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "solver/nlgs/law_local_problem_3d.hpp"
#include "tests/support/random_blocks.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using test::in_range;

using test::random_q;
using test::random_spd;

Interaction3D spring(LocalForm3D form) {
  Interaction3D c;
  c.W = random_spd();
  c.form = form;
  c.normal_compliance = in_range(0.0, 10.0);
  return c;
}

RC_GTEST_PROP(WireLocalProblem, WirePullsOnlyWhenStretchedAndThenHoldsItsSpringLaw, ()) {
  const Interaction3D c = spring(LocalForm3D::wire);
  const LawState3D none;  // springs read none of it
  const Vector3d q = random_q();
  const Vector3d r = solve_law_form_3d(c, none, q, Vector3d::Zero(), 1e-12);
  const Vector3d uu = q + c.W * r;
  RC_ASSERT(r(0) == 0.0 && r(2) == 0.0);
  RC_ASSERT(r(1) <= 0.0);  // traction only
  RC_ASSERT(law_form_residual_3d(c, none, r, uu).norm() <= 1e-12 * (1.0 + q.norm()));
  RC_ASSERT((law_form_status_3d(c, none, r, uu) == ContactStatus::stick) == (r(1) < 0.0));
}

RC_GTEST_PROP(WireLocalProblem, RodHoldsItsSpringLawInTensionAndCompression, ()) {
  const Interaction3D c = spring(LocalForm3D::rod);
  const LawState3D none;
  const Vector3d q = random_q();
  const Vector3d r = solve_law_form_3d(c, none, q, Vector3d::Zero(), 1e-12);
  const Vector3d uu = q + c.W * r;
  RC_ASSERT(std::abs(uu(1) + c.normal_compliance * r(1)) <= 1e-12 * (1.0 + q.norm()));
  RC_ASSERT(law_form_residual_3d(c, none, r, uu).norm() <= 1e-12 * (1.0 + q.norm()));
}

RC_GTEST_PROP(CohesiveLocalProblem, ReactionMinusCohesionSatisfiesSignoriniCoulombWithinTolerance, ()) {
  Interaction3D c;
  c.W = random_spd();
  c.form = LocalForm3D::cohesive;
  c.mu = in_range(0.0, 2.0);
  const double kt = -in_range(0.0, 10.0), kn = -in_range(0.0, 10.0);
  LawState3D zone;
  zone.cohesive_slope = Vector3d(kt, kn, kt);
  zone.cohesive_shift = Vector3d(in_range(-1.0, 1.0), 0.0, in_range(-1.0, 1.0));
  const Vector3d q = random_q();
  const double tolerance = 1e-10 * (1.0 + q.norm());
  const Vector3d r = solve_law_form_3d(c, zone, q, Vector3d::Zero(), tolerance);
  const Vector3d uu = q + c.W * r;
  // The cohesive part is the linear traction of the auxiliary velocity; the rest lies in the cone.
  const Vector3d rr = r - zone.cohesive_shift - zone.cohesive_slope.cwiseProduct(uu);
  RC_ASSERT(rr(1) >= -tolerance);
  RC_ASSERT(std::hypot(rr(0), rr(2)) <= c.mu * rr(1) + 10.0 * tolerance);
  RC_ASSERT(law_form_residual_3d(c, zone, r, uu).norm() <= 10.0 * tolerance);
}

}  // namespace
}  // namespace lmgc::solver
