#include "solver/driver/run_2d.hpp"

#include <chrono>

#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/gpv/writer.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/io/display_2d.hpp"
#include "solver/io/exact_state.hpp"
#include "solver/io/mesh_gauss_values.hpp"
#include "solver/io/state_files_2d.hpp"

namespace lmgc::solver {

std::string non_finite_2d(const Scene2D& scene, const RunState2D&) {
  const RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.displacement[i].allFinite()) return "body " + std::to_string(i + 1) + ": displacement X";
    if (!b.velocity[i].allFinite()) return "body " + std::to_string(i + 1) + ": velocity V";
  }
  const DeformableBodies& d = scene.deformable;
  for (std::size_t m = 0; m < d.states.size(); ++m)
    if (!d.states[m].x.allFinite() || !d.states[m].v.allFinite())
      return "MAILx " + std::to_string(m + 1) + ": nodal displacement or velocity";
  return {};
}

bool start_run_2d(Scene2D& scene, const run::RunOptions& options, const RunOutputs2D& outputs,
                  RunState2D& state, RunSummary& summary) {
  scene.y_min = options.y_min;
  scene.y_max = options.y_max;
  scene.x_min = options.x_min;
  scene.x_max = options.x_max;
  scene.x_period = options.x_period;

  if (options.zero_initial_velocity)
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      scene.bodies.velocity_begin[i].setZero();
      scene.bodies.velocity[i].setZero();
    }

  state = RunState2D{};
  state.step = outputs.initial_step;
  state.time = outputs.initial_time;
  state.h = options.dt;
  state.theta = options.theta;
  state.scramble = QuickScramble(options.nlgs.scramble_seed);
  state.visibility = build_visibility_index(scene);
  if (outputs.warm_start) {
    const WarmStart2D warm = warm_start_2d(*outputs.warm_start, scene, options.dt);
    store_interactions(state, warm.interactions, warm.law_states);
  }
  if (outputs.exact_state && !restore_exact_state(*outputs.exact_state, scene, state, summary.error)) {
    summary.error = "DATBOX/EXACT_STATE.INI: " + summary.error;
    summary.failure = RunFailure::data;
    return false;
  }
  return true;
}

RunSummary run_2d(Scene2D& scene, const run::RunOptions& options, const RunOutputs2D& outputs) {
  namespace fs = std::filesystem;
  const fs::path outbox = outputs.case_dir / "OUTBOX";
  std::error_code ec;
  fs::create_directories(outbox, ec);

  RunSummary summary;
  RunState2D state;
  if (!start_run_2d(scene, options, outputs, state, summary)) return summary;
  Postpro2D postpro;
  if (!outputs.postpro.empty() &&
      !postpro.open(outputs.case_dir / "POSTPRO", outputs.postpro, summary.error)) {
    summary.failure = RunFailure::output;
    return summary;
  }
  DisplayWriter2D display(outputs.case_dir / "DISPLAY");
  const RunDimension<Scene2D, RunState2D> dimension{
      [](Scene2D& s, RunState2D& st, const NlgsOptions& o) { return step_2d(s, st, o); },
      [](const Scene2D& s) { return kinetic_energy(s.bodies) + kinetic_energy(s.deformable); },
      non_finite_2d,
      [](const Scene2D& s, const RunState2D& st) { return grammar::write_dof(dof_file_2d(s, st)); },
      [](const Scene2D& s, const RunState2D& st) {
        return grammar::write_vloc_rloc(vloc_rloc_file_2d(s, st));
      },
      [](const Scene2D& s, const RunState2D& st) { return write_exact_state(s, st); },
      [](const Scene2D& s, const RunState2D& st) {
        return s.deformable.empty()
                   ? std::string()
                   : grammar::write_gpv(gauss_point_values_file(s.deformable, st.step, st.time));
      },
      [](const Scene2D& s) { return s.deformable.empty(); },
  };
  return run_loop(scene, state, options, outputs.case_dir, postpro, !outputs.postpro.empty(), display,
                  dimension);
}

}  // namespace lmgc::solver
