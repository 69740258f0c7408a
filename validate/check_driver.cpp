// What the case's drivers ask of a run (COMMAND.DAT, command.py) and its multi-physics data, against
// what lmgc-solve runs: L4005-L4007, L4009, L4010, L4012. lmgc-check reports them as warnings and
// notes (the case is valid for LMGC90); lmgc-solve refuses a case with an L4005 or L4007.
#include <cmath>
#include <set>

#include "grammar/command/catalogue.hpp"
#include "grammar/command/expand.hpp"
#include "grammar/command_py/chipy_catalogue.hpp"
#include "run/run_parameters.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

using grammar::CommandSupport;
using grammar::Location;
using grammar::SourceSpan;

std::string in_quotes(std::string_view s) {
  return "'" + std::string(s) + "'";
}

// The commands COMMAND.DAT runs (every CHIC flag 0, as lmgc-solve reads it), each line once: the
// support of its keyword decides the diagnostic.
void check_command_dat_commands(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  const std::string path = datbox_path(files, "COMMAND.DAT");
  grammar::DiagnosticSink scratch(static_cast<std::size_t>(-1));
  std::set<std::uint32_t> seen;
  bool stepping = false;  // an INCREMENT STEP has run: the time loop has begun
  grammar::run_command_program(
      *files.command, 10'000'000, scratch, {}, [&](const grammar::ExecutedCommand& c) {
        if (c.keyword == "INCREMENT STEP") stepping = true;
        if (!seen.insert(c.line).second) return;
        const grammar::CommandKeyword* k = grammar::find_command_keyword(c.keyword);
        if (!k) return;
        const Location where{path, SourceSpan{c.line, 1, static_cast<std::uint16_t>(1 + c.keyword.size())}};
        switch (k->support) {
          case CommandSupport::not_run:
            sink.report("L4005", where,
                        "COMMAND.DAT runs " + in_quotes(c.keyword) + ", which lmgc-solve does not do yet",
                        "lmgc-solve refuses this run; --no-command-dat runs the case without COMMAND.DAT, "
                        "which LMGC90 2025 no longer reads");
            break;
          case CommandSupport::first_only:
            if (stepping)
              sink.report("L4005", where,
                          "COMMAND.DAT runs " + in_quotes(c.keyword) +
                              " inside the time loop; lmgc-solve does it only before the first step",
                          "lmgc-solve refuses this run; --no-command-dat runs the case without COMMAND.DAT");
            break;
          case CommandSupport::multiphysics:
            sink.report("L4007", where,
                        "COMMAND.DAT runs " + in_quotes(c.keyword) +
                            ", LMGC90's multi-physics, which lmgc-solve does "
                            "not run yet");
            break;
          case CommandSupport::not_written:
            sink.report("L4006", where,
                        in_quotes(c.keyword) + " is an output or display lmgc-solve does not write");
            break;
          case CommandSupport::warm_start:
            sink.report("L4006", where,
                        in_quotes(c.keyword) +
                            " sets LMGC90's warm start by position (PLPLx); lmgc-solve matches "
                            "the previous reactions by contactor: the first NLGS iterate may differ, not the "
                            "problem");
            break;
          default:
            break;
        }
      });
}

// The run parameters COMMAND.DAT gives, against the values a run can take: the run-parameter
// table's own test (run/run_parameters.hpp), L4010 with the line.
void check_command_dat_parameters(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  const std::string path = datbox_path(files, "COMMAND.DAT");
  // LMGC90's 2D NLGS stops on an unknown norm; its 3D one keeps Quad (lmgc-solve does the same).
  bool three_d = files.bodies && !files.bodies->bodies.empty();
  if (files.bodies)
    for (const auto& b : files.bodies->bodies) three_d &= b.type == grammar::BodyType::rbdy3;
  // The file's own faults (an APPELLE without its label, ...) are reported by its grammar's checks.
  grammar::DiagnosticSink quiet(static_cast<std::size_t>(-1));
  const grammar::CommandRunParameters p = grammar::command_run_parameters(*files.command, quiet);
  run::RunOptions scratch;
  run::apply_command_parameters(p, path, three_d, scratch, sink);
  if (p.lines.count("solver_type")) {
    std::string storage = p.storage;
    while (!storage.empty() && storage.back() == ' ') storage.pop_back();
    // CHIC reads the storage from the line after EX PREP NLGS, whatever it holds; both storages give
    // the same iterates, so an unknown word changes nothing lmgc-solve computes.
    if (storage != "Stored_Delassus_Loops" && storage != "Exchange_Local_Global")
      sink.report("L4006", Location{path, SourceSpan{p.lines.at("solver_type"), 1, 2}},
                  "EX PREP NLGS reads " + in_quotes(storage) +
                      " as its storage; lmgc-solve runs Stored_Delassus_Loops, whose iterates are those of "
                      "either storage");
  }
}

// The chipy calls of command.py that ask for what lmgc-solve does not run.
void check_command_script(const CaseFiles& files, grammar::DiagnosticSink& sink, bool read_only) {
  const grammar::CommandScript& script = *files.command_script;
  std::set<std::string> unknown;
  bool polygons = false;
  if (files.bodies)
    for (const auto& b : files.bodies->bodies)
      for (const auto& t : b.contactors) polygons |= t.type.value == "POLYG";
  for (const grammar::ScriptCall& call : script.calls) {
    const Location where{script.path, SourceSpan{call.line, call.column,
                                                 static_cast<std::uint16_t>(call.column + call.name.size())}};
    const grammar::ChipyFunction* f = grammar::find_chipy_function(call.name);
    if (!f) {
      if (unknown.insert(call.name).second)
        sink.report("L4009", where,
                    "chipy." + call.name + " is not known to lmgc: its effect on the run is not checked");
      continue;
    }
    switch (f->support) {
      case CommandSupport::not_run:
        sink.report("L4005", where,
                    "chipy." + call.name + " " + std::string(f->what) + "; lmgc-solve does not do it yet",
                    "lmgc-solve refuses this case");
        break;
      case CommandSupport::script_only:
        if (read_only)
          sink.report("L4005", where,
                      "chipy." + call.name + " " + std::string(f->what) +
                          "; lmgc-solve reads the script without running it, so it cannot",
                      "lmgc-solve refuses this run; without --read-script and run-parameter flags it runs "
                      "command.py (lmgc-run)");
        break;
      case CommandSupport::multiphysics:
        sink.report(
            "L4007", where,
            "chipy." + call.name + " " + std::string(f->what) + ", which lmgc-solve does not run yet");
        break;
      case CommandSupport::warm_start:
      case CommandSupport::not_written:
        sink.report("L4006", where,
                    "chipy." + call.name + " " + std::string(f->what) + "; lmgc-solve does not");
        break;
      default:
        break;
    }
    // Cundall's detection with its shrink or simplification parameters (lmgc-solve runs it without).
    if (call.name == "PRPRx_UseCpCundallDetection")
      for (std::size_t k = 1; k < 4; ++k) {
        static constexpr std::string_view kNames[] = {"", "cd_shrink", "an_shrink", "delta"};
        const grammar::ScriptArgument* a = grammar::script_argument(call, k, kNames[k]);
        if (a && !(a->value.number && *a->value.number == 0.0))
          sink.report("L4005", where,
                      "chipy.PRPRx_UseCpCundallDetection is given " + std::string(kNames[k]) + " = " +
                          a->expression +
                          "; lmgc-solve runs Cundall's detection without shrinking or simplifying the faces",
                      "lmgc-solve refuses this case");
      }
    // RecupRloc(tol): LMGC90 matches PLPLx reactions by position within tol (2D).
    if (call.name == "RecupRloc" && !call.arguments.empty() && polygons)
      sink.report("L4006", where,
                  "RecupRloc(" + call.arguments[0].expression +
                      ") matches LMGC90's PLPLx warm start by position; lmgc-solve matches the previous "
                      "reactions by contactor: the first NLGS iterate may differ, not the problem");
    if ((call.name == "ReadIni" || call.name == "ReadIniDof" || call.name == "ReadIniVlocRloc") &&
        !call.arguments.empty() &&
        !(call.arguments[0].value.number && *call.arguments[0].value.number == 0.0))
      sink.report("L4005", where,
                  "chipy." + call.name + "(" + call.arguments[0].expression +
                      ") restarts from OUTBOX's files; lmgc-solve starts from DATBOX's .INI files",
                  "copy the files to DATBOX/DOF.INI and DATBOX/Vloc_Rloc.INI, as docs/restart.md says");
  }
}

// MP_DEM and PTPT2 data, and bulk laws whose thermal or electrical part only LMGC90's multi-physics uses.
void check_multiphysics(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  for (const std::string& name : files.unread_files) {
    if (name == "MP_DEM.DAT")
      sink.report(
          "L4007", Location{datbox_path(files, name), {}},
          "MP_DEM.DAT holds thermal or electrical behaviours that LMGC90's multi-physics solver reads "
          "(ReadMpBehaviours); lmgc-solve does not run it yet");
    if (name == "PTPT2_NETWORK.DAT")
      sink.report("L4007", Location{datbox_path(files, name), {}},
                  "PTPT2_NETWORK.DAT holds PTPT2 links that LMGC90 reads under PTPT2_LoadNetwork; "
                  "lmgc-solve does not run PTPT2 links yet");
  }
  if (!files.bulk_behav) return;
  for (const grammar::BulkLaw& law : files.bulk_behav->laws)
    if (law.law_type.value == "THERMO_RIGID" || law.law_type.value == "ELECTRO_RIGID" ||
        law.law_type.value == "THERMO_ELECTRO_RIGID")
      sink.report("L4012", Location{datbox_path(files, "BULK_BEHAV.DAT"), law.law_type.span},
                  in_quotes(law.law_type.value) +
                      " is run as RIGID (its density only), as LMGC90 runs it when the script loads no "
                      "multi-physics behaviour");
}

}  // namespace

void check_drivers(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options) {
  if (command_dat_drives(files, options)) {
    check_command_dat_parameters(files, sink);
    check_command_dat_commands(files, sink);
  }
  if (files.command_script) check_command_script(files, sink, options.script_read_only);
  check_multiphysics(files, sink);
}

}  // namespace lmgc::validate
