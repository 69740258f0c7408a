// lmgc-solve: runs an LMGC90 case (rigid 2D, rigid 3D) and writes what LMGC90 writes: OUTBOX echo
// and state files, DISPLAY, POSTPRO, plus a per-step run report with the achieved residual and the
// run's parameters with where each came from. Exit codes: see kExit* below and docs/lmgc-solve.md.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic_catalogue.hpp"
#include "grammar/common/output_file.hpp"
#include "lmgc_revision.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/case_input.hpp"
#include "solver/driver/run_2d.hpp"
#include "solver/driver/run_3d.hpp"
#include "validate/checks.hpp"
#include "validate/render.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitData = 1;            // the case's data are invalid (lmgc-check errors)
constexpr int kExitUsage = 2;           // the command line, or a folder that is not a case
constexpr int kExitNotConverged = 3;    // --strict: a step stopped at the NLGS's iteration cap
constexpr int kExitOutput = 4;          // an output file could not be written (disk full, ...)
constexpr int kExitRefused = 5;         // the case uses what lmgc-solve does not run yet (L4001-L4007)
constexpr int kExitNonFinite = 6;       // a body's state became NaN or infinite
constexpr int kExitNewtonDiverged = 7;  // a Newton loop did not converge at the smallest time step
// Stopped by a signal after finishing a step and writing .LAST: 128 + the signal's number
// (129 SIGHUP, 130 SIGINT, 143 SIGTERM), as shells report it.
constexpr int kExitSignalBase = 128;

// CLI11's number checks let NaN through (every comparison with NaN is false).
const CLI::Validator kFinite(
    [](std::string& text) {
      try {
        std::size_t used = 0;
        const double x = std::stod(text, &used);
        if (!std::isfinite(x)) return std::string("must be a finite number");
      } catch (const std::exception&) {
        return std::string("is not a number");
      }
      return std::string();
    },
    "FINITE");

// Runs CASE_DIR/command.py with lmgc-run (next to this program): lmgc-run's exit code, or 5 when
// this build has no Python module.
int run_script(const std::string& case_dir, long max_steps, bool quiet) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path lmgc_run = self.parent_path() / "lmgc-run";
  if (ec || !std::filesystem::exists(lmgc_run)) {
    std::cerr
        << "lmgc-solve: refused: the case is driven by its command.py, which lmgc runs with its chipy "
           "module (lmgc-run), and this build has none (it needs python3-dev and pybind11-dev when "
           "configured); --read-script runs lmgc-solve's own loop with the script's literal parameters\n";
    return kExitRefused;
  }
  std::vector<std::string> args{lmgc_run.string(), case_dir};
  if (max_steps >= 0) args.insert(args.end(), {"--max-steps", std::to_string(max_steps)});
  if (quiet) args.push_back("--quiet");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(lmgc_run.c_str(), argv.data());
  std::cerr << "lmgc-solve: cannot run " << lmgc_run << "\n";
  return kExitRefused;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lmgc;
  CLI::App app{
      "lmgc-solve: run an LMGC90 case folder (CASE_DIR/DATBOX/) with the Moreau-Jean scheme and NLGS"};
  std::string case_dir;
  run::RunOptions options;
  std::string storage = "Stored_Delassus_Loops", norm = "Quad";
  double rloc_tol = 0.0;
  bool no_command_dat = false;
  bool command_dat = false;
  // A run parameter's description comes from the run-parameter table (run/run_parameters.hpp).
  const auto described = [](std::string_view flag) {
    const run::RunParameter* parameter = run::find_run_parameter_by_flag(flag);
    return parameter ? run::flag_help(*parameter) : std::string();
  };
  app.add_option("CASE_DIR", case_dir, "case folder holding DATBOX/ (after '--' it may start with '-')")
      ->required();
  app.add_option("--dt", options.dt, described("--dt"))->check(kFinite & CLI::PositiveNumber);
  app.add_option("--theta", options.theta, described("--theta"))->check(kFinite & CLI::Range(0.5, 1.0));
  app.add_option("--steps", options.steps, described("--steps"))->check(CLI::Range(0L, 1'000'000'000'000L));
  app.add_option("--solver", storage, described("--solver"));
  app.add_option("--norm", norm, described("--norm"));
  app.add_option("--tol", options.nlgs.tolerance, described("--tol"))->check(kFinite & CLI::PositiveNumber);
  app.add_option("--relax", options.nlgs.relax, described("--relax"))
      ->check(kFinite & CLI::Range(std::nextafter(0.0, 1.0), 2.0));
  app.add_option("--gs-it1", options.nlgs.gs_it1, described("--gs-it1"))->check(CLI::Range(1, 1'000'000'000));
  app.add_option("--gs-it2", options.nlgs.gs_it2, described("--gs-it2"))->check(CLI::Range(1, 1'000'000'000));
  app.add_flag("--quick-scramble", options.nlgs.quick_scramble, described("--quick-scramble"));
  app.add_option("--scramble-seed", options.nlgs.scramble_seed, described("--scramble-seed"));
  app.add_flag("--diagonal-resolution", options.nlgs.diagonal_resolution, described("--diagonal-resolution"));
  app.add_option("--residual-target", options.nlgs.residual_target, described("--residual-target"))
      ->check(kFinite & CLI::NonNegativeNumber);
  app.add_option("--rloc-tol", rloc_tol,
                 "refused: LMGC90's RecupRloc(tol) matches PLPLx reactions by position; lmgc-solve matches "
                 "them by contactor (the first NLGS iterate may differ, not the problem)");
  app.add_option("--cundall-iterations", options.cundall_iterations, described("--cundall-iterations"))
      ->check(CLI::Range(1, 1'000'000));
  app.add_option("--write-every", options.write_every, described("--write-every"))
      ->check(CLI::Range(0L, 1'000'000'000'000L));
  app.add_option("--display-every", options.display_every, described("--display-every"))
      ->check(CLI::Range(0L, 1'000'000'000'000L));
  app.add_option("--ymin-boundary", options.y_min, described("--ymin-boundary"))->check(kFinite);
  app.add_option("--ymax-boundary", options.y_max, described("--ymax-boundary"))->check(kFinite);
  app.add_option("--xmin-boundary", options.x_min, described("--xmin-boundary"))->check(kFinite);
  app.add_option("--xmax-boundary", options.x_max, described("--xmax-boundary"))->check(kFinite);
  app.add_option("--xperiod", options.x_period, described("--xperiod"))->check(kFinite & CLI::PositiveNumber);
  app.add_option("--yperiod", options.y_period, described("--yperiod"))->check(kFinite & CLI::PositiveNumber);
  app.add_flag("--ptpt3-network", options.ptpt3_network, described("--ptpt3-network"));
  app.add_flag("--ptpt3-current-nonuc0", options.ptpt3_current_nonuc0, described("--ptpt3-current-nonuc0"));
  std::vector<double> source_point;
  bool source_point_relative = false;
  app.add_option("--source-point", source_point, described("--source-point"))
      ->expected(5)
      ->delimiter(',')
      ->check(kFinite);
  app.add_flag("--source-point-relative", source_point_relative,
               "3D: --source-point X Y Z is a translation from each body's reference position "
               "(RBDY3_SetSourcePoint, INIT SOURCE POINT) instead of a position");
  app.add_flag("--no-command-dat", no_command_dat,
               "do not read DATBOX/COMMAND.DAT (LMGC90 2025 no longer reads it): the run takes its "
               "parameters from the defaults and the flags only");
  bool read_script = false;
  app.add_flag(
      "--read-script", read_script,
      "with a command.py: read the run parameters it passes as literals and run lmgc-solve's own loop "
      "(with the flags given), instead of running the script (lmgc-run); run-parameter flags imply it");
  app.add_flag("--command-dat", command_dat,
               "take the run parameters from DATBOX/COMMAND.DAT even when the case has a command.py (the "
               "legacy driver of LMGC90 before 2025)");
  app.add_flag("-q,--quiet", options.quiet, "no progress line, no warnings but those that refuse the run");
  app.add_flag("--new-rotation-scheme", options.new_rotation_scheme, described("--new-rotation-scheme"));
  app.add_flag("--strict", options.strict, "exit 3 when a step stopped at the iteration cap");
  app.set_version_flag("--version",
                       std::string("lmgc-solve ") + LMGC_VERSION + " (revision " + LMGC_REVISION + ")");
  app.footer(
      "Run parameters: the defaults (--dt 1e-3 --theta 0.5 --steps 1000 --norm Quad --tol 1.666e-4 --gs-it1 "
      "50\n"
      "--gs-it2 500), then the case's driver, then the flags given here. The driver is CASE_DIR/command.py "
      "when it\n"
      "exists: run, unchanged, with lmgc's chipy module (lmgc-run; --steps N ends it after N steps, .LAST "
      "written);\n"
      "with --read-script or any run-parameter flag it is read instead (the literals its chipy calls pass, "
      "and the\n"
      "count of its step loop; what it computes is named, L4013). Without command.py: DATBOX/COMMAND.DAT "
      "(TIME STEP, THETA, the step loop's REPETE count, NLGS "
      "CHECK TYPE,\n"
      "the NLGS loops, WRITE OUT DOF STEP, ...; not with --no-command-dat; before the script with "
      "--command-dat).\n"
      "OUTBOX/run_parameters.csv records every value and where it came from.\n"
      "Outputs: OUTBOX/ (echo files, DOF and Vloc_Rloc .OUT.n and .LAST, run_report.csv with the achieved\n"
      "natural-map residual of every step, run_parameters.csv), POSTPRO/ (POSTPRO.DAT's commands), "
      "DISPLAY/.\n"
      "Exit: 0 success, 1 invalid data, 2 usage, 3 a step not converged under --strict, 4 an output could "
      "not\n"
      "be written, 5 the case uses what lmgc-solve does not run yet, 6 a state became NaN or infinite,\n"
      "7 a Newton loop (deformable bodies) did not converge at the smallest time step (.LAST of the last\n"
      "converged step),\n"
      "129/130/143 stopped by SIGHUP/SIGINT/SIGTERM after the step in progress (.LAST written).");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  solver::ignore_file_size_signal();
  if (app.count("--rloc-tol")) {
    std::cerr
        << "lmgc-solve: --rloc-tol is not supported: LMGC90's RecupRloc(tol) matches PLPLx reactions by "
           "position within tol, lmgc-solve matches the previous step's reactions by contactor (the NLGS "
           "starts from another guess; the problem solved is the same). Leave the flag out.\n";
    return kExitUsage;
  }

  grammar::DiagnosticSink sink(5000);
  // PTPT3_NETWORK.DAT is read (and checked) only when the run uses it, as LMGC90.
  auto files = case_folder::load_case(case_dir, sink, case_folder::LoadOptions{options.ptpt3_network});
  if (command_dat && no_command_dat) {
    std::cerr << "lmgc-solve: --command-dat and --no-command-dat exclude each other\n";
    return kExitUsage;
  }
  // The driver of the run: the case's command.py (as LMGC90 2025), or COMMAND.DAT. The script runs
  // through lmgc's chipy module (lmgc-run) unless flags ask for lmgc-solve's own loop: a run
  // parameter, --strict, or --read-script; then it is read, not run.
  bool own_loop_flags = read_script || app.count("--strict") > 0 || app.count("--source-point") > 0 ||
                        app.count("--source-point-relative") > 0;
  for (const run::RunParameter& p : run::run_parameters())
    if (!p.flag.empty() && p.flag != "--steps" && app.count(std::string(p.flag))) own_loop_flags = true;
  validate::CheckOptions check_options{!no_command_dat, command_dat};
  const bool script_drives = files && validate::script_drives(*files, check_options);
  const bool script_runs = script_drives && !own_loop_flags;
  check_options.script_read_only = script_drives && own_loop_flags;
  if (script_runs) {
    // Its calls are checked as it runs (chipy/session.hpp); COMMAND.DAT is not read.
    files->command_script.reset();
    files->command.reset();
  }
  if (files) validate::check_case(*files, sink, check_options);
  const bool three_d = files && solver::is_rigid_3d_case(*files);

  // The norm: an unknown one is a usage error, except for rigid 3D cases: LMGC90's 3D NLGS ignores
  // a norm it does not know and keeps Quad (mod_nlgs_3D set_nlgs_parameter has no default branch);
  // the RIGID_3D example 1_ClusterSP_2_PL relies on it with 'MaxM '.
  if (!run::parse_storage(storage, options.nlgs.storage)) {
    std::cerr << "lmgc-solve: unknown --solver '" << storage
              << "' (Stored_Delassus_Loops or Exchange_Local_Global)\n";
    return kExitUsage;
  }
  if (!run::parse_norm(norm, options.nlgs.norm)) {
    if (!three_d) {
      std::cerr << "lmgc-solve: unknown --norm '" << norm << "' (Quad, QuaN, Maxm or QM/16)\n";
      return kExitUsage;
    }
    options.nlgs.norm = solver::NlgsNorm::quad;
    std::cerr << "lmgc-solve: warning: unknown norm '" << norm
              << "': the 3D NLGS keeps 'Quad ' as LMGC90 does\n";
  }

  solver::Scene2D scene;
  solver::RunOutputs2D outputs;
  solver::Scene3D scene_3d;
  solver::RunOutputs3D outputs_3d;
  bool prepared = files && !sink.has_errors() &&
                  (three_d ? solver::prepare_run_3d(*files, scene_3d, outputs_3d, sink)
                           : solver::prepare_run_2d(*files, scene, outputs, sink));
  run::ParameterSources sources;
  if (prepared) {
    // The layers: defaults, the driver's parameters (command.py or COMMAND.DAT), then the flags given
    // on the command line.
    run::RunOptions from_file;  // the defaults
    run::ParameterSources file_sources;
    if (script_runs) {
      // The script sets its parameters as it runs.
    } else if (script_drives) {
      run::apply_script_parameters(*files->command_script, three_d, from_file, file_sources, sink);
    } else if (!no_command_dat && files->command) {
      run::apply_command_parameters(*files->command, validate::datbox_path(*files, "COMMAND.DAT"), three_d,
                                    from_file, sink, &file_sources);
    }
    // --source-point FIRST RADIUS X Y Z fills the source point's fields, which the table then takes.
    if (app.count("--source-point")) {
      if (source_point[0] < 1.0 || source_point[1] <= 0.0) {
        std::cerr << "lmgc-solve: --source-point needs FIRST >= 1 and RADIUS > 0\n";
        return kExitUsage;
      }
      options.source_first = static_cast<long>(source_point[0]);
      options.source_radius = source_point[1];
      for (int d = 0; d < 3; ++d) options.source_point[d] = source_point[static_cast<std::size_t>(d + 2)];
      options.source_point_absolute = !source_point_relative;
    }
    run::RunOptions chosen = from_file;
    chosen.quiet = options.quiet;
    chosen.strict = options.strict;
    sources = file_sources;
    for (const run::RunParameter& p : run::run_parameters()) {
      if (p.flag.empty() || !app.count(std::string(p.flag))) continue;
      p.take(chosen, options);
      sources[std::string(p.name)] = run::ParameterSource::flag;
    }
    options = chosen;
    if (!three_d && (options.y_period > 0.0 || options.source_first > 0 || options.ptpt3_network ||
                     options.ptpt3_current_nonuc0)) {
      std::cerr << "lmgc-solve: --yperiod, --source-point (YPERIODIC CONDITION, INIT SOURCE POINT) and the "
                   "--ptpt3 options apply to RBDY3 cases only\n";
      return kExitUsage;
    }
    // The script LMGC90 runs: say that lmgc-solve does not run it, and every parameter that differs.
    if (files->command_script) {
      const std::string& path = files->command_script->path;
      sink.report(
          "L4011", grammar::Location{path, {}},
          "this case has a command.py, which LMGC90 runs; lmgc-solve reads it without running it and runs " +
              std::string(script_drives                       ? "the run parameters it passes as literals"
                          : files->command && !no_command_dat ? "COMMAND.DAT's parameters"
                                                              : "its defaults") +
              " and the flags");
      for (const run::ScriptDifference& d : run::script_differences(options, *files->command_script)) {
        const auto it = sources.find(d.parameter->name);
        const std::string source(
            run::source_name(it == sources.end() ? run::ParameterSource::default_value : it->second));
        sink.report("L4008",
                    grammar::Location{path, grammar::SourceSpan{d.line, d.column,
                                                                static_cast<std::uint16_t>(d.column + 1)}},
                    std::string(d.parameter->name) + " is " + d.run_value + " (" + source +
                        "); command.py passes " + d.script_value +
                        (d.parameter->flag.empty() ? "" : " (" + std::string(d.parameter->flag) + ")"));
      }
    }
  }

  // Diagnostics: errors and what refuses the run always; other warnings unless --quiet.
  bool refused = false;
  for (const auto& d : sink.items()) refused |= grammar::refuses_run(d.code);
  std::vector<grammar::Diagnostic> shown = sink.items();
  for (auto& d : sink.overflow_diagnostic()) shown.push_back(std::move(d));
  const bool color = std::getenv("NO_COLOR") == nullptr && isatty(STDERR_FILENO);
  const auto lookup = [&](const std::string& file, std::uint32_t line) -> std::string_view {
    if (!files) return {};
    auto it = files->sources.find(file);
    return it == files->sources.end() ? std::string_view{} : it->second.line_text(line);
  };
  for (const auto& d : shown)
    if (d.severity == grammar::Severity::error || grammar::refuses_run(d.code) ||
        (!options.quiet && d.severity == grammar::Severity::warning))
      std::cerr << validate::render_text(d, lookup, {color});
  if (!files) return kExitUsage;
  if (sink.has_errors()) {
    std::cerr << "lmgc-solve: the case cannot run (" << sink.error_count() << " error"
              << (sink.error_count() == 1 ? "" : "s") << ")\n";
    return kExitData;
  }
  if (refused || !prepared) {
    std::set<std::string> codes;
    for (const auto& d : sink.items())
      if (grammar::refuses_run(d.code)) codes.insert(d.code);
    std::string list;
    for (const std::string& c : codes) list += (list.empty() ? "" : ", ") + c;
    std::cerr << "lmgc-solve: refused: the case uses what lmgc-solve does not run yet (" << list
              << "); nothing was written\n";
    return kExitRefused;
  }

  if (script_runs) return run_script(case_dir, app.count("--steps") ? options.steps : -1, options.quiet);
  // Deformable bodies take their 2D hypothesis (plane strain, plane stress, axisymmetric) from the
  // script's SetDimension(2, mhyp): lmgc-solve's own loop does not know it.
  if (!scene.deformable.empty()) {
    std::cerr << "lmgc-solve: refused: this case has MAILx bodies, which run through the case's command.py "
                 "(its SetDimension gives their 2D hypothesis): run lmgc-solve without --read-script and "
                 "run-parameter flags, or lmgc-run\n";
    return kExitRefused;
  }

  // Outputs: stale temporaries of a killed run first, then the echo files LMGC90 writes when it reads
  // the case, and the run's parameters.
  const std::filesystem::path case_path(case_dir);
  for (const char* folder : {"OUTBOX", "POSTPRO", "DISPLAY"})
    grammar::remove_stale_temporaries(case_path / folder);
  std::vector<case_folder::OutputFile> echo =
      three_d ? solver::echo_files_3d(*files) : solver::echo_files_2d(*files);
  echo.push_back({"OUTBOX/run_parameters.csv", run::run_parameters_csv(options, sources)});
  for (const auto& output : echo) {
    std::string error;
    if (!grammar::write_file_whole(case_path / output.relative_path, output.content, error)) {
      std::cerr << "lmgc-solve: " << error << "\n";
      return kExitOutput;
    }
  }
  solver::install_interrupt_handler();
  const solver::RunSummary summary =
      three_d ? solver::run_3d(scene_3d, options, outputs_3d) : solver::run_2d(scene, options, outputs);
  if (!options.quiet || summary.failure != solver::RunFailure::none)
    std::fprintf(
        stderr,
        "%ld steps to t=%.6g; %ld not converged within gs_it1*gs_it2; worst natural-map residual/|q| %.3e\n",
        summary.steps_done, summary.final_time, summary.steps_not_converged, summary.worst_residual);
  switch (summary.failure) {
    case solver::RunFailure::none:
      break;
    case solver::RunFailure::data:
      std::cerr << "lmgc-solve: " << summary.error << "\n";
      return kExitData;
    case solver::RunFailure::output:
      std::cerr << "lmgc-solve: " << summary.error << "\n";
      return kExitOutput;
    case solver::RunFailure::non_finite:
      std::cerr << "lmgc-solve: " << summary.error << "\n";
      return kExitNonFinite;
    case solver::RunFailure::not_converged:  // a Newton loop: its script runs through lmgc-run
      std::cerr << "lmgc-solve: " << summary.error << "\n";
      return kExitNewtonDiverged;
  }
  if (summary.stop_signal != 0) return kExitSignalBase + summary.stop_signal;
  if (options.strict && summary.steps_not_converged > 0) return kExitNotConverged;
  return kExitOk;
}
