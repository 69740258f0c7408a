// Two reference checks of the linear mesh body (solver/fem/linear_body.hpp):
// - the patch test: a square patch of distorted elements whose boundary follows an affine
//   displacement u = A x reproduces it at every interior node and a uniform stress D ε at every
//   Gauss point, for every element type, to round-off (source: the patch test of Irons; tolerance
//   1e-10 relative: a sparse solve of a few dozen dofs);
// - the wave speed in a bar: a step velocity imposed at one end of a bar (E = 2e11, ρ = 7800,
//   ν = 0, 400 Q4 along its length, θ = ½) drives a front that reaches the bar's middle at
//   (L/2)/√(E/ρ) (source: the 1D wave equation); measured as the time the middle node's velocity
//   reaches half the imposed one, within 2 % (the mesh's dispersion spreads the front over a few
//   elements: 5 of 200 elements to the middle). Measured: −0.57 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/fem_meshes.hpp"

namespace lmgc::solver::fem {
namespace {

TEST(FemPatch, DistortedPatchesReproduceAnAffineDisplacementAndAUniformStress) {
  Eigen::Matrix2d a;
  a << 1e-3, 2e-3, -0.5e-3, 1.5e-3;
  for (ElementKind kind : {ElementKind::T3, ElementKind::Q4, ElementKind::T6, ElementKind::Q8}) {
    SCOPED_TRACE(std::string(element_entry(kind).name));
    for (Hypothesis h : {Hypothesis::plane_strain, Hypothesis::plane_stress}) {
      MeshBody body = test::rectangle(kind, 3, 3, 2.0, 2.0, Material{1e9, 0.3, 0.0}, h);
      const std::size_t nodes = body.nodes();
      // Interior nodes moved by up to 0.08 (a cell is 0.67 wide): distorted, never inverted.
      std::vector<std::int32_t> boundary;
      for (std::size_t i = 0; i < nodes; ++i) {
        double& x = body.coordinates[2 * i];
        double& y = body.coordinates[2 * i + 1];
        if (x == 0.0 || y == 0.0 || x == 2.0 || y == 2.0) {
          boundary.insert(boundary.end(),
                          {static_cast<std::int32_t>(2 * i), static_cast<std::int32_t>(2 * i + 1)});
          continue;
        }
        const double dx = 0.08 * std::sin(3.7 * x + 1.3 * y), dy = 0.08 * std::cos(2.1 * x - 4.3 * y);
        x += dx;
        y += dy;
      }
      LinearBodyMatrices m;
      std::string error;
      ASSERT_TRUE(assemble(body, m, error)) << error;
      LinearThetaScheme scheme;
      ASSERT_TRUE(scheme.prepare(m, 1.0, 1.0, 0.0, 0.0, boundary));
      const auto n = static_cast<Eigen::Index>(body.dofs());
      const auto affine = [&](std::size_t i) {
        return Eigen::Vector2d(a * Eigen::Vector2d(body.coordinates[2 * i], body.coordinates[2 * i + 1]));
      };
      std::vector<DrivenVelocity> driven;
      for (std::int32_t d : boundary) driven.push_back({d, affine(static_cast<std::size_t>(d / 2))(d % 2)});
      Eigen::VectorXd v;
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
      scheme.free_velocity(zero, zero, zero, driven, v);
      const Eigen::VectorXd u = scheme.displacement(zero, zero, v);  // θ = 1, h = 1: u = v
      for (std::size_t i = 0; i < nodes; ++i) {
        EXPECT_NEAR(u(static_cast<Eigen::Index>(2 * i)), affine(i).x(), 1e-12);
        EXPECT_NEAR(u(static_cast<Eigen::Index>(2 * i + 1)), affine(i).y(), 1e-12);
      }
      // The stress at every Gauss point of every element: D ε with ε = (a00, a11, a01 + a10).
      const Eigen::MatrixXd d = elasticity_matrix(h, 1e9, 0.3);
      const Eigen::Vector3d uniform = d * Eigen::Vector3d(a(0, 0), a(1, 1), a(0, 1) + a(1, 0));
      for (const MeshElement& element : body.elements)
        with_element(element.kind, [&](auto shape) {
          using E = decltype(shape);
          if constexpr (E::kDimension != 2)
            return;
          else {
            NodeCoordinates<E> x;
            Eigen::Matrix<double, E::kNodes * 2, 1> ue;
            for (int k = 0; k < E::kNodes; ++k) {
              const auto node = static_cast<std::size_t>(element.nodes[static_cast<std::size_t>(k)]);
              x.row(k) << body.coordinates[2 * node], body.coordinates[2 * node + 1];
              ue.template segment<2>(2 * k) = u.segment<2>(static_cast<Eigen::Index>(2 * node));
            }
            const QuadratureRule<2> q = quadrature<2>(element_entry(element.kind).stiffness_rule);
            for (int p = 0; p < q.size(); ++p) {
              const auto g = point_geometry<E>(x, q.points[static_cast<std::size_t>(p)],
                                               q.weights[static_cast<std::size_t>(p)], h);
              ASSERT_TRUE(g.has_value());
              const Eigen::VectorXd stress = d * (strain_matrix<E>(*g, h) * ue);
              EXPECT_LE((stress - uniform).norm(), 1e-10 * uniform.norm());
            }
          }
        });
    }
  }
}

TEST(FemWave, AFrontCrossesABarAtTheBarWaveSpeed) {
  const double young = 2e11, density = 7800.0, length = 1.0;
  const int cells = 400;
  const MeshBody body = test::rectangle(ElementKind::Q4, cells, 1, length, length / cells,
                                        Material{young, 0.0, density}, Hypothesis::plane_stress);
  LinearBodyMatrices m;
  std::string error;
  ASSERT_TRUE(assemble(body, m, error)) << error;
  const double speed = std::sqrt(young / density), h = 0.25 * (length / cells) / speed;
  std::vector<std::int32_t> pushed;
  std::size_t middle = 0;
  for (std::size_t i = 0; i < body.nodes(); ++i) {
    if (body.coordinates[2 * i] == 0.0) pushed.push_back(static_cast<std::int32_t>(2 * i));
    if (std::abs(body.coordinates[2 * i] - 0.5 * length) < 1e-12 && body.coordinates[2 * i + 1] == 0.0)
      middle = i;
  }
  LinearThetaScheme scheme;
  ASSERT_TRUE(scheme.prepare(m, h, 0.5, 0.0, 0.0, pushed));
  const auto n = static_cast<Eigen::Index>(body.dofs());
  const double v0 = 1.0;
  std::vector<DrivenVelocity> driven;
  for (std::int32_t d : pushed) driven.push_back({d, v0});
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  double arrival = -1.0;
  double previous = 0.0;
  for (int step = 1; step <= 4 * cells && arrival < 0.0; ++step) {
    Eigen::VectorXd v_free;
    scheme.free_velocity(x, v, zero, driven, v_free);
    x = scheme.displacement(x, v, v_free);
    v = v_free;
    const double now = v(static_cast<Eigen::Index>(2 * middle));
    if (now >= 0.5 * v0) arrival = h * (step - 1 + (0.5 * v0 - previous) / (now - previous));
    previous = now;
  }
  const double expected = 0.5 * length / speed;
  std::printf("front at the middle after %.6e s; (L/2)/sqrt(E/rho) = %.6e s (%.2f %%)\n", arrival, expected,
              100.0 * (arrival - expected) / expected);
  EXPECT_NEAR(arrival, expected, 0.02 * expected);
}

}  // namespace
}  // namespace lmgc::solver::fem
