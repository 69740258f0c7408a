#pragma once
// The Gauss-point values LMGC90 writes for a linear elastic MAILx body (GPV.OUT.n, GPV.LAST): per
// element, per Gauss point of its stiffness rule, the stress and the strain of the displacement X on
// the reference geometry, in LMGC90's component order (docs/lmgc90-facts/mailx-2d.md §5):
// - its own elasticity ('isext no___'): σ (xx, yy, xy, zz), ε (xx, yy, γxy, 0) in 2D (σzz = ν(σxx + σyy)
//   in plane strain, 0 in plane stress; axisymmetric (rr, zz, rz, θθ)); 3D (xx, yy, zz, xy, yz, zx);
// - MatLib's ('isext MatL_'): σ (xx, xy, yy, zz), ε (xx, γxy, yy, zz), then a line with the elastic
//   energy density ½ σ:ε; 3D (xx, xy, yy, xz, yz, zz).
#include <Eigen/Core>

#include "grammar/gpv/ast.hpp"
#include "solver/fem/linear_body.hpp"
#include "solver/model/deformable_bodies.hpp"

namespace lmgc::solver {

// body_number: the MAILx rank (1-based) written on the block.
grammar::GpvBody gauss_point_values(const fem::MeshBody& body, bool matlib,
                                    const Eigen::VectorXd& displacement, int body_number);

// The mean over an element's Gauss points of its 2D strain (xx, yy, γxy, zz) and stress (xx, yy, xy,
// zz) in LMGC90's own order, for the display's nodal fields.
void element_mean_strain_stress(const fem::MeshBody& body, const Eigen::VectorXd& displacement,
                                std::size_t element, Eigen::Vector4d& strain, Eigen::Vector4d& stress);

// GPV.OUT.n / GPV.LAST of a scene's deformable bodies at its current displacements.
grammar::GpvFile gauss_point_values_file(const DeformableBodies& bodies, long step, double time);

}  // namespace lmgc::solver
