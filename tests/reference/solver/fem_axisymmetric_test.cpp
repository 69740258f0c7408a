// A thick-walled tube under internal pressure in axisymmetry (solver/fem, Hypothesis::axisymmetric):
// radii a = 1 and b = 2, pressure p = 1e6 Pa, E = 2e11, ν = 0.3, no axial strain (u_z = 0 on both
// ends of the slice). Lamé's solution (source: any elasticity text; the tube in plane strain):
// u_r(r) = (1 + ν) p a² / (E (b² − a²)) · ((1 − 2ν) r + b² / r). The pressure's nodal forces are
// p × the inner face's area with LMGC90's 2π (6.2831853, as the element integrals take it), so that
// the truncated 2π cancels. Tolerances, the meshes' errors with room: 1e-6 relative at both radii
// with 40 Q8 across the wall (measured 6.8e-9: the field a r + b/r is nearly quadratic over an
// element), 5e-4 with 40 Q4 (measured 1.0e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/fem_meshes.hpp"

namespace lmgc::solver::fem {
namespace {

double lame(double r) {
  const double a = 1.0, b = 2.0, p = 1e6, e = 2e11, nu = 0.3;
  return (1 + nu) * p * a * a / (e * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r);
}

void tube(ElementKind kind, double tolerance) {
  const int cells = 40;
  const double height = 0.05;
  MeshBody body =
      test::rectangle(kind, cells, 1, 1.0, height, Material{2e11, 0.3, 0.0}, Hypothesis::axisymmetric);
  for (std::size_t i = 0; i < body.nodes(); ++i) body.coordinates[2 * i] += 1.0;  // r from a = 1 to b = 2
  LinearBodyMatrices m;
  std::string error;
  ASSERT_TRUE(assemble(body, m, error)) << error;
  const auto n = static_cast<Eigen::Index>(body.dofs());
  std::vector<std::int32_t> axial;
  std::vector<std::pair<double, Eigen::Index>> inner;  // (z, node) on r = a
  for (std::size_t i = 0; i < body.nodes(); ++i) {
    axial.push_back(static_cast<std::int32_t>(2 * i + 1));  // u_z = 0 everywhere: no axial strain
    if (body.coordinates[2 * i] == 1.0)
      inner.emplace_back(body.coordinates[2 * i + 1], static_cast<Eigen::Index>(i));
  }
  std::sort(inner.begin(), inner.end());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  const double total = 1e6 * kAxisymmetricTwoPi * 1.0 * height;
  if (inner.size() == 2) {
    for (const auto& [z, node] : inner) f(2 * node) += total / 2.0;
  } else {  // quadratic edge: 1/6, 4/6, 1/6
    f(2 * inner[0].second) += total / 6.0;
    f(2 * inner[1].second) += 4.0 * total / 6.0;
    f(2 * inner[2].second) += total / 6.0;
  }
  LinearThetaScheme scheme;
  ASSERT_TRUE(scheme.prepare(m, 1.0, 1.0, 0.0, 0.0, axial));
  std::vector<DrivenVelocity> fixed;
  for (std::int32_t d : axial) fixed.push_back({d, 0.0});
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd v;
  scheme.free_velocity(zero, zero, f, fixed, v);
  double worst = 0.0;
  for (std::size_t i = 0; i < body.nodes(); ++i) {
    const double r = body.coordinates[2 * i];
    if (r != 1.0 && r != 2.0) continue;
    const double expected = lame(r);
    worst = std::max(worst, std::abs(v(static_cast<Eigen::Index>(2 * i)) - expected) / expected);
  }
  std::printf("%s: largest relative error of u_r at the radii %.2e\n",
              std::string(element_entry(kind).name).c_str(), worst);
  EXPECT_LE(worst, tolerance);
}

TEST(FemAxisymmetric, ATubeUnderPressureFollowsLame) {
  tube(ElementKind::Q8, 1e-6);
  tube(ElementKind::Q4, 5e-4);
}

}  // namespace
}  // namespace lmgc::solver::fem
