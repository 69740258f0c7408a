#pragma once
// Non-linear Gauss–Seidel over the 2D interactions of a step. spec: numerics.md §3-§4.
#include <string>
#include <vector>

#include "solver/bodies/rigid_bodies_2d.hpp"
#include "solver/model/interaction_2d.hpp"
#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

enum class NlgsNorm { quad, quad_normal, maxm, qm16 };  // 'Quad ', 'QuaN ', 'Maxm ', 'QM/16'
enum class NlgsStorage { exchange_local_global, stored_delassus_loops };

struct NlgsOptions {
  NlgsStorage storage = NlgsStorage::stored_delassus_loops;
  NlgsNorm norm = NlgsNorm::quad;
  double tolerance = 1.666e-4;
  double relax = 1.0;
  int gs_it1 = 50;   // sweeps between two convergence checks
  int gs_it2 = 500;  // maximum number of checks
  bool quick_scramble = false;
  // Extra stopping rule of ours: stop when the natural-map residual ÷ ‖q‖ is below this (0 = off).
  double residual_target = 0.0;
};

// LMGC90's check quantities (numerics.md §4.1), normalised by the tolerance.
struct NlgsNorms {
  double mean_dvor = 0.0;  // MeanDVoR
  double quad_dv = 0.0;    // QuadDV
  double quad_dvr = 0.0;   // QuadDVR
  double maxm_dv = 0.0;    // MaxmDV
  double maxm_dvr = 0.0;   // MaxmDVR
  double quad_wr = 0.0;    // QuadWR
};

struct NlgsResult {
  int iterations = 0;  // sweeps done
  bool converged = false;
  bool diverged = false;  // NaN
  NlgsNorms norms;
  // Solver-independent error: natural-map residual of the local problems (fc3d/FORMAT.md §3),
  // absolute and divided by ‖q‖ (q = free local velocities of all interactions).
  double residual_absolute = 0.0;
  double residual_relative = 0.0;
  double free_velocity_norm = 0.0;
  std::size_t active = 0;  // interactions with a non-zero reaction
  double seconds = 0.0;    // wall time of the solve (set by the solve_contacts stage)
};

// Builds the Delassus blocks and local problems, starts from the reactions already in
// `contacts` (warm start), iterates, then sets velocities (bodies.velocity = V_free + M⁻¹ H r),
// relative velocities and statuses.
NlgsResult solve_nlgs_2d(const Scene2D& scene, RigidBodies2D& bodies, std::vector<Interaction2D>& contacts,
                         double h, double time, const NlgsOptions& options);

}  // namespace lmgc::solver
