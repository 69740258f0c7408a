#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/ptpt3_network/ast.hpp"

namespace lmgc::grammar {

// Reads PTPT3_NETWORK.DAT (layout in ast.hpp). The form is set by the first record: six items
// (plain) or eight (with parameters, PTPT3_LoadParams); every record must have that many. Blank
// records are skipped as a list-directed read skips them. Never throws.
Ptpt3NetworkFile parse_ptpt3_network(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
