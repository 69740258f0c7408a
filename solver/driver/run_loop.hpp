#pragma once
// The run loop both dimensions share: steps, the outputs after each (run report, POSTPRO, DOF and
// Vloc_Rloc .OUT.n, DISPLAY), the checks that stop a run (an output that cannot be written, a state
// that is no longer finite, a stop signal), and the .LAST files at the end. Written whole or not at
// all: a run that stops keeps every file it completed, and never writes a non-finite state.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>

#include "grammar/common/output_file.hpp"
#include "run/run_options.hpp"
#include "solver/driver/step_log.hpp"

namespace lmgc::solver {

// Signal handling: SIGINT, SIGTERM and SIGHUP (what batch schedulers send) set the signal number;
// the loop finishes the step, writes .LAST and returns.
extern std::atomic<int> g_stop_signal;
void install_interrupt_handler();
// SIGXFSZ ignored: a write past `ulimit -f` fails (exit 4) rather than kill the program mid-file.
void ignore_file_size_signal();

// What one dimension provides to the loop (2D and 3D in run_2d.cpp and run_3d.cpp).
template <class Scene, class State>
struct RunDimension {
  NlgsResult (*step)(Scene&, State&, const NlgsOptions&);
  double (*kinetic_energy)(const Scene&);
  // The first body whose state is not finite, as "body N: velocity" (empty when all are finite).
  std::string (*non_finite)(const Scene&, const State&);
  std::string (*dof_text)(const Scene&, const State&);
  std::string (*vloc_rloc_text)(const Scene&, const State&);
  std::string (*exact_state)(const Scene&, const State&);  // EXACT_STATE.LAST (solver/io/exact_state.hpp)
  // GPV.OUT.n / GPV.LAST (deformable bodies' Gauss-point values); empty when the scene has none.
  std::string (*gpv_text)(const Scene&, const State&) = nullptr;
  // Whether EXACT_STATE.LAST holds the whole state (not when deformable bodies are in the scene).
  bool (*exact_state_complete)(const Scene&) = nullptr;
};

template <class Scene, class State, class Postpro, class Display>
RunSummary run_loop(Scene& scene, State& state, const run::RunOptions& options,
                    const std::filesystem::path& case_dir, Postpro& postpro, bool postpro_open,
                    Display& display, const RunDimension<Scene, State>& dimension) {
  namespace fs = std::filesystem;
  RunSummary summary;
  const fs::path outbox = case_dir / "OUTBOX";
  StepLog log(outbox, options);
  if (!log.good()) {
    summary.fail(RunFailure::output, log.error());
    return summary;
  }
  long written = 0;
  // GPV.<suffix>, computed once, when the scene has Gauss-point values.
  const auto write_gpv = [&](const std::string& suffix) {
    if (!dimension.gpv_text) return true;
    const std::string gpv = dimension.gpv_text(scene, state);
    std::string error;
    return gpv.empty() || grammar::write_file_whole(outbox / ("GPV." + suffix), gpv, error) ||
           (summary.fail(RunFailure::output, error), false);
  };
  const auto write_state = [&](const std::string& suffix) {
    std::string error;
    const bool ok =
        grammar::write_file_whole(outbox / ("DOF." + suffix), dimension.dof_text(scene, state), error) &&
        grammar::write_file_whole(outbox / ("Vloc_Rloc." + suffix), dimension.vloc_rloc_text(scene, state),
                                  error) &&
        write_gpv(suffix) &&
        (suffix != "LAST" || (dimension.exact_state_complete && !dimension.exact_state_complete(scene)) ||
         grammar::write_file_whole(outbox / "EXACT_STATE.LAST", dimension.exact_state(scene, state), error));
    if (!ok) summary.fail(RunFailure::output, error);
    return ok;
  };
  for (long k = 0; k < options.steps; ++k) {
    const auto step_start = std::chrono::steady_clock::now();
    const NlgsResult result = dimension.step(scene, state, options.nlgs);
    const double step_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
    // A state that is no longer finite is never written: the run stops before this step's outputs.
    if (const std::string where = dimension.non_finite(scene, state); !where.empty()) {
      summary.fail(RunFailure::non_finite, "the state is not finite after step " +
                                               std::to_string(state.step) +
                                               " (t = " + std::to_string(state.time) + "): " + where +
                                               "; no output of this step is written, and no .LAST");
      break;
    }
    log.record(state.step, state.time, state.contacts.size(), result, dimension.kinetic_energy(scene),
               step_seconds, summary);
    if (!log.good()) {
      summary.fail(RunFailure::output, log.error());
      break;
    }
    std::string error;
    if (postpro_open && !postpro.write(scene, state, result, error)) {
      summary.fail(RunFailure::output, error);
      break;
    }
    if (options.write_every > 0 && state.step % options.write_every == 0 &&
        !write_state("OUT." + std::to_string(++written)))
      break;
    if (options.display_every > 0 && state.step % options.display_every == 0 &&
        !display.write(scene, state, error)) {
      summary.fail(RunFailure::output, error);
      break;
    }
    if (const int signal = g_stop_signal.load(); signal != 0) {
      summary.stop_signal = signal;
      break;
    }
  }
  summary.final_time = state.time;
  // .LAST after a run that ended, was stopped by a signal or by an output failure (the state is
  // good then; the write may fail again, reported once); never after a non-finite state.
  if (summary.failure != RunFailure::non_finite) write_state("LAST");
  std::string error;
  if (postpro_open && !postpro.close(error) && summary.failure == RunFailure::none)
    summary.fail(RunFailure::output, error);
  if (!log.close() && summary.failure == RunFailure::none) summary.fail(RunFailure::output, log.error());
  return summary;
}

}  // namespace lmgc::solver
