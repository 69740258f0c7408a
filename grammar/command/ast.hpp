#pragma once
// COMMAND.DAT, the legacy CHIC driver: every line of the file, classified as LMGC90's CHIC
// interpreter reads it, with what it ignores kept for a byte-exact echo.
// docs/lmgc90-facts/state-and-outputs.md §2.1.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

enum class CommandLineKind {
  blank,      // nothing in columns 1-30
  comment,    // '#' first (after the leading blanks): offered to no handler in practice
  message,    // '.' first: printed when ECHO is ON
  keyword,    // a module command of the catalogue (prefix match)
  control,    // a CHIC control line: APPELLE, SUB, RETOUR, REPETE, DEPUIS, IOK =, CAP SI, ...
  argument,   // a line read as an argument by the keyword line before it
  label,      // any other line named by a DEPUIS or SUR line: a jump target
  unknown,    // any other line no DEPUIS/SUR names: LMGC90 ignores it (warning L1019)
  after_end,  // after 'FIN DU FICHIER': never read
};

enum class CommandArgumentKind {
  real,      // one list-directed real
  integer,   // one list-directed integer
  word,      // the whole significant text ('3D', 'Stored_Delassus_Loops', ...)
  type_tol,  // NLGS check: type = characters 1-5, tolerance read list-directed from 6-30
  reals,     // every list-directed real of the line (coordinates)
};

struct CommandValue {
  CommandArgumentKind kind = CommandArgumentKind::real;
  Word word;                // word; type of type_tol
  std::vector<Real> reals;  // real (1), tolerance of type_tol (1), reals (n)
  Integer integer;          // integer
  friend bool operator==(const CommandValue&, const CommandValue&) = default;
};

struct CommandLine {
  CommandLineKind kind = CommandLineKind::blank;
  // The line is indent blanks + text + trailer, byte for byte.
  std::uint32_t indent = 0;           // leading blanks of columns 1-30 (CHIC strips them)
  Word text;                          // the rest of columns 1-30, trailing blanks removed: what CHIC compares
  std::string trailer;                // everything after `text`: blanks, the ':' of column 31, the comment
  bool crlf = false;                  // the line ended with "\r\n"
  std::string keyword;                // keyword / control: the catalogue spelling matched
  std::string parameter;              // keyword / control: the text after the keyword ("STEP 100", "32 FOIS",
                                      // the label of DEPUIS/SUR/INTO, the name of APPELLE/SUB)
  std::optional<CommandValue> value;  // argument lines
  friend bool operator==(const CommandLine&, const CommandLine&) = default;
};

struct CommandFile {
  std::vector<CommandLine> lines;  // every line of the file, in order
  bool final_newline = true;
  friend bool operator==(const CommandFile&, const CommandFile&) = default;
};

}  // namespace lmgc::grammar
