#pragma once
// What a rigid 2D run carries from stage to stage and from step to step: the step's clock, its
// interactions and their law states, the verlet list the warm start reads.
#include "solver/detection/detection_2d.hpp"
#include "solver/model/interaction_2d.hpp"
#include "solver/model/large_array.hpp"
#include "solver/model/mesh_contact_2d.hpp"
#include "solver/model/step_context.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

struct RunState2D : StepContext {
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
  PointPairs2D point_pairs;  // P2P2L's, made at the first detection
  QuickScramble scramble;    // the sweep order's random lists, step after step
};

}  // namespace lmgc::solver
