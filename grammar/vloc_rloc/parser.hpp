#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/vloc_rloc/ast.hpp"

namespace lmgc::grammar {

// Reads Vloc_Rloc.INI / .LAST / .OUT.n (docs/lmgc90-facts/state-and-outputs.md §1.4). Never throws.
VlocRlocFile parse_vloc_rloc(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
