#pragma once
// The keywords of the legacy COMMAND.DAT driver with the argument lines each one reads.
// spec: state-and-outputs.md §2.1.3. Dispatch is by prefix: a statement is a keyword when it
// starts with one (the longest match wins).
#include <span>
#include <string_view>

namespace lmgc::grammar {

enum class CommandArgument : std::uint8_t { real, integer, word, type_tolerance, label, command };

struct CommandKeyword {
  std::string_view keyword;
  std::span<const CommandArgument> arguments;  // lines read after the statement
};

std::span<const CommandKeyword> command_keyword_catalogue();
// The keyword a statement starts with (longest), or nullptr.
const CommandKeyword* match_command_keyword(std::string_view statement);

}  // namespace lmgc::grammar
