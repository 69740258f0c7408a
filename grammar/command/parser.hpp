#pragma once
#include <functional>

#include "grammar/command/ast.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::grammar {

// Reads COMMAND.DAT (spec: state-and-outputs.md §2.1): classifies every line, checks keywords,
// argument lines, loops and subroutine calls. Never throws.
CommandFile parse_command(const SourceText& source, DiagnosticSink& sink);

// The text exactly as read.
std::string write_command(const CommandFile& file);

// Runs the program symbolically: APPELLE calls inlined, REPETE/DEPUIS loops unrolled (REPETE n
// gives n+1 passes), 'STOP REPETE SI IOK = k', 'CAP SI IOK = k' and 'IOK = ...' evaluated with
// `flag` giving the value of 'IOK = FLAG f INTO <command>' (default: 0, i.e. "converged").
// Stops after `max_commands` executed commands (reported as L1019 when reached).
using CommandFlag = std::function<int(const std::string& command, int flag)>;
std::vector<ExecutedCommand> expand_command_program(const CommandFile& file, std::size_t max_commands,
                                                    DiagnosticSink& sink, const CommandFlag& flag = {});

// Run parameters a COMMAND.DAT sets, read off its expansion.
struct CommandRunParameters {
  double dt = 0.0;
  double theta = 0.5;
  long steps = 0;                 // executed INCREMENT STEP
  std::string norm;               // 'Quad ', 'QuaN ', 'Maxm ', 'QM/16'
  double tolerance = 0.0;
  double relax = 1.0;
  std::string storage;            // Stored_Delassus_Loops / Exchange_Local_Global
  int gs_it1 = 0, gs_it2 = 0;     // sweeps per check, checks (REPETE counts + 1)
  long write_every = 0;           // WRITE OUT DOF STEP p
  long display_every = 0;         // WRITE OUTPUT GMV STEP n
  bool quick_scramble = false;
  double y_min = 0.0;
  bool has_y_min = false;
};
CommandRunParameters command_run_parameters(const CommandFile& file, DiagnosticSink& sink);

}  // namespace lmgc::grammar
