#pragma once
#include <string>

#include "grammar/dof/ast.hpp"

namespace lmgc::grammar {

// DOF.OUT.n / DOF.LAST exactly as LMGC90 writes them (docs/lmgc90-facts/state-and-outputs.md §1.2-1.3):
// the 6-line header, then each section's bodies and, for a closed section, a dashed line.
std::string write_dof(const DofFile& file);

}  // namespace lmgc::grammar
