#pragma once
// The run parameters of lmgc-solve in one table: name (as LMGC90's command.py scripts name them),
// flag, the COMMAND.DAT keyword and the chipy call that set them, and how a value is compared and
// written. The layers apply in order (defaults, then the case's driver: the literals of its
// command.py, or COMMAND.DAT; then flags); each parameter remembers which layer gave its value, and
// OUTBOX/run_parameters.csv records it with the run.
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/command/ast.hpp"
#include "grammar/command/expand.hpp"
#include "grammar/command_py/script.hpp"
#include "grammar/common/diagnostic.hpp"
#include "run/run_options.hpp"

namespace lmgc::run {

enum class ParameterSource { default_value, command_dat, command_py, flag };
// "default", "COMMAND.DAT", "command.py", "flag"
std::string_view source_name(ParameterSource source);

struct RunParameter {
  std::string_view name;         // "dt"
  std::string_view flag;         // "--dt"
  std::string_view command_dat;  // the COMMAND.DAT keyword that sets it ("" when none does)
  std::string_view chipy;        // the chipy call of a command.py that sets it ("" when none does)
  // Which argument of that call (position, or keyword), or -1 when the call's presence sets it.
  int argument = -1;
  std::string_view keyword;
  // The value of the run, as written in the report and compared with a script's literal.
  std::string (*text)(const RunOptions&);
  std::optional<double> (*number)(const RunOptions&);
  // Sets the run's value from a script's literal; false when the literal is not a value the run
  // can take (nullptr: the script's value is compared, never taken).
  bool (*assign)(RunOptions&, const grammar::ScriptValue&) = nullptr;
  // The value of the chipy call's argument when the call is made without it (write and display
  // frequencies: every step), if any.
  std::optional<double> call_default = std::nullopt;
  // The flag layer: copies this parameter's value(s) from the options the command line filled.
  void (*take)(RunOptions& run, const RunOptions& flags) = nullptr;
  // The COMMAND.DAT layer: the value the file gives (read when its keyword's line is set).
  grammar::ScriptValue (*from_command_dat)(const grammar::CommandRunParameters&) = nullptr;
  // What it means, for --help and the docs (flag_help and run_parameters_markdown add where it is
  // set and its default).
  std::string_view help;
};

std::span<const RunParameter> run_parameters();
const RunParameter* find_run_parameter(std::string_view name);
const RunParameter* find_run_parameter_by_flag(std::string_view flag);
// lmgc-solve --help's description of a parameter's flag: its meaning, the chipy call and the
// COMMAND.DAT keyword that set it, its default.
std::string flag_help(const RunParameter& parameter);
// The table as docs/lmgc-solve.md shows it (one row per parameter).
std::string run_parameters_markdown();

// Which layer gave each parameter (by name): the default unless COMMAND.DAT or a flag set it.
using ParameterSources = std::map<std::string, ParameterSource, std::less<>>;

// A run parameter whose value differs from what the case's command.py assigns.
struct ScriptDifference {
  const RunParameter* parameter = nullptr;
  std::string run_value;
  std::string script_value;  // the literal the script passes
  std::uint32_t line = 0;    // of the call in command.py
  std::uint16_t column = 0;
};

// What a command.py sets for one run parameter: the literal of the call's argument (or 1 when the
// call alone sets it), or an unresolved value when the script computes it.
struct ScriptSetting {
  const RunParameter* parameter = nullptr;
  grammar::ScriptValue value;  // for the source point: FIRST (see source_point below)
  std::string expression;      // as written, for messages
  std::uint32_t line = 0;      // of the call (0 when the call is absent: "not called")
  std::uint16_t column = 0;
  // RBDY3_SetSourcePoint(WithIni): first, radius, x, y, z, and which of the two calls.
  std::vector<grammar::ScriptValue> source_point;
  bool source_point_relative = false;
};

// Every run parameter the script sets, in the table's order. A call under a condition counts (the
// condition is taken as it holds in LMGC90's default run: 'if "--norand" not in sys.argv'); of
// several calls the last one; the step count comes from the time loop's range(); a parameter set by
// the presence of a call is 1 when called, 0 when not.
std::vector<ScriptSetting> script_settings(const grammar::CommandScript& script);

// The script's layer: takes every value the script sets by a literal (sources[name] = command_py).
// A value the run cannot take is an error (L4010), a value the script computes a warning that
// names the value run instead and its flag (L4013), both at the call in command.py. `three_d`: the
// 3D NLGS keeps 'Quad ' for a norm it does not know, as LMGC90's does.
void apply_script_parameters(const grammar::CommandScript& script, bool three_d, RunOptions& options,
                             ParameterSources& sources, grammar::DiagnosticSink& sink);

// The parameters the script sets by a literal (or a name bound to one) that differ from the run's.
// A parameter the script sets by a computed value, or under a condition, is compared only when its
// literal resolves (the condition is that of LMGC90's default run: 'if "--norand" not in sys.argv'
// holds); the step count comes from the time loop's range().
std::vector<ScriptDifference> script_differences(const RunOptions& options,
                                                 const grammar::CommandScript& script);

// OUTBOX/run_parameters.csv: name,value,source,flag,command_dat,chipy.
std::string run_parameters_csv(const RunOptions& options, const ParameterSources& sources);

// The COMMAND.DAT layer: the run parameters the file sets, laid over `options` (flags given on the
// command line are applied afterwards by the caller, so they win); each one set is recorded in
// `sources`. `path`: the file's, for diagnostics. A value a run cannot take is an error (L4010, at its line),
// checked by the table's `assign` as a script's literal is; `three_d`: the 3D NLGS keeps 'Quad ' for a norm
// it does not know.
void apply_command_parameters(const grammar::CommandFile& command, std::string_view path, bool three_d,
                              RunOptions& options, grammar::DiagnosticSink& sink,
                              ParameterSources* sources = nullptr);
// The same from the parameters of an expanded COMMAND.DAT (grammar::command_run_parameters), for a
// caller that reads them too.
void apply_command_parameters(const grammar::CommandRunParameters& parameters, std::string_view path,
                              bool three_d, RunOptions& options, grammar::DiagnosticSink& sink,
                              ParameterSources* sources = nullptr);
}  // namespace lmgc::run
