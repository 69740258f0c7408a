#pragma once
#include "grammar/bulk_behav/ast.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::grammar {

// Reads BULK_BEHAV.DAT (docs/lmgc90-facts/datbox-inputs.md §2). Never throws; problems go to `sink`.
BulkBehavFile parse_bulk_behav(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
