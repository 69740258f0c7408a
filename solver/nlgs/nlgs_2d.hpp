#pragma once
// Non-linear Gauss–Seidel over the 2D interactions of a step. docs/lmgc90-facts/numerics.md §3-§4.
#include <span>
#include <string>
#include <vector>

#include "solver/bodies/rigid_bodies_2d.hpp"
#include "solver/model/interaction_2d.hpp"
#include "solver/model/large_array.hpp"
#include "solver/model/scene_2d.hpp"
#include "solver/nlgs/nlgs_check.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

// Builds the Delassus blocks and local problems, starts from the reactions already in
// `contacts` (warm start), iterates, then sets velocities (bodies.velocity = V_free + M⁻¹ H r),
// relative velocities and statuses. `step`: the step as the laws see it (h, the time at its end,
// whether it is the first step and the run's first preparation with interactions). `scramble`: the
// run's quick-scramble generator, used when options.quick_scramble. `law_states`: the interactions'
// internal variables, index for index, or empty in a scene whose laws have none.
NlgsResult solve_nlgs_2d(const Scene2D& scene, RigidBodies2D& bodies, LargeArray<Interaction2D>& contacts,
                         std::span<LawState2D> law_states, const LawStep& step, const NlgsOptions& options,
                         QuickScramble& scramble);

}  // namespace lmgc::solver
