#pragma once
#include <string>

#include "grammar/bodies/ast.hpp"

namespace lmgc::grammar {

// BODIES.OUT as LMGC90 echoes it (docs/lmgc90-facts/datbox-inputs.md §1.6): the fixed header, MAILx bodies,
// a dashed line, then RBDY2 bodies and a dashed line (2D) or RBDY3 bodies (3D). Numbers of
// bodies, elements, nodes and contactors are written as ranks, as LMGC90 does.
std::string write_bodies(const BodiesFile& file);

}  // namespace lmgc::grammar
