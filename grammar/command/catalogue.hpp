#pragma once
// The COMMAND.DAT keywords: one table, keyword -> module -> argument lines. Dispatch is by
// prefix (each handler tests INDEX(line,'KEYWORD')==1); a few CHIC words are exact. The parser
// classifies a line by the longest keyword that prefixes it. docs/lmgc90-facts/state-and-outputs.md §2.1.3.
#include <cstdint>
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

// What lmgc-solve does with a command when COMMAND.DAT drives its run (docs/command-dat.md lists
// every keyword with it).
enum class CommandSupport : std::uint8_t {
  run,           // done as LMGC90 does: a run parameter, a stage of every step, a file read
  written,       // an output lmgc-solve writes as LMGC90 does
  not_written,   // an output or display lmgc-solve does not write (noted: the run is the same)
  warm_start,    // changes only the NLGS's initial guess, not the problem solved (noted)
  first_only,    // honoured before the time loop only; refused when run inside it
  not_run,       // changes the physics or the run and is not done: lmgc-solve refuses the case
  multiphysics,  // thermal or electrical fields (MP_DEM): lmgc-solve refuses the case
  deformable,    // acts on MAILx bodies only (lmgc-solve refuses MAILx cases); nothing otherwise
  control,       // CHIC's own words: the program's structure
  // A call done when lmgc runs the script (lmgc-run, lmgc-solve's default with a command.py);
  // refused when lmgc-solve only reads the script's literals (--read-script or run-parameter flags).
  script_only,
};

struct CommandKeyword {
  std::string_view keyword;
  std::string_view module;  // "chic" for the interpreter's own control words
  CommandMatch match;
  CommandInline inline_part;
  std::span<const CommandArgumentKind> arguments;  // lines read after the keyword line
  bool control = false;                            // handled by CHIC itself (never emitted as a command)
  CommandSupport support = CommandSupport::run;
};

std::string_view support_name(CommandSupport support);

std::span<const CommandKeyword> command_catalogue();
// The longest catalogue keyword that `text` (leading blanks stripped) starts with (or equals,
// for exact ones); nullptr if none.
const CommandKeyword* find_command_keyword(std::string_view text);

}  // namespace lmgc::grammar
