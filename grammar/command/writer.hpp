#pragma once
#include <string>

#include "grammar/command/ast.hpp"

namespace lmgc::grammar {

// The file again, byte for byte: each line is its leading blanks, its significant text and its
// trailer (the comment after column 30 included), with its own line ending.
// write_command(parse_command(text)) == text for every text.
std::string write_command(const CommandFile& file);

}  // namespace lmgc::grammar
