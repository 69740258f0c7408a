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

// Where a displacement cannot be evaluated: an element with a Gauss point where det F ≤ 0.
struct InvertedElement {
  std::size_t element = 0;  // 0-based
  int point = 0;            // 0-based, in the stiffness rule's order
};

// F_int(u) and, when `tangent` is given, K_t(u) of the whole body (dofs as MeshBody's). False with
// `inverted` set when an element is inverted at u.
bool large_strain_forces(const MeshBody& body, const Eigen::VectorXd& displacement, Eigen::VectorXd& internal,
                         Eigen::SparseMatrix<double>* tangent, InvertedElement& inverted);

// The Gauss points of element e at the displacement (empty when the element is inverted there).
std::vector<LargeStrainPoint> large_strain_points(const MeshBody& body, const Eigen::VectorXd& displacement,
                                                  std::size_t element);

}  // namespace lmgc::solver::fem
