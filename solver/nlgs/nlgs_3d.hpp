#pragma once
// Non-linear Gauss–Seidel over the 3D interactions of a step. docs/lmgc90-facts/numerics.md §3-§4.
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"
#include "solver/nlgs/nlgs_check.hpp"

namespace lmgc::solver {

// NLGS in LMGC90's Exchange_Local_Global form: every local solve sees the bodies' current velocities
// and injects its impulse increment at once (numerics.md §3). Starts from the reactions already in
// state.contacts (warm start); ends with the bodies' velocities and impulses, the contacts' relative
// velocities and statuses, as LMGC90's post sweep leaves them.
NlgsResult solve_contacts(Scene3D& scene, RunState3D& state, const NlgsOptions& options);

}  // namespace lmgc::solver
