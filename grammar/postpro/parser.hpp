#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/postpro/ast.hpp"

namespace lmgc::grammar {

// Reads POSTPRO.DAT as LMGC90 does (datbox-inputs.md §8): raw lines, only columns 1-30 for
// names, positional arguments, no look-ahead. `dimension` (2 or 3) picks LMGC90's 2D or 3D
// reader: they know different commands and read three commands' arguments differently. 0 means
// "not known": every command of either reader is accepted and read with the 2D layout.
PostproFile parse_postpro(const SourceText& source, DiagnosticSink& sink, int dimension = 0);

}  // namespace lmgc::grammar
