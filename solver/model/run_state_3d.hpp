#pragma once
// What a rigid 3D run carries from stage to stage and from step to step: the step's clock, its
// interactions and their law states, the verlet list of the last step.
#include "solver/detection/visibility_index_3d.hpp"
#include "solver/model/interaction_3d.hpp"
#include "solver/model/large_array.hpp"
#include "solver/model/step_context.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

struct RunState3D : StepContext {
  LargeArray<Interaction3D> contacts;
  // The interactions' law states, index for index; empty in a scene whose laws keep none
  // (keeps_law_state_3d).
  LargeArray<LawState3D> law_states;
  LargeArray<StoredInteraction3D> previous;  // last step's, in its order (store_interactions)
  // Detection's points before sorting, kept from step to step for its memory: a list built afresh
  // would take new pages from the system, for the kernel to fault in, at every step on large scenes.
  LargeArray<DetectedPoint3D> detected;
  VisibilityIndex3D visibility;   // built at the first detection
  bool laws_initialized = false;  // a step with interactions has been solved (LawStep::first_step)
  QuickScramble scramble;         // the sweep order's random lists, step after step
};

}  // namespace lmgc::solver
