#pragma once
// One Moreau–Jean θ-scheme step of a rigid 2D scene, as the stages of LMGC90's step
// (docs/lmgc90-facts/numerics.md §1.1, state-and-outputs.md §2.2): each stage is a plain function over the
// scene's flat arrays, so a driver can call them one by one as LMGC90's command.py does.
#include <span>
#include <string_view>
#include <vector>

#include "solver/detection/detection_2d.hpp"
#include "solver/model/run_state_2d.hpp"
#include "solver/model/scene_2d.hpp"
#include "solver/nlgs/nlgs_2d.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

// The clock moves on by h; impulses to 0, V to V_begin.
void increment_step(Scene2D& scene, StepContext& step);
// Gravity and the driven forces, θ-averaged over the step.
void compute_external_forces(Scene2D& scene, const StepContext& step);
// V_free = V_begin + h M⁻¹ F; driven velocities at t.
void compute_free_velocity(Scene2D& scene, const StepContext& step);
// Detection on the θ configuration: coor = reference + X_begin + (1-θ) h V_begin.
void select_prox_tactors(Scene2D& scene, RunState2D& state);
// Warm start: reactions, statuses and internal variables of the matching previous interaction.
void recup_rloc(RunState2D& state);
NlgsResult solve_contacts(Scene2D& scene, RunState2D& state, const NlgsOptions& options);
void stock_rloc(RunState2D& state);
// The verlet list the next recup_rloc reads (stock_rloc's, or a warm start's from Vloc_Rloc.INI):
// sorted like detection's interactions, by (family, candidate, antagonist, vertex), with the internals
// of `law_states` (index for index, or empty). A copy, where stock_rloc keeps the step's own list.
void store_interactions(RunState2D& state, std::span<const Interaction2D> interactions,
                        std::span<const LawState2D> law_states);
// Whether a law of the scene's visibility rows has internal variables (a LawState2D per interaction).
bool scene_keeps_law_state_2d(const Scene2D& scene);
// X = X_begin + h((1-θ) V_begin + θ V).
void compute_dof(Scene2D& scene, const StepContext& step);
// Bodies out of the scene's bounds become invisible (frozen at the bound, zero velocity).
void apply_bounds(Scene2D& scene);
// End of step: begin ← end.
void update_step(Scene2D& scene);

// A stage of the step under the name of the chipy call of LMGC90's command.py that runs it.
struct StepStage2D {
  std::string_view name;
  void (*run)(Scene2D& scene, RunState2D& state, const NlgsOptions& options, NlgsResult& result);
};
// The step: the stages in LMGC90's order (its macro time loop).
std::span<const StepStage2D> step_stages_2d();

// Runs the step's stages in order; returns the solver statistics of the step.
NlgsResult step_2d(Scene2D& scene, RunState2D& state, const NlgsOptions& options);

// Kinetic energy Σ ½ m |v|² + ½ I ω² at the end of the step [J].
double kinetic_energy(const RigidBodies2D& bodies);

}  // namespace lmgc::solver
