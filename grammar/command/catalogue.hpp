#pragma once
// The COMMAND.DAT keywords: one table, keyword -> module -> argument lines. Dispatch is by
// prefix (each handler tests INDEX(line,'KEYWORD')==1); a few CHIC words are exact. The parser
// classifies a line by the longest keyword that prefixes it. spec: state-and-outputs.md §2.1.3.
#include <span>
#include <string_view>

#include "grammar/command/ast.hpp"

namespace lmgc::grammar {

enum class CommandMatch { prefix, exact };

// What follows the keyword on its own line.
enum class CommandInline {
  none,          // nothing expected (text after the keyword is ignored by the handler)
  step_or_dtps,  // optional 'STEP n' or 'DTPS dt'
  text,          // free text: a label, a subroutine name, body ranges, a flag number, ...
};

struct CommandKeyword {
  std::string_view keyword;
  std::string_view module;  // "chic" for the interpreter's own control words
  CommandMatch match;
  CommandInline inline_part;
  std::span<const CommandArgumentKind> arguments;  // lines read after the keyword line
  bool control = false;                            // handled by CHIC itself (never emitted as a command)
};

std::span<const CommandKeyword> command_catalogue();
// The longest catalogue keyword that `text` (leading blanks stripped) starts with (or equals,
// for exact ones); nullptr if none.
const CommandKeyword* find_command_keyword(std::string_view text);

}  // namespace lmgc::grammar
