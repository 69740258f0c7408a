#pragma once
// What a case's command.py says without running it: its top-level literal assignments, the chipy
// calls it makes (with their arguments where they are literals or names of literals) and the step
// loop. A Python driver can compute anything; this reader resolves only what is written plainly
// (numbers, strings, True/False, names bound to those, and + - * / ** on numbers), and marks the
// rest unresolved, so a caller can say "the script assigns 1e-4" or "the script computes it".
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lmgc::grammar {

// A literal value: a number or a string (True/False read as 1/0).
struct ScriptValue {
  std::optional<double> number;
  std::optional<std::string> text;
  bool resolved() const { return number || text; }
};

struct ScriptArgument {
  std::string keyword;     // "" for a positional argument
  std::string expression;  // as written
  ScriptValue value;       // when the expression is a literal (or names one)
};

struct ScriptCall {
  std::string name;  // without the module prefix: "TimeEvolution_SetTimeStep"
  std::vector<ScriptArgument> arguments;
  std::uint32_t line = 0;
  std::uint16_t column = 0;
  bool conditional = false;  // inside an if/else, a try or a function body: may not run
  bool in_loop = false;      // inside a for or while loop
};

struct ScriptLoop {
  std::uint32_t line = 0;
  std::string header;                 // "for k in range(0, nb_steps):"
  std::optional<std::int64_t> count;  // passes, when range(...)'s bounds resolve
  bool steps = false;                 // its body calls IncrementStep(): the time loop
};

struct CommandScript {
  std::string path;
  std::map<std::string, ScriptValue> assignments;  // last top-level literal assignment of each name
  std::vector<ScriptCall> calls;                   // chipy calls, in file order
  std::vector<ScriptLoop> loops;
  // The calls named `name`, in file order.
  std::vector<const ScriptCall*> calls_to(std::string_view name) const;
  // The time loop (the loop whose body increments the step), if any.
  const ScriptLoop* step_loop() const;
};

// Reads a command.py text. Never fails: what it cannot resolve stays unresolved.
CommandScript read_command_script(std::string path, std::string_view text);

// The argument of `call` at `position` or given as `keyword` (nullptr when absent).
const ScriptArgument* script_argument(const ScriptCall& call, std::size_t position, std::string_view keyword);

}  // namespace lmgc::grammar
