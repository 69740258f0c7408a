#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/postpro/ast.hpp"

namespace lmgc::grammar {

// Reads POSTPRO.DAT as LMGC90 does (datbox-inputs.md §8): raw lines, only columns 1-30,
// positional arguments. `dimension` (2 or 3) decides the few commands whose arguments differ.
PostproFile parse_postpro(const SourceText& source, DiagnosticSink& sink, int dimension = 2);

}  // namespace lmgc::grammar
