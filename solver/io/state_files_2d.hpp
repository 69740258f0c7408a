#pragma once
// DOF and Vloc_Rloc state of a rigid 2D run in LMGC90's layout (through the grammar writers).
// docs/lmgc90-facts/state-and-outputs.md §1.2-1.4.
#include <string>

#include "grammar/dof/ast.hpp"
#include "grammar/vloc_rloc/ast.hpp"
#include "solver/integrator/step_2d.hpp"

namespace lmgc::solver {

// DOF.OUT.n / DOF.LAST: X (displacement from the reference) and V of every RBDY2 body.
grammar::DofFile dof_file_2d(const Scene2D& scene, const RunState2D& state);

// Vloc_Rloc.OUT.n / .LAST: the interactions of the step, module by module in LMGC90's order,
// with LMGC90's data-line fields (docs/lmgc90-facts/rigid-2d.md §3.4).
grammar::VlocRlocFile vloc_rloc_file_2d(const Scene2D& scene, const RunState2D& state);

// The interactions of a Vloc_Rloc.INI as the "previous step" of the first step (warm start):
// reactions (rl/H × h), statuses and internal variables, matched to the scene's contactors.
// Interactions naming contactors that do not exist are skipped (as LMGC90 does). The internals are
// in `law_states`, index for index.
struct WarmStart2D {
  std::vector<Interaction2D> interactions;
  std::vector<LawState2D> law_states;
};
WarmStart2D warm_start_2d(const grammar::VlocRlocFile& file, const Scene2D& scene, double h);

}  // namespace lmgc::solver
