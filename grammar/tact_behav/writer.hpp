#pragma once
#include <string>

#include "grammar/tact_behav/ast.hpp"

namespace lmgc::grammar {

// LMGC90's TACT_BEHAV.OUT echo, byte for byte (write_xxx_tact_behav): the 96-line comment
// block, each law with LMGC90's 5-character parameter names, a ' ' line, then the see table
// in LMGC90's order (lmgc90_see_order: duplicates merged, entries sorted).
std::string write_tact_behav(const TactBehavFile& file);

}  // namespace lmgc::grammar
