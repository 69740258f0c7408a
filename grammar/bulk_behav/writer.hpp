#pragma once
#include <string>

#include "grammar/bulk_behav/ast.hpp"

namespace lmgc::grammar {

// BULK_BEHAV.OUT as LMGC90 echoes it (datbox-inputs.md §2 "Echo"): the fixed header, '$gravy',
// then every law with LMGC90's internal labels and its blank-line quirks.
std::string write_bulk_behav(const BulkBehavFile& file);

}  // namespace lmgc::grammar
