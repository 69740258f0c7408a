#include "solver/driver/run_2d.hpp"

#include <chrono>
#include <csignal>

#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "solver/io/display_2d.hpp"
#include "solver/io/state_files_2d.hpp"

namespace lmgc::solver {

std::atomic<bool> g_stop_requested{false};

namespace {
extern "C" void on_interrupt(int) {
  g_stop_requested.store(true);
}
}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
}

RunSummary run_2d(Scene2D& scene, const RunOptions& options, const RunOutputs2D& outputs) {
  RunSummary summary;
  namespace fs = std::filesystem;
  const fs::path outbox = outputs.case_dir / "OUTBOX";
  std::error_code ec;
  fs::create_directories(outbox, ec);

  scene.y_min = options.y_min;
  scene.y_max = options.y_max;
  scene.x_min = options.x_min;
  scene.x_max = options.x_max;
  scene.x_period = options.x_period;

  RunState2D state;
  state.h = options.dt;
  state.theta = options.theta;
  state.scramble = QuickScramble(options.nlgs.scramble_seed);
  state.visibility = build_visibility_index(scene);
  if (outputs.warm_start) {
    const WarmStart2D warm = warm_start_2d(*outputs.warm_start, scene, options.dt);
    store_interactions(state, warm.interactions, warm.law_states);
  }

  Postpro2D postpro;
  if (!outputs.postpro.empty() && !postpro.open(outputs.case_dir / "POSTPRO", outputs.postpro, summary.error))
    return summary;
  DisplayWriter2D display(outputs.case_dir / "DISPLAY");

  // The run report: one line per step, flushed, so an interrupted run keeps what it did.
  StepLog log(outbox, options);

  long written = 0;
  auto write_state = [&](const std::string& suffix) {
    if (!grammar::write_file_whole(outbox / ("DOF." + suffix), grammar::write_dof(dof_file_2d(scene, state)),
                                   summary.error))
      return false;
    if (outputs.vloc_rloc_text &&
        !grammar::write_file_whole(outbox / ("Vloc_Rloc." + suffix), outputs.vloc_rloc_text(scene, state),
                                   summary.error))
      return false;
    return true;
  };

  for (long k = 0; k < options.steps; ++k) {
    const auto step_start = std::chrono::steady_clock::now();
    const NlgsResult result = step_2d(scene, state, options.nlgs);
    const double step_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
    log.record(state.step, state.time, state.contacts.size(), result, kinetic_energy(scene.bodies),
               step_seconds, summary);
    if (!outputs.postpro.empty()) postpro.write(scene, state, result);
    if (options.write_every > 0 && state.step % options.write_every == 0) {
      if (!write_state("OUT." + std::to_string(++written))) break;
    }
    if (options.display_every > 0 && state.step % options.display_every == 0) {
      if (!display.write(scene, state, summary.error)) break;
    }
    if (g_stop_requested.load()) {
      summary.interrupted = true;
      break;
    }
  }
  summary.final_time = state.time;
  if (summary.error.empty()) write_state("LAST");
  postpro.close();
  return summary;
}

}  // namespace lmgc::solver
