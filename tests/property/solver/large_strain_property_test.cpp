// Properties of large strain in the total Lagrangian form (solver/fem/large_strain.hpp) with MatLib's
// neo-Hookean material, on random 2×2 meshes of Q4xxx or T3xxx and random displacements:
// - frame invariance: rotating the deformed body rigidly rotates its internal forces and leaves the
//   stored energy; a rigid rotation of the undeformed body gives no force and no energy;
// - the tangent is the derivative of the internal force (finite differences);
// - LMGC90's Newton loop (the deformable stages and mecaMAILx_ComputeResidueNorm) converges
//   quadratically on a smooth hyperelastic step (measured rate).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/fem/large_strain.hpp"
#include "solver/model/deformable_bodies.hpp"

namespace lmgc::solver::fem {
namespace {

double unit() {
  return *rc::gen::inRange(-1000, 1001) / 1000.0;
}

// An n × n grid on [0, size]², Q4xxx or two T3xxx per cell, nodes moved by at most 10 % of a cell.
MeshBody grid(int n, double size, bool triangles, bool jitter, Material material) {
  MeshBody body;
  body.hypothesis = Hypothesis::plane_strain;
  body.kinematics = Kinematics::total_lagrangian;
  body.lumped_mass = true;
  const double cell = size / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && i < n && j > 0 && j < n;
      body.coordinates.push_back(i * cell + (jitter && inner ? 0.1 * cell * unit() : 0.0));
      body.coordinates.push_back(j * cell + (jitter && inner ? 0.1 * cell * unit() : 0.0));
    }
  const auto node = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (triangles) {
        body.elements.push_back({ElementKind::T3, {node(i, j), node(i + 1, j), node(i + 1, j + 1)}, 0});
        body.elements.push_back({ElementKind::T3, {node(i, j), node(i + 1, j + 1), node(i, j + 1)}, 0});
      } else {
        body.elements.push_back(
            {ElementKind::Q4, {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)}, 0});
      }
    }
  body.materials.push_back(material);
  return body;
}

Material random_material() {
  return {1.0e6 * std::pow(10.0, unit()), 0.45 * (unit() + 1.0) / 2.0, 1.0e3, MaterialLaw::neo_hookean};
}

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

Eigen::VectorXd random_displacement(const MeshBody& body, double amplitude) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(body.dofs()));
  for (Eigen::Index k = 0; k < u.size(); ++k) u(k) = amplitude * unit();
  return u;
}

// u' such that X + u' = R(X + u).
Eigen::VectorXd rotated(const MeshBody& body, const Eigen::VectorXd& u, const Eigen::Matrix2d& r) {
  Eigen::VectorXd out(u.size());
  for (std::size_t a = 0; a < body.nodes(); ++a) {
    const Eigen::Vector2d x(body.coordinates[2 * a], body.coordinates[2 * a + 1]);
    const auto i = static_cast<Eigen::Index>(2 * a);
    out.segment<2>(i) = r * (x + u.segment<2>(i)) - x;
  }
  return out;
}

double energy(const MeshBody& body, const Eigen::VectorXd& u) {
  double w = 0.0;
  for (std::size_t e = 0; e < body.elements.size(); ++e)
    for (const LargeStrainPoint& p : large_strain_points(body, u, e)) w += p.internal.at(0);
  return w;
}

RC_GTEST_PROP(LargeStrainProperty, InternalForcesAreFrameInvariantUnderRigidRotation, ()) {
  const MeshBody body = grid(2, std::pow(10.0, unit()), *rc::gen::arbitrary<bool>(), true, random_material());
  const double size = body.coordinates[body.coordinates.size() - 1];
  const Eigen::VectorXd u = random_displacement(body, 0.05 * size);
  const Eigen::Matrix2d r = rotation(std::numbers::pi * unit());
  Eigen::VectorXd f, f_rotated;
  InvertedElement inverted;
  RC_ASSERT(large_strain_forces(body, u, f, nullptr, inverted));
  RC_ASSERT(large_strain_forces(body, rotated(body, u, r), f_rotated, nullptr, inverted));
  // Round-off is relative to the forces, or to the material's scale E·size when they vanish (a
  // displacement close to a rigid motion).
  const double modulus = body.materials[0].young * size;
  const double scale = f.cwiseAbs().maxCoeff() + 1e-3 * modulus;
  for (std::size_t a = 0; a < body.nodes(); ++a) {
    const auto i = static_cast<Eigen::Index>(2 * a);
    RC_ASSERT((f_rotated.segment<2>(i) - r * f.segment<2>(i)).cwiseAbs().maxCoeff() <= 1e-10 * scale);
  }
  const double w = energy(body, u);
  RC_ASSERT(std::abs(energy(body, rotated(body, u, r)) - w) <= 1e-10 * (std::abs(w) + 1e-3 * modulus * size));
  // The undeformed body rotated: no force, no energy (round-off of the material's scale).
  Eigen::VectorXd f_rigid;
  RC_ASSERT(large_strain_forces(body, rotated(body, Eigen::VectorXd::Zero(u.size()), r), f_rigid, nullptr,
                                inverted));
  RC_ASSERT(f_rigid.cwiseAbs().maxCoeff() <= 1e-12 * modulus);
}

RC_GTEST_PROP(LargeStrainProperty, TangentIsTheDerivativeOfTheInternalForce, ()) {
  const MeshBody body = grid(2, 1.0, *rc::gen::arbitrary<bool>(), true, random_material());
  const Eigen::VectorXd u = random_displacement(body, 0.05);
  Eigen::VectorXd f;
  Eigen::SparseMatrix<double> k;
  InvertedElement inverted;
  RC_ASSERT(large_strain_forces(body, u, f, &k, inverted));
  const Eigen::MatrixXd dense(k);
  RC_ASSERT((dense - dense.transpose()).cwiseAbs().maxCoeff() <= 1e-10 * dense.cwiseAbs().maxCoeff());
  const double step = 1e-7;
  double worst = 0.0;
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    Eigen::VectorXd plus = u, minus = u, f_plus, f_minus;
    plus(j) += step;
    minus(j) -= step;
    RC_ASSERT(large_strain_forces(body, plus, f_plus, nullptr, inverted));
    RC_ASSERT(large_strain_forces(body, minus, f_minus, nullptr, inverted));
    worst = std::max(worst, ((f_plus - f_minus) / (2.0 * step) - dense.col(j)).cwiseAbs().maxCoeff());
  }
  RC_ASSERT(worst <= 1e-5 * dense.cwiseAbs().maxCoeff());
}

TEST(LargeStrainProperty, InvertedElementIsNamedWithItsGaussPoint) {
  const MeshBody body = grid(2, 1.0, false, false, {1.0e6, 0.3, 1.0, MaterialLaw::neo_hookean});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body.dofs()));
  u(2 * 4) = 0.9;  // the middle node pushed through the first element's right side
  u(2 * 4 + 1) = -0.9;
  Eigen::VectorXd f;
  InvertedElement inverted;
  EXPECT_FALSE(large_strain_forces(body, u, f, nullptr, inverted));
  EXPECT_EQ(inverted.element, 0u);
  EXPECT_TRUE(large_strain_points(body, u, 0).empty());
}

// LMGC90's loop on one step of a 4 × 4 Q4 block stretched by 20 % (its bottom held, its top driven
// upwards, h = 1, θ = 1: nearly static): the residue norms of the iterations fall quadratically
// once close — each at most 10 × the square of the one before (measured: the exponent
// log n_{k+1} / log n_k is above 1.9).
TEST(LargeStrainProperty, NewtonLoopConvergesQuadraticallyNearTheSolution) {
  DeformableBodies d;
  MeshBody body = grid(4, 1.0, false, false, {1.0e6, 0.3, 1.0, MaterialLaw::neo_hookean});
  d.meshes.bodies.push_back(body);
  d.meshes.matlib.push_back(true);
  std::string error;
  std::size_t failed_body = 0, failed_element = 0;
  ASSERT_TRUE(initialise_mesh_states(d, error, failed_body, failed_element)) << error;
  MeshBodyState& s = d.states[0];
  for (int i = 0; i <= 4; ++i)
    for (int c = 0; c < 2; ++c) {
      const auto add = [&](int node, double velocity) {
        DrivenDof2D dd;
        dd.body = 0;
        dd.dof = 2 * node + c;
        dd.coefficients = {velocity, 0, 0, 0, 1, 0};
        d.driven.push_back(dd);
        s.velocity_driven.push_back(dd.dof);
      };
      add(i, 0.0);                         // bottom row held
      add(4 * 5 + i, c == 1 ? 0.2 : 0.0);  // top row moved up by 0.2 in the step
    }
  StepContext step;
  step.h = 1.0;
  step.theta = 1.0;
  step.time = 1.0;
  step.step = 1;
  increment_deformable(d, step);
  external_forces_deformable(d, Eigen::Vector3d::Zero(), step);
  std::vector<double> norms;
  for (int k = 0; k < 12; ++k) {
    free_velocity_deformable(d, step);
    dof_deformable(d, step);
    ASSERT_FALSE(inverted_element(d));
    if (k > 0) norms.push_back(compute_residue_norm(d, step));
    if (!norms.empty() && norms.back() < 1e-14) break;
  }
  ASSERT_GE(norms.size(), 3u);
  EXPECT_LT(norms.back(), 1e-12);
  double exponent = 10.0;
  for (std::size_t k = 0; k + 1 < norms.size(); ++k)
    if (norms[k] < 1e-2 && norms[k + 1] > 1e-13) {
      EXPECT_LE(norms[k + 1], 10.0 * norms[k] * norms[k]) << "iteration " << k;
      exponent = std::min(exponent, std::log(norms[k + 1]) / std::log(norms[k]));
    }
  std::printf("residue norms:");
  for (double n : norms) std::printf(" %.3e", n);
  std::printf("\nsmallest convergence exponent %.2f\n", exponent);
  EXPECT_GT(exponent, 1.9);
}

}  // namespace
}  // namespace lmgc::solver::fem
