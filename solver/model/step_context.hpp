#pragma once
// The clock of a Moreau–Jean step, what every stage of the step reads: the time at the end of the
// step, its index, the time step and θ (docs/lmgc90-facts/numerics.md §1). A run state is a step
// context plus what the stages carry from one to the next; a stage that needs only the clock takes
// this type alone.

namespace lmgc::solver {

struct StepContext {
  double time = 0.0;  // TPS: the end of the current step
  long step = 0;      // Nstep
  double h = 1e-3;    // time step
  double theta = 0.5;

  double begin_time() const { return time - h; }
};

}  // namespace lmgc::solver
