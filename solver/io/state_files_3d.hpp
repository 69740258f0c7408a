#pragma once
// DOF and Vloc_Rloc state of a rigid 3D run in LMGC90's layout (through the grammar writers).
// docs/lmgc90-facts/state-and-outputs.md §1.2-1.4 (§1.4.2 for the 3D blocks).
#include <vector>

#include "grammar/dof/ast.hpp"
#include "grammar/vloc_rloc/ast.hpp"
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

// DOF.OUT.n / DOF.LAST: for every RBDY3 body (numbered body index + 1) one NO6xx node with
// X(1..6) (displacement of the centre of inertia from the reference; X(4..6) as the scene holds
// them, LMGC90 writes 0), V(1..6) (translation, then spin in the principal axes), and a, b, g =
// the columns of the principal frame; then the (empty) MAILx section's dashed line.
grammar::DofFile dof_file_3d(const Scene3D& scene, const RunState3D& state);

// Vloc_Rloc.OUT.n / .LAST: the interactions of the step, SPPLx then SPSPx (LMGC90's 3D module
// order), by candidate contactor inside a module, each block as its module writes it
// (grammar/vloc_rloc/interaction_catalogue.cpp): reactions rl/H = r / h and velocities in the
// order (s, t, n), gTT = end-of-step gap (gap at detection + h·u_n), frame rows s, t, n, contact
// point, and the law's internal variables (3D count of the law catalogue) when it has some.
grammar::VlocRlocFile vloc_rloc_file_3d(const Scene3D& scene, const RunState3D& state);

// The SPSPx / SPPLx interactions of a Vloc_Rloc.INI as the "previous step" of the first step
// (warm start): reactions (rl/H × h, stored (t, n, s)), relative velocities, statuses and internal
// variables, matched to the scene's contactors by (body number, contactor rank). Interactions
// naming contactors that do not exist (or of another shape) are skipped, as LMGC90 does. Sorted
// by (family, candidate, antagonist), so that the links of one PTPT3 pair come together and take
// their ranks. The internals are in `law_states`, index for index.
struct WarmStart3D {
  std::vector<Interaction3D> interactions;
  std::vector<LawState3D> law_states;
};
WarmStart3D warm_start_3d(const grammar::VlocRlocFile& file, const Scene3D& scene, double h);

}  // namespace lmgc::solver
