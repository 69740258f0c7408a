// Fuzz target: a whole case as lmgc-check and lmgc-solve take it. The first byte chooses the base
// case (a 2D column of disks or a 3D stack of cubes) and which of its files the rest of the input
// replaces; the case is then loaded, checked, prepared for a run and, when it may run, stepped
// three times in memory.
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "grammar/common/diagnostic_catalogue.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/case_input.hpp"
#include "solver/integrator/step_2d.hpp"
#include "solver/integrator/step_3d.hpp"
#include "validate/checks.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::array kFiles = {"DATBOX/BODIES.DAT",     "DATBOX/BULK_BEHAV.DAT", "DATBOX/TACT_BEHAV.DAT",
                               "DATBOX/DRV_DOF.DAT",    "DATBOX/DOF.INI",        "DATBOX/Vloc_Rloc.INI",
                               "DATBOX/POSTPRO.DAT",    "DATBOX/COMMAND.DAT",    "command.py",
                               "DATBOX/EXACT_STATE.INI"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc;
  if (size == 0) return 0;
  const bool three_d = data[0] & 0x80;
  const std::size_t which = (data[0] & 0x7f) % kFiles.size();
  static const fs::path scratch =
      fs::temp_directory_path() / ("lmgc_case_fuzz_" + std::to_string(::getpid()));
  const fs::path base =
      fs::path(LMGC_SOURCE_DIR) / "reference_cases" / (three_d ? "cube_stack_10_3d" : "disk_column_20");
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  fs::copy(base / "DATBOX", scratch / "DATBOX", fs::copy_options::recursive);
  std::ofstream(scratch / kFiles[which], std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));

  grammar::DiagnosticSink sink(5000);
  auto files = case_folder::load_case(scratch, sink);
  if (!files) return 0;
  const validate::CheckOptions check_options;
  validate::check_case(*files, sink, check_options);
  solver::report_solver_support(*files, sink);
  if (sink.has_errors()) return 0;
  for (const auto& d : sink.items())
    if (grammar::refuses_run(d.code)) return 0;
  // The run's parameters from its driver, as lmgc-solve takes them.
  run::RunOptions options;
  run::ParameterSources sources;
  if (validate::script_drives(*files, check_options))
    run::apply_script_parameters(*files->command_script, solver::is_rigid_3d_case(*files), options, sources,
                                 sink);
  else if (files->command)
    run::apply_command_parameters(*files->command, "COMMAND.DAT", solver::is_rigid_3d_case(*files), options,
                                  sink);
  if (sink.has_errors()) return 0;
  options.nlgs.gs_it1 = 5;
  options.nlgs.gs_it2 = 5;
  if (solver::is_rigid_3d_case(*files)) {
    solver::Scene3D scene;
    solver::RunOutputs3D outputs;
    if (!solver::prepare_run_3d(*files, scene, outputs, sink)) return 0;
    solver::RunState3D state;
    state.h = options.dt;
    for (int k = 0; k < 3; ++k) solver::step_3d(scene, state, options.nlgs);
  } else {
    solver::Scene2D scene;
    solver::RunOutputs2D outputs;
    if (!solver::prepare_run_2d(*files, scene, outputs, sink)) return 0;
    solver::RunState2D state;
    state.h = options.dt;
    state.visibility = solver::build_visibility_index(scene);
    for (int k = 0; k < 3; ++k) solver::step_2d(scene, state, options.nlgs);
  }
  return 0;
}
