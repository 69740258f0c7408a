#pragma once
// Rigid 3D bodies (RBDY3) as flat arrays indexed by body id. Translation dofs of the centre of
// inertia in the global frame; rotation velocity in the body's principal inertia frame, whose
// orientation is carried by `frame` (columns = principal axes in global coordinates).
// docs/lmgc90-facts/numerics.md §1.2.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

using Vector6d = Eigen::Matrix<double, 6, 1>;

struct RigidBodies3D {
  std::vector<Eigen::Vector3d> reference;      // (n) centre of inertia in BODIES.DAT (cooref) [m]
  std::vector<Vector6d> displacement_begin;    // (n) X at t_begin: translation from reference; X(4:6) = 0
  std::vector<Vector6d> displacement;          // (n) X at t_end
  std::vector<Vector6d> velocity_begin;        // (n) V at t_begin: (v global [m/s], ω body axes [rad/s])
  std::vector<Vector6d> velocity;              // (n) V at t_end (during NLGS: V_free + M⁻¹ I)
  std::vector<Vector6d> velocity_free;         // (n) free velocity of the θ-scheme
  std::vector<Vector6d> inverse_mass;          // (n) (1/m ×3, 1/I1, 1/I2, 1/I3); 0 on driven dofs
  std::vector<Vector6d> external_force;        // (n) θ-averaged external force + gyroscopic torque
  std::vector<Vector6d> impulse;               // (n) contact impulse of the step (Ireac), torque in body axes
  std::vector<Eigen::Matrix3d> frame_initial;  // (n) principal frame at t_begin (LocalFrameIni)
  std::vector<Eigen::Matrix3d> frame_detection;  // (n) frame at the detection configuration (LocalFrameTT)
  std::vector<Eigen::Matrix3d> frame;            // (n) frame at t_end (LocalFrame)
  std::vector<double> mass;                      // (n) [kg]
  std::vector<Eigen::Vector3d> inertia;          // (n) principal moments I1, I2, I3 [kg·m²]
  std::vector<int> bulk_behav;                   // (n) index into the bulk behaviours
  std::vector<std::uint8_t> driven_mask;         // (n) bit d set when dof d has an imposed velocity
  std::vector<std::uint8_t> visible;             // (n)

  std::size_t size() const { return reference.size(); }
  void resize(std::size_t n);
};

// Frame update of `update_inertia_frame33` (docs/lmgc90-facts/numerics.md §1.2): w = Σ spin_i e_i (spin in
// body axes, e_i the columns of `frame`).
//   linearised: e_i' = e_i + h w × e_i, then Gram–Schmidt (LMGC90's default scheme, method 1);
//   cayley:     e_i' = (I - h/2 [w]×)⁻¹ (I + h/2 [w]×) e_i (Hughes–Winget, `new_rotation_scheme`, method 2).
enum class FrameUpdate : std::uint8_t { linearised, cayley };
Eigen::Matrix3d update_frame(const Eigen::Matrix3d& frame, const Eigen::Vector3d& spin_body_axes, double h,
                             FrameUpdate method);

// Explicit gyroscopic torque at the beginning of the step, body axes:
// (-(I3 - I2) ω2 ω3, -(I1 - I3) ω1 ω3, -(I2 - I1) ω1 ω2).
Eigen::Vector3d gyroscopic_torque(const Eigen::Vector3d& inertia, const Eigen::Vector3d& omega);

// ½ m |v|² + ½ Σ I_i ω_i² at the end of the step [J].
double kinetic_energy(const RigidBodies3D& bodies);

}  // namespace lmgc::solver
