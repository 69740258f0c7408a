#pragma once
#include <string>

#include "grammar/postpro/ast.hpp"

namespace lmgc::grammar {

// Canonical POSTPRO.DAT: a '#' ruler line, then every line's meaningful text padded to 30
// columns and closed by ':' in column 31 (the layout of LMGC90's examples), and 'END'.
// LMGC90 itself writes no echo of this file (POSTPRO/POSTPRO.OUT is created empty).
std::string write_postpro(const PostproFile& file, int dimension = 2);

}  // namespace lmgc::grammar
