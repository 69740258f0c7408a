#pragma once
// DOF and Vloc_Rloc state of a rigid 2D run in LMGC90's layout (through the grammar writers).
// spec: state-and-outputs.md §1.2-1.4.
#include <string>

#include "grammar/dof/ast.hpp"
#include "solver/integrator/step_2d.hpp"

namespace lmgc::solver {

// DOF.OUT.n / DOF.LAST: X (displacement from the reference) and V of every RBDY2 body.
grammar::DofFile dof_file_2d(const Scene2D& scene, const RunState2D& state);

}  // namespace lmgc::solver
