#pragma once
// Large strain in the total Lagrangian form (MODELS.DAT 'kine_ large', 'form_ TotaL'), in 2D: at each
// Gauss point of the stiffness rule, on the reference geometry, the deformation gradient
// F = I + B_F u in LMGC90's component order (F11, F12, F21, F22, F33), F33 = 1 in plane strain and
// 1 + u_r/R in axisymmetry; the material gives the first Piola–Kirchhoff stress P in the same order
// and its tangent dP/dF; the element's internal force is ∫ B_Fᵀ P dV₀ and its tangent stiffness
// ∫ B_Fᵀ (dP/dF) B_F dV₀ (LMGC90's BULK_GD_ISO, docs/lmgc90-facts/mailx-2d-large-strain.md §1).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <vector>

#include "solver/fem/linear_body.hpp"

namespace lmgc::solver::fem {

using GradientVector = Eigen::Matrix<double, 5, 1>;  // (11, 12, 21, 22, 33)

// What one Gauss point holds at a displacement: P and F in the order above, the material's
// internal variables (neo-Hookean: the stored energy W).
struct LargeStrainPoint {
  GradientVector stress = GradientVector::Zero();
  GradientVector gradient = GradientVector::Zero();
  std::vector<double> internal;
};

// Where a displacement cannot be evaluated: an element with a Gauss point where det F ≤ 0, or (J2
// plasticity) whose return mapping did not converge in LMGC90's 50 iterations.
struct InvertedElement {
  std::size_t element = 0;  // 0-based
  int point = 0;            // 0-based, in the stiffness rule's order
  bool return_mapping = false;
};

// The Gauss-point history of a body whose material keeps one (J2 plasticity: kJ2Internal values per
// point, the points of each element in order): the state at the beginning of the step, read; and,
// when given, where the state and the Cauchy stress (4 per point) at the displacement go.
struct PointHistory {
  const std::vector<double>* begin = nullptr;
  std::vector<double>* end = nullptr;
  std::vector<double>* stress = nullptr;
};

// F_int(u) and, when `tangent` is given, K_t(u) of the whole body (dofs as MeshBody's). False with
// `inverted` set when an element cannot be evaluated at u.
bool large_strain_forces(const MeshBody& body, const Eigen::VectorXd& displacement, Eigen::VectorXd& internal,
                         Eigen::SparseMatrix<double>* tangent, InvertedElement& inverted,
                         const PointHistory& history = {});

// What LMGC90 reports as the internal force of a body with J2 plasticity (its ComputeField's
// Stress2Fint): Σ Bᵀσ dV with the small-strain B and the volume of the reference configuration
// and the stored Cauchy stresses (4 per point) — not the force of the Newton iteration, which
// integrates on the current configuration; Fint EVOLUTION and the residue norm's scale read it.
Eigen::VectorXd reported_internal_force(const MeshBody& body, const std::vector<double>& stress);

// The history of a body with J2 plasticity at rest (LMGC90's first step: Cp⁻¹ = I); empty otherwise.
std::vector<double> initial_point_history(const MeshBody& body);
bool keeps_point_history(const MeshBody& body);

// The Gauss points of element e at the displacement (empty when the element is inverted there).
std::vector<LargeStrainPoint> large_strain_points(const MeshBody& body, const Eigen::VectorXd& displacement,
                                                  std::size_t element);

}  // namespace lmgc::solver::fem
