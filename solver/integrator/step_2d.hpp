#pragma once
// One Moreau–Jean θ-scheme step of a rigid 2D scene, as the stages of LMGC90's step
// (docs/lmgc90-facts/numerics.md §1.1, state-and-outputs.md §2.2): each stage is a plain function over the
// scene's flat arrays, so a driver can call them one by one as LMGC90's command.py does.
#include <span>
#include <vector>

#include "solver/detection/detection_2d.hpp"
#include "solver/model/scene_2d.hpp"
#include "solver/nlgs/nlgs_2d.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

struct RunState2D {
  double time = 0.0;  // TPS at the end of the current step
  long step = 0;      // Nstep
  double h = 1e-3;    // time step
  double theta = 0.5;
  LargeArray<Interaction2D> contacts;  // this step's interactions
  // The stored list the warm start reads (LMGC90's verlet list). stock_rloc stores `contacts` by
  // marking them (contacts_stored: until the next detection, `contacts` is the stored list and
  // `previous` an older one); the next detection swaps them in here before it writes the new list,
  // so the store copies nothing.
  LargeArray<Interaction2D> previous;
  // The interactions' internal variables, index for index with `contacts` and `previous`; both empty
  // in a scene whose laws have none (keeps_law_state_2d).
  LargeArray<LawState2D> law_states, previous_law_states;
  bool contacts_stored = false;
  bool laws_initialized = false;  // a step with interactions has been solved (LawStep::first_step)
  VisibilityIndex2D visibility;
  QuickScramble scramble;  // the sweep order's random lists, step after step
};

void increment_step(Scene2D& scene, RunState2D& state);
void compute_external_forces(Scene2D& scene, const RunState2D& state);
void compute_free_velocity(Scene2D& scene, const RunState2D& state);
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
void compute_dof(Scene2D& scene, const RunState2D& state);
// Bodies out of the scene's bounds become invisible (frozen at the bound, zero velocity).
void apply_bounds(Scene2D& scene);
// End of step: begin ← end.
void update_step(Scene2D& scene);

// All stages in LMGC90's order; returns the solver statistics of the step.
NlgsResult step_2d(Scene2D& scene, RunState2D& state, const NlgsOptions& options);

// Kinetic energy Σ ½ m |v|² + ½ I ω² at the end of the step [J].
double kinetic_energy(const RigidBodies2D& bodies);

}  // namespace lmgc::solver
