#pragma once
// The deformable (MAILx) bodies of a run and their state: the linear elastic meshes
// (mesh_bodies.hpp), each with its assembled matrices, its θ-scheme (solver/fem/linear_body.hpp),
// its nodal displacements and velocities at the beginning and the end of the step, its free
// velocity and external force; the driven dofs of their nodes (DRV_DOF.DAT); Rayleigh damping.
// The stages of the step (solver/integrator/step_2d.cpp) call the functions below for them, next
// to the rigid bodies': docs/lmgc90-facts/mailx-2d.md §4.
#include <Eigen/Core>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
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
void increment_deformable(DeformableBodies& d);  // V ← V_begin
// F_ext = M g + driven forces θ-averaged over the step.
void external_forces_deformable(DeformableBodies& d, const Eigen::Vector3d& gravity, const StepContext& step);
// V_free from the residual at V_begin; K̂ refactorised when h or θ changed; driven velocities at t.
// Throws std::runtime_error naming the body when K̂ is singular on its free dofs.
void free_velocity_deformable(DeformableBodies& d, const StepContext& step);
// V = V_free + K̂⁻¹ I_reac (V_free without contact); X = X_begin + h((1 − θ)V_begin + θV).
void dof_deformable(DeformableBodies& d, const StepContext& step);
// Builds each body's contact_compliance on the nodes of its contactors, where not built since K̂
// was last factorised.
void prepare_contact_compliance(DeformableBodies& d);
void update_deformable(DeformableBodies& d);  // begin ← end

// ½VᵀMV of every deformable body.
double kinetic_energy(const DeformableBodies& d);

}  // namespace lmgc::solver
