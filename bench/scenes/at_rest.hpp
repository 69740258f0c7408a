#pragma once
// The scaling benches' state "at rest", shared by the 2D disk boxes and the 3D sphere box. A packing
// that has just been built or has just landed has a share of loaded contacts that depends on its size
// (the deeper piles take longer to come down), so its time per contact compares unlike states.
#include <stdexcept>
#include <string>

namespace lmgc::bench {

// Calls step() (one time step; returns its solver::NlgsResult) until the contacts with a reaction are
// at least 98% of the `bodies` for 10 steps in a row: every body carried, one loaded contact below
// each. Returns the steps taken; throws std::runtime_error naming `what` after 1000 steps.
template <class Step>
int step_until_at_rest(int bodies, const std::string& what, Step&& step) {
  constexpr int kStepsCarried = 10, kMaxSteps = 1000;
  const double carried = 0.98 * static_cast<double>(bodies);
  int steps = 0;
  for (int carried_steps = 0; carried_steps < kStepsCarried; ++steps) {
    if (steps == kMaxSteps)
      throw std::runtime_error(what + " not at rest after " + std::to_string(kMaxSteps) + " steps");
    carried_steps = static_cast<double>(step().active) >= carried ? carried_steps + 1 : 0;
  }
  return steps;
}

}  // namespace lmgc::bench
