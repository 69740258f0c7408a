// lmgc-solve: runs an LMGC90 case (rigid 2D; rigid 3D with spheres and planes) and writes what LMGC90 writes:
// OUTBOX echo and state files, DISPLAY, POSTPRO, plus a per-step run report with the achieved residual. Exit:
// 0 success, 1 invalid data, 2 usage, 3 not converged under --strict, 130 interrupted.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "grammar/common/output_file.hpp"
#include "solver/driver/case_input.hpp"
#include "solver/driver/run_2d.hpp"
#include "validate/case_files.hpp"
#include "validate/checks.hpp"
#include "validate/render.hpp"

namespace {
constexpr int kExitOk = 0;

// Whether BODIES.DAT holds RBDY3 bodies only (a cheap look before the case is loaded).
bool rigid_3d_folder(const std::string& case_dir) {
  std::ifstream in(std::filesystem::path(case_dir) / "DATBOX" / "BODIES.DAT");
  std::string line;
  bool any = false;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos) continue;
    const bool body_line = line.compare(first, 4, "RBDY") == 0 || line.compare(first, 5, "MAILx") == 0;
    if (!body_line) continue;
    if (line.compare(first, 5, "RBDY3") != 0) return false;
    any = true;
  }
  return any;
}
constexpr int kExitData = 1;
constexpr int kExitUsage = 2;
constexpr int kExitNotConverged = 3;
constexpr int kExitInterrupted = 130;
}  // namespace

int main(int argc, char** argv) {
  using namespace lmgc;
  CLI::App app{
      "lmgc-solve: run an LMGC90 case folder (CASE_DIR/DATBOX/) with the Moreau-Jean scheme and NLGS"};
  std::string case_dir;
  solver::RunOptions options;
  std::string storage = "Stored_Delassus_Loops", norm = "Quad";
  app.add_option("CASE_DIR", case_dir, "case folder holding DATBOX/")->required();
  app.add_option("--dt", options.dt, "time step [s]")->check(CLI::PositiveNumber);
  app.add_option("--theta", options.theta, "theta of the Moreau-Jean scheme, in [0.5, 1]")
      ->check(CLI::Range(0.5, 1.0));
  app.add_option("--steps", options.steps, "number of steps")->check(CLI::NonNegativeNumber);
  app.add_option("--solver", storage, "NLGS storage: Stored_Delassus_Loops or Exchange_Local_Global");
  app.add_option("--norm", norm, "NLGS convergence norm: Quad, QuaN, Maxm or QM/16");
  app.add_option("--tol", options.nlgs.tolerance, "NLGS tolerance of the norm")->check(CLI::PositiveNumber);
  app.add_option("--relax", options.nlgs.relax, "NLGS relaxation")->check(CLI::Range(0.0, 2.0));
  app.add_option("--gs-it1", options.nlgs.gs_it1, "NLGS sweeps between two convergence checks")
      ->check(CLI::PositiveNumber);
  app.add_option("--gs-it2", options.nlgs.gs_it2, "maximum number of convergence checks")
      ->check(CLI::PositiveNumber);
  app.add_flag("--quick-scramble", options.nlgs.quick_scramble,
               "scramble the contact order before each block of sweeps as LMGC90 does");
  app.add_option("--scramble-seed", options.nlgs.scramble_seed,
                 "seed of the quick scramble's random lists (LMGC90's differ from run to run)");
  app.add_flag("--diagonal-resolution", options.nlgs.diagonal_resolution,
               "3D: solve each contact with the diagonal of its Delassus block, then project on the "
               "Coulomb cone (nlgs_3D_DiagonalResolution)");
  app.add_option("--residual-target", options.nlgs.residual_target,
                 "also stop a step when the natural-map residual / |q| is below this (0 = off)");
  app.add_option("--rloc-tol", options.rloc_tol,
                 "warm-start matching tolerance (accepted; contactor matching is used)");
  app.add_option("--write-every", options.write_every,
                 "write DOF/Vloc_Rloc .OUT.n every n steps (0 = never)");
  app.add_option("--display-every", options.display_every, "write DISPLAY files every n steps (0 = never)");
  app.add_option("--ymin-boundary", options.y_min,
                 "bodies whose centre goes below this become invisible (RBDY2_SetYminBoundary)");
  app.add_option("--ymax-boundary", options.y_max, "... above this");
  app.add_option("--xmin-boundary", options.x_min, "... left of this");
  app.add_option("--xmax-boundary", options.x_max, "... right of this");
  app.add_option("--xperiod", options.x_period, "periodic in x with this period (SetPeriodicCondition)");
  app.add_option("--yperiod", options.y_period, "3D: periodic in y with this period (SetPeriodicCondition)");
  app.add_flag("--ptpt3-network", options.ptpt3_network,
               "3D: link PT3Dx points as DATBOX/PTPT3_NETWORK.DAT lists instead of by distance "
               "(PTPT3_LoadNetwork)");
  app.add_flag("--ptpt3-current-nonuc0", options.ptpt3_current_nonuc0,
               "3D: PTPT3 reference lengths from the network file's nonuc0, or for detected links from "
               "the positions at the start (PTPT3_UseCurrentNonuc0(1))");
  std::vector<double> source_point;
  app.add_option("--source-point", source_point,
                 "3D: FIRST RADIUS X Y Z: bodies after FIRST enter one by one at (X, Y, Z), each when the "
                 "previous one is farther than RADIUS from it (RBDY3_SetSourcePointWithIni)")
      ->expected(5)
      ->delimiter(',');
  app.add_flag("-q,--quiet", options.quiet, "no progress line");
  app.add_flag("--new-rotation-scheme", options.new_rotation_scheme,
               "RBDY3: update the principal frame by the Cayley map (RBDY3_NewRotationScheme)");
  app.add_flag("--strict", options.strict, "exit 3 when a step stopped at the iteration cap");
  app.set_version_flag("--version", "lmgc-solve 0.1.0");
  app.footer(
      "Run parameters come from CASE_DIR/DATBOX/COMMAND.DAT when it exists (TIME STEP, THETA, the step "
      "loop's\n"
      "REPETE count, NLGS CHECK TYPE, the NLGS loops, WRITE OUT DOF STEP, ...); a flag given here overrides\n"
      "the file. Without COMMAND.DAT the defaults are --dt 1e-3 --theta 0.5 --steps 1000 --norm Quad --tol "
      "1.666e-4\n"
      "--gs-it1 50 --gs-it2 500.\n"
      "Outputs: OUTBOX/ (echo files, DOF and Vloc_Rloc .OUT.n and .LAST, run_report.csv with the achieved\n"
      "natural-map residual of every step), POSTPRO/ (POSTPRO.DAT's commands), DISPLAY/ (ParaView).\n"
      "Exit: 0 success, 1 invalid data, 2 usage, 3 a step not converged under --strict, 130 interrupted.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  // An unknown norm is a usage error, except for rigid 3D cases: LMGC90's 3D NLGS ignores a norm it
  // does not know and keeps Quad (mod_nlgs_3D set_nlgs_parameter has no default branch); the
  // RIGID_3D example 1_ClusterSP_2_PL relies on it with 'MaxM '.
  const bool norm_known = solver::parse_norm(norm, options.nlgs.norm);
  if (!solver::parse_storage(storage, options.nlgs.storage) ||
      (!norm_known && !(app.count("CASE_DIR") && rigid_3d_folder(case_dir)))) {
    std::cerr << "lmgc-solve: unknown --solver or --norm value\n";
    return kExitUsage;
  }
  if (!norm_known) {
    options.nlgs.norm = solver::NlgsNorm::quad;
    if (!options.quiet)
      std::cerr << "lmgc-solve: warning: unknown norm '" << norm
                << "': the 3D NLGS keeps 'Quad ' as LMGC90 does\n";
  }

  grammar::DiagnosticSink sink(5000);
  // PTPT3_NETWORK.DAT is read (and checked) only when the run uses it, as LMGC90.
  auto files = validate::load_case(case_dir, sink, validate::LoadOptions{options.ptpt3_network});
  if (files) validate::check_case(*files, sink);
  solver::Scene2D scene;
  solver::RunOutputs2D outputs;
  solver::Scene3D scene_3d;
  solver::RunOutputs3D outputs_3d;
  const bool three_d = files && solver::is_rigid_3d_case(*files);
  bool ready = files && !sink.has_errors() &&
               (three_d ? solver::prepare_run_3d(*files, scene_3d, outputs_3d, sink)
                        : solver::prepare_run_2d(*files, scene, outputs, sink));
  if (ready) {
    // COMMAND.DAT's parameters first, then the flags given on the command line on top of them.
    solver::RunOptions from_file;
    solver::apply_command_parameters(*files, from_file, sink);
    const auto given = [&](const char* flag) { return app.count(flag) > 0; };
    if (!given("--dt")) options.dt = from_file.dt;
    if (!given("--theta")) options.theta = from_file.theta;
    if (!given("--steps")) options.steps = from_file.steps;
    if (!given("--solver")) options.nlgs.storage = from_file.nlgs.storage;
    if (!given("--norm")) options.nlgs.norm = from_file.nlgs.norm;
    if (!given("--tol")) options.nlgs.tolerance = from_file.nlgs.tolerance;
    if (!given("--relax")) options.nlgs.relax = from_file.nlgs.relax;
    if (!given("--gs-it1")) options.nlgs.gs_it1 = from_file.nlgs.gs_it1;
    if (!given("--gs-it2")) options.nlgs.gs_it2 = from_file.nlgs.gs_it2;
    if (!given("--quick-scramble")) options.nlgs.quick_scramble = from_file.nlgs.quick_scramble;
    if (!given("--diagonal-resolution"))
      options.nlgs.diagonal_resolution = from_file.nlgs.diagonal_resolution;
    if (!given("--write-every")) options.write_every = from_file.write_every;
    if (!given("--display-every")) options.display_every = from_file.display_every;
    if (!given("--ymin-boundary")) options.y_min = from_file.y_min;
    if (!given("--xperiod")) options.x_period = from_file.x_period;
    if (!given("--new-rotation-scheme")) options.new_rotation_scheme = from_file.new_rotation_scheme;
    if (!given("--yperiod")) options.y_period = from_file.y_period;
    if (given("--source-point")) {
      options.source_first = static_cast<long>(source_point[0]);
      options.source_radius = source_point[1];
      for (int d = 0; d < 3; ++d) options.source_point[d] = source_point[static_cast<std::size_t>(d + 2)];
    } else {
      options.source_first = from_file.source_first;
      options.source_radius = from_file.source_radius;
      for (int d = 0; d < 3; ++d) options.source_point[d] = from_file.source_point[d];
    }
    if (!three_d && (options.y_period > 0.0 || options.source_first > 0 || options.ptpt3_network ||
                     options.ptpt3_current_nonuc0)) {
      std::cerr << "lmgc-solve: --yperiod, --source-point (YPERIODIC CONDITION, INIT SOURCE POINT) and the "
                   "--ptpt3 options apply to RBDY3 cases only\n";
      return kExitUsage;
    }
  }
  // Diagnostics: errors always, warnings and notes unless --quiet (the run goes on with them).
  const bool color = std::getenv("NO_COLOR") == nullptr && isatty(STDERR_FILENO);
  const auto lookup = [&](const std::string& file, std::uint32_t line) -> std::string_view {
    if (!files) return {};
    auto it = files->sources.find(file);
    return it == files->sources.end() ? std::string_view{} : it->second.line_text(line);
  };
  for (const auto& d : sink.items())
    if (d.severity == grammar::Severity::error ||
        (!options.quiet && d.severity == grammar::Severity::warning))
      std::cerr << validate::render_text(d, lookup, {color});
  if (!ready) {
    std::cerr << "lmgc-solve: the case cannot run (" << sink.error_count() << " error"
              << (sink.error_count() == 1 ? "" : "s") << ")\n";
    return files ? kExitData : kExitUsage;
  }
  // The echo files, as LMGC90 writes them when it reads the case.
  for (const auto& output : three_d ? solver::echo_files_3d(*files) : solver::echo_files_2d(*files)) {
    std::string error;
    if (!grammar::write_file_whole(std::filesystem::path(case_dir) / output.relative_path, output.content,
                                   error)) {
      std::cerr << "lmgc-solve: " << error << "\n";
      return kExitData;
    }
  }
  solver::install_interrupt_handler();
  if (options.new_rotation_scheme) scene_3d.rotation = solver::FrameUpdate::cayley;
  const solver::RunSummary summary =
      three_d ? solver::run_3d(scene_3d, options, outputs_3d) : solver::run_2d(scene, options, outputs);
  if (!summary.error.empty()) {
    std::cerr << "lmgc-solve: " << summary.error << "\n";
    return kExitData;
  }
  if (!options.quiet)
    std::fprintf(
        stderr,
        "%ld steps to t=%.6g; %ld not converged within gs_it1*gs_it2; worst natural-map residual/|q| %.3e\n",
        summary.steps_done, summary.final_time, summary.steps_not_converged, summary.worst_residual);
  if (summary.interrupted) return kExitInterrupted;
  if (options.strict && summary.steps_not_converged > 0) return kExitNotConverged;
  return kExitOk;
}
