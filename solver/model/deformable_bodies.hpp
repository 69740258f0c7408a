#pragma once
// The deformable (MAILx) bodies of a run and their state: the linear elastic meshes
// (mesh_bodies.hpp), each with its assembled matrices, its θ-scheme (solver/fem/linear_body.hpp),
// its nodal displacements and velocities at the beginning and the end of the step, its free
// velocity and external force; the driven dofs of their nodes (DRV_DOF.DAT); Rayleigh damping.
// The stages of the step (solver/integrator/step_2d.cpp) call the functions below for them, next
// to the rigid bodies': docs/lmgc90-facts/mailx-2d.md §4.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "solver/fem/large_strain.hpp"
#include "solver/model/driven_dofs.hpp"
#include "solver/model/mesh_bodies.hpp"
#include "solver/model/step_context.hpp"

namespace lmgc::solver {

struct MeshBodyState {
  Eigen::VectorXd x, x_begin, v, v_begin, v_free, f_ext;
  // At the end of the step (LMGC90's ComputeField): F_int = K X + C V, F_inert = M(V − V_begin)/h,
  // residue = F_int + F_inert − I_reac/h − F_ext.
  Eigen::VectorXd internal_force, inertial_force, residue;
  // I_reac: the contact impulses of the step on the nodes (Σ Hᵀ r), set by the contact solve;
  // V = V_free + K̂⁻¹ I_reac (mailx-2d-contact.md §8.6). Empty when no contact touched the body.
  Eigen::VectorXd contact_impulse;
  // K̂⁻¹ condensed on the dofs of the body's contactor nodes (LMGC90's precon W, one solve per dof:
  // mailx-2d-contact.md §8.5), built when a contact first needs it after K̂ was factorised.
  Eigen::MatrixXd contact_compliance;
  std::vector<std::int32_t> compliance_row;  // dof → row of contact_compliance, or −1
  fem::LinearBodyMatrices matrices;
  fem::LinearThetaScheme scheme;
  double prepared_h = 0.0, prepared_theta = 0.0;  // K̂ is factorised for these (0: not yet)
  std::vector<std::int32_t> velocity_driven;      // dofs whose velocity DRV_DOF.DAT imposes
  // LMGC90's AssembleMechanicalRHS at the velocity V the iteration starts from, as an impulse:
  // R(V) = M(V_begin − V) + h(F_ext − F_int(X_θ) − C V_θ), X_θ = X_begin + θh((1 − θ)V_begin + θV),
  // V_θ = θV + (1 − θ)V_begin (mailx-2d-large-strain.md §3). mecaMAILx_ComputeResidueNorm reads it.
  Eigen::VectorXd rhs;
  // A large-strain body whose last evaluation met an inverted element (det F ≤ 0 at a Gauss point):
  // the step cannot be completed from this iterate.
  std::optional<fem::InvertedElement> inverted;
  bool large_strain = false;  // K̂ is rebuilt from the tangent K_t at every iteration
  // A large-strain body's ComputeBulk: F_int and K_t at X_θ of the iterate (LMGC90's element arrays),
  // which the iteration's ComputeFreeVelocity and a Rayleigh damping call then use.
  Eigen::VectorXd bulk_force;
  Eigen::SparseMatrix<double> bulk_tangent;
  bool bulk_current = false;  // computed for the iterate in progress
  // C of a large-strain body: αM + βK_t as they were at mecaMAILx_ComputeRayleighDamping (empty: none).
  Eigen::SparseMatrix<double> damping;
  // J2 plasticity's Gauss-point states (fem::kJ2Internal per point) at the beginning of the step and at
  // the last ComputeDof's X, and the Cauchy stresses there (4 per point): what GPV files write.
  std::vector<double> history_begin, history, point_stress;
};

struct DeformableBodies {
  MeshBodies meshes;
  std::vector<MeshBodyState> states;
  std::vector<DrivenDof2D> driven;  // body: mesh index; dof: node × D + component
  // mecaMAILx_ComputeRayleighDamping(alpha, beta): C = αM + βK on every body (mailx-2d.md §4.2).
  double rayleigh_alpha = 0.0, rayleigh_beta = 0.0;
  bool empty() const { return states.empty(); }
};

// Meshes, matrices (an element whose Jacobian is not positive: L2019 at its line), driven dofs,
// the initial state of DOF.INI. False with diagnostics when the case cannot run.
bool build_deformable_bodies(const case_folder::CaseFiles& files, fem::Hypothesis hypothesis,
                             DeformableBodies& out, grammar::DiagnosticSink& sink);

// Assembles each mesh's matrices and sets its state to rest at the reference configuration. False,
// with the body and element (0-based) and what is wrong, when an element has a Gauss point whose
// Jacobian is not positive.
bool initialise_mesh_states(DeformableBodies& d, std::string& error, std::size_t& failed_body,
                            std::size_t& failed_element);

// The stages (each over every deformable body).
// V ← V_begin (and X ← X_begin + hV_begin for a large-strain body: its first iterate).
void increment_deformable(DeformableBodies& d, const StepContext& step);
// ComputeBulk: F_int and K_t of each large-strain body at X_θ of its iterate (nothing for linear
// bodies, whose stiffness is assembled once).
void bulk_deformable(DeformableBodies& d, const StepContext& step);
// mecaMAILx_ComputeRayleighDamping(α, β): C = αM + βK, K a large-strain body's tangent of its last
// ComputeBulk (0 before the first), a linear body's stiffness.
void set_rayleigh_damping(DeformableBodies& d, double alpha, double beta);
// F_ext = M g + driven forces θ-averaged over the step.
void external_forces_deformable(DeformableBodies& d, const Eigen::Vector3d& gravity, const StepContext& step);
// V_free from the residual at V_begin; K̂ refactorised when h or θ changed; driven velocities at t.
// Throws std::runtime_error naming the body when K̂ is singular on its free dofs.
void free_velocity_deformable(DeformableBodies& d, const StepContext& step);
// Large-strain bodies iterate (LMGC90's Newton loop): V_free = V + K̂_t⁻¹ R(V) from the current
// iterate V, K̂_t = M + (θh)² K_t(X_θ) factorised at every call.
// V = V_free + K̂⁻¹ I_reac (V_free without contact); X = X_begin + h((1 − θ)V_begin + θV).
void dof_deformable(DeformableBodies& d, const StepContext& step);
// mecaMAILx_ComputeResidueNorm: the largest over bodies of ‖R + I_reac‖∞ (driven dofs left out)
// over max(h‖F_int‖∞, h‖F_inert‖∞, h‖F_ext‖∞) (1 when that is ≤ 0.1); +∞ when a body is inverted.
// Each body's residue becomes R + I_reac with its driven dofs zeroed, as LMGC90 overwrites it.
double compute_residue_norm(DeformableBodies& d, const StepContext& step);
// The first inverted element met in the step's last evaluation: (body, element), if any.
std::optional<std::pair<std::size_t, fem::InvertedElement>> inverted_element(const DeformableBodies& d);
// Builds each body's contact_compliance on the nodes of its contactors, where not built since K̂
// was last factorised.
void prepare_contact_compliance(DeformableBodies& d);
void update_deformable(DeformableBodies& d);  // begin ← end

// ½VᵀMV of every deformable body.
double kinetic_energy(const DeformableBodies& d);

}  // namespace lmgc::solver
