#pragma once
// COMMAND.DAT, the legacy keyword driver of LMGC90 (CHIC). spec: state-and-outputs.md §2.1.
// Only columns 1-30 of a line are significant; the rest is a comment. The AST keeps every line
// as written (so the file is echoed exactly) with its role.
#include <cstdint>
#include <string>
#include <vector>

namespace lmgc::grammar {

enum class CommandLineKind : std::uint8_t {
  blank,      // nothing in columns 1-30
  comment,    // '#' first
  message,    // '.' first: echoed when ECHO is ON
  statement,  // a keyword, a control word or a loop label
  argument,   // a value line read by the statement before it
};

struct CommandLine {
  std::string raw;     // the whole line, without its terminator
  std::uint32_t number = 0;
  CommandLineKind kind = CommandLineKind::blank;
  std::string text;    // columns 1-30, leading and trailing blanks removed
  friend bool operator==(const CommandLine& a, const CommandLine& b) { return a.raw == b.raw; }
};

struct CommandFile {
  std::vector<CommandLine> lines;
  bool final_newline = true;
  friend bool operator==(const CommandFile&, const CommandFile&) = default;
};

// One command as executed: its statement text and the argument lines it read.
struct ExecutedCommand {
  std::string statement;
  std::vector<std::string> arguments;
  std::uint32_t line = 0;  // line of the statement in COMMAND.DAT
};

}  // namespace lmgc::grammar
