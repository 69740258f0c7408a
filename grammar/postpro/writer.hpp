#pragma once
#include <string>

#include "grammar/postpro/ast.hpp"

namespace lmgc::grammar {

// Canonical POSTPRO.DAT (the layout of LMGC90's examples): a '#' ruler comment line, then every
// line's text (command name, 'STEP n', each argument line) padded with blanks to 30 columns and
// closed by ':' in column 31, and a last 'END' line in the same layout. Integers are written
// left-justified in their I fields, reals as ES14.7. parse_postpro(write_postpro(f)) == f.
// LMGC90 itself writes no echo of this file (POSTPRO/POSTPRO.OUT is created empty).
std::string write_postpro(const PostproFile& file);

}  // namespace lmgc::grammar
