#pragma once
// A linear elastic mesh body (MAILx with small strain and linear isotropic elasticity): its
// assembled stiffness and mass, and LMGC90's Moreau–Jean θ-scheme on its nodal velocities
// (docs/lmgc90-facts/numerics.md §1.3): iteration matrix K̂ = M + θhC + θ²h²K with Rayleigh damping
// C = αM + βK, factorised once while h, θ and the matrices stay; free velocity from the step's
// residual at V = V_begin (one solve: the problem is linear); V = V_free + K̂⁻¹ I for a contact
// impulse I; X = X_begin + h((1 − θ)V_begin + θV). Driven velocities are imposed by elimination: a
// driven dof takes its value, the others see it through K̂'s coupling.
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/fem/element_catalogue.hpp"
#include "solver/fem/element_matrices.hpp"
#include "solver/fem/finite_strain_plasticity.hpp"

namespace lmgc::solver::fem {

// The behaviour a Gauss point follows: linear elasticity (small strain), or MatLib's compressible
// neo-Hookean potential (large strain, neo_hookean.hpp).
// or LMGC90's own J2 plasticity (large strain on Q4P0x, finite_strain_plasticity.hpp).
enum class MaterialLaw : std::uint8_t { linear_elastic, neo_hookean, j2_plasticity };

struct Material {
  double young = 0.0;
  double poisson = 0.0;
  double density = 0.0;
  MaterialLaw law = MaterialLaw::linear_elastic;
  J2Parameters plasticity{};  // j2_plasticity
};

// MODELS.DAT 'kine_': small strain, or large strain in the total Lagrangian form ('form_ TotaL':
// the deformation gradient F on the reference configuration, large_strain.hpp).
enum class Kinematics : std::uint8_t { small_strain, total_lagrangian };

struct MeshElement {
  ElementKind kind = ElementKind::T3;
  std::array<std::int32_t, 8> nodes{};  // 0-based, the element's node count used
  std::int32_t material = 0;
};

struct MeshBody {
  int dimension = 2;
  Hypothesis hypothesis = Hypothesis::plane_strain;
  std::vector<double> coordinates;  // reference positions, node after node (D values each)
  std::vector<MeshElement> elements;
  std::vector<Material> materials;
  bool lumped_mass = false;  // MODELS.DAT 'mstrg lump_'
  Kinematics kinematics = Kinematics::small_strain;
  std::size_t nodes() const { return coordinates.size() / static_cast<std::size_t>(dimension); }
  std::size_t dofs() const { return coordinates.size(); }
};

struct LinearBodyMatrices {
  Eigen::SparseMatrix<double> stiffness, mass;
};

// Assembles K and M. False, with `error` naming the element (1-based), when an element has a Gauss
// point whose Jacobian is not positive.
bool assemble(const MeshBody& body, LinearBodyMatrices& matrices, std::string& error,
              std::size_t* failed_element = nullptr);

struct DrivenVelocity {
  std::int32_t dof = 0;  // node × D + component
  double value = 0.0;    // the velocity at the end of the step
};

class LinearThetaScheme {
 public:
  // Factorises K̂ for the step h and θ, with the dofs of `driven` eliminated. False when K̂ is not
  // positive definite on the free dofs (a body free to move rigidly without mass, ...).
  bool prepare(const LinearBodyMatrices& matrices, double h, double theta, double rayleigh_alpha,
               double rayleigh_beta, std::span<const std::int32_t> driven_dofs);
  // The same with the stiffness (a tangent) and the damping matrix C given (empty: none).
  bool prepare(const Eigen::SparseMatrix<double>& mass, const Eigen::SparseMatrix<double>& stiffness,
               double h, double theta, const Eigen::SparseMatrix<double>& damping,
               std::span<const std::int32_t> driven_dofs);
  // V_free for the step from the state at its beginning and the external force (averaged over it).
  void free_velocity(const Eigen::VectorXd& x_begin, const Eigen::VectorXd& v_begin,
                     const Eigen::VectorXd& f_ext, std::span<const DrivenVelocity> driven,
                     Eigen::VectorXd& v_free) const;
  // ΔV = K̂⁻¹ (R − K̂ ΔV_d) + ΔV_d: the increment of a residual R with the driven dofs' increments
  // ΔV_d (zero on the free dofs) imposed (the Newton iteration of a nonlinear body).
  Eigen::VectorXd increment(const Eigen::VectorXd& residual, const Eigen::VectorXd& imposed) const {
    return solve_free(residual - iteration_ * imposed) + imposed;
  }
  // ΔV = K̂⁻¹ I: the velocity a contact impulse I adds (0 on driven dofs).
  Eigen::VectorXd response(const Eigen::VectorXd& impulse) const;
  // X = X_begin + h((1 − θ)V_begin + θV).
  Eigen::VectorXd displacement(const Eigen::VectorXd& x_begin, const Eigen::VectorXd& v_begin,
                               const Eigen::VectorXd& v) const;
  // K X + C V: the internal force of displacement X and velocity V.
  Eigen::VectorXd internal_force(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    return stiffness_ * x + damping_ * v;
  }
  const Eigen::SparseMatrix<double>& damping() const { return damping_; }
  double h() const { return h_; }
  double theta() const { return theta_; }

 private:
  Eigen::VectorXd solve_free(const Eigen::VectorXd& rhs) const;
  double h_ = 0.0, theta_ = 0.5;
  Eigen::SparseMatrix<double> stiffness_, mass_, damping_, iteration_;
  std::vector<std::int32_t> free_of_;  // dof → index among the free dofs, or −1 when driven
  std::vector<std::int32_t> free_dofs_;
  Eigen::SparseMatrix<double> iteration_free_;
  // Shared by copies (a scene may be copied); prepare() makes a new one.
  std::shared_ptr<const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> factor_;
  std::vector<int> pattern_outer_, pattern_inner_;  // the sparsity factor_ was analysed for
};

}  // namespace lmgc::solver::fem
