#pragma once
// Rigid 2D bodies (RBDY2) as flat arrays indexed by body id. Degrees of freedom (x, y, θ) of the
// centre of inertia. docs/lmgc90-facts/numerics.md §1.1.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace lmgc::solver {

struct RigidBodies2D {
  std::vector<Eigen::Vector3d>
      reference;  // (n) coordinates of the centre of inertia in BODIES.DAT [m, m, rad]
  std::vector<Eigen::Vector3d> displacement_begin;  // (n) X at t_begin: displacement from reference
  std::vector<Eigen::Vector3d> displacement;        // (n) X at t_end
  std::vector<Eigen::Vector3d> velocity_begin;      // (n) V at t_begin [m/s, m/s, rad/s]
  std::vector<Eigen::Vector3d> velocity;            // (n) V at t_end (during NLGS: V_free + M⁻¹ I)
  std::vector<Eigen::Vector3d> velocity_free;       // (n) free velocity of the θ-scheme
  std::vector<Eigen::Vector3d> inverse_mass;        // (n) (1/m, 1/m, 1/I); 0 on driven dofs
  std::vector<Eigen::Vector3d> external_force;      // (n) θ-averaged external force of the step [N, N, N·m]
  std::vector<Eigen::Vector3d> impulse;             // (n) contact impulse of the step (Ireac) [N·s]
  std::vector<double> mass;                         // (n) [kg]
  std::vector<double> inertia;                      // (n) [kg·m²]
  std::vector<double> avrd;                         // (n) equivalent radius (mass = ρ π avrd²) [m]
  std::vector<double> gyrd;                         // (n) gyration radius (I = m gyrd²) [m]
  std::vector<int> bulk_behav;                      // (n) index into the bulk behaviours
  std::vector<std::uint8_t> driven_mask;            // (n) bit d set when dof d has an imposed velocity
  std::vector<std::uint8_t> visible;                // (n) 0 once a body left the bounds: frozen, not detected

  std::size_t size() const { return reference.size(); }
  void resize(std::size_t n);
};

}  // namespace lmgc::solver
