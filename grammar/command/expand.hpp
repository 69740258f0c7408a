#pragma once
// Running COMMAND.DAT: CHIC's compilation (APPELLE inlined, occurrences, REPETE loops resolved)
// and its execution into the flat list of module commands a bounded run executes.
// docs/lmgc90-facts/state-and-outputs.md §2.1.2.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "grammar/command/ast.hpp"
#include "grammar/common/diagnostic.hpp"

namespace lmgc::grammar {

// CHIC's deployed program: the main program with every APPELLE replaced by 'SUB name', the
// subroutine's lines and 'RETOUR', until no APPELLE remains.
struct CommandLoop {
  std::size_t repete = 0;  // deployed index of the REPETE line
  std::size_t label = 0;   // deployed index of the line DEPUIS names
  std::int64_t count = 0;  // n of 'REPETE n FOIS': n + 1 passes
};

struct CommandProgram {
  std::vector<std::size_t> entries;      // deployed list: indices into CommandFile::lines
  std::vector<std::int64_t> occurrence;  // 'OCCURENCE m' on the next entry, else 0
  std::vector<CommandLoop> loops;
};

// Reports what CHIC stops on while compiling (missing SUB or RETOUR, DEPUIS label not found,
// more than 1000 commands, more than 50 loops); nullopt then.
std::optional<CommandProgram> compile_command_program(const CommandFile& file, DiagnosticSink& sink,
                                                      const std::string& path = "COMMAND.DAT");

// One module command as executed.
struct ExecutedCommand {
  std::string keyword;    // catalogue spelling ("WRITE OUT DOF")
  std::string module;     // catalogue module ("overall", "nlgs", ...)
  std::string text;       // the significant text of the line ("WRITE OUT DOF STEP 100")
  std::string parameter;  // the text after the keyword ("STEP 100")
  std::vector<CommandValue> arguments;
  std::uint32_t line = 0;    // line in COMMAND.DAT
  std::size_t deployed = 0;  // index in the deployed program
};

// A flag that a command sets when it runs (CHIC flags: AFTER ITER CHECK sets flag 1 to 0 when
// converged, 1 otherwise; COMPUTE TIME STEP sets flags 2 and 3; ...). Flags start at 0.
struct CommandFlagRule {
  std::string keyword;
  int flag = 1;
  std::int64_t value = 0;
};

// Runs the program as CHIC does (REPETE n gives n + 1 passes, STOP REPETE SI, CAP SI, IOK and
// FLAG lines) and returns the module commands executed, at most `max_commands` of them. Flags
// are set only by `rules` (so with no rule every flag reads 0: 'STOP REPETE SI IOK = 0' after
// 'IOK = FLAG 1' stops at the first check). 'IOK = ?' (keyboard input) reads 0.
std::vector<ExecutedCommand> expand_command_program(const CommandFile& file, std::size_t max_commands,
                                                    DiagnosticSink& sink,
                                                    std::span<const CommandFlagRule> rules = {});

// As expand_command_program, handing each executed command to `visit` instead of keeping it;
// returns how many ran.
std::size_t run_command_program(const CommandFile& file, std::size_t max_commands, DiagnosticSink& sink,
                                std::span<const CommandFlagRule> rules,
                                const std::function<void(const ExecutedCommand&)>& visit);

// Run parameters a COMMAND.DAT sets, read off its bounded run (every flag 0) and its loops. `lines`
// holds, for each parameter the file sets (named as in lmgc-solve's run-parameter table: "dt",
// "theta", "nb_steps", "tol", ...), the line that sets it (0 for the step count of a file that runs
// no INCREMENT STEP); a parameter absent from `lines` keeps lmgc-solve's default.
struct CommandRunParameters {
  std::map<std::string, std::uint32_t, std::less<>> lines;
  double dt = 0.0;
  double theta = 0.5;
  long steps = 0;    // INCREMENT STEP executed (run bounded to 10^7 commands)
  std::string norm;  // 'Quad', 'QuaN', 'Maxm', 'QM/16' (trailing blanks removed)
  double tolerance = 0.0;
  double relax = 1.0;
  std::string storage;         // Stored_Delassus_Loops / Exchange_Local_Global
  int gs_it1 = 0, gs_it2 = 0;  // sweeps per check, checks: REPETE counts + 1
  long write_every = 0;        // WRITE OUT DOF STEP p
  long display_every = 0;      // WRITE OUTPUT GMV STEP n
  bool quick_scramble = false;
  double y_min = 0.0, y_max = 0.0, x_min = 0.0, x_max = 0.0;  // INIT YMIN/YMAX/XMIN/XMAX BOUNDARY (2D)
  bool has_y_min = false;
  long cundall_iterations = 0;         // CUNDALL ITERATION
  bool zero_initial_velocity = false;  // FATAL DAMPING or INI V DOF NULL before the first step
  double x_period = 0.0;               // PERIODIC CONDITION (2D) / XPERIODIC CONDITION (3D); 0 = none
  double y_period = 0.0;               // YPERIODIC CONDITION (3D)
  bool new_rotation_scheme = false;    // NEW ROTATION SCHEME (RBDY3: Cayley update of the frame)
  bool diagonal_resolution = false;    // DIAGONAL RESOLUTION (3D NLGS)
  // (FD) INIT SOURCE POINT: first body (1-based), radius, point.
  bool has_source_point = false;
  long source_first = 0;
  double source_radius = 0.0;
  double source_point[3] = {0.0, 0.0, 0.0};
  // FD INIT SOURCE POINT (RBDY3_SetSourcePointWithIni): the point is a position; INIT SOURCE POINT
  // (RBDY3_SetSourcePoint): a translation from each body's reference position.
  bool source_point_absolute = true;
};
CommandRunParameters command_run_parameters(const CommandFile& file, DiagnosticSink& sink);

}  // namespace lmgc::grammar
