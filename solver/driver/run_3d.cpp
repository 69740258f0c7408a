#include "solver/driver/run_3d.hpp"

#include <chrono>

#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/io/display_3d.hpp"
#include "solver/io/exact_state.hpp"
#include "solver/io/state_files_3d.hpp"

namespace lmgc::solver {

std::string non_finite_3d(const Scene3D& scene, const RunState3D&) {
  const RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.displacement[i].allFinite()) return "body " + std::to_string(i + 1) + ": displacement X";
    if (!b.velocity[i].allFinite()) return "body " + std::to_string(i + 1) + ": velocity V";
    if (!b.frame[i].allFinite()) return "body " + std::to_string(i + 1) + ": principal frame";
  }
  return {};
}

bool start_run_3d(Scene3D& scene, const run::RunOptions& options, const RunOutputs3D& outputs,
                  RunState3D& state, RunSummary& summary) {
  if (options.new_rotation_scheme) scene.rotation = FrameUpdate::cayley;
  scene.x_period = options.x_period;
  scene.y_period = options.y_period;
  scene.cundall_iterations = options.cundall_iterations;
  // PTPT3 links: the network file's when asked for, else detected (again when periods or current
  // lengths change what the scene's build found).
  const LinkLength length =
      options.ptpt3_current_nonuc0 ? LinkLength::current : LinkLength::reference_configuration;
  if (options.ptpt3_network) {
    if (!outputs.ptpt3_network) {
      summary.fail(RunFailure::data,
                   "--ptpt3-network: " + (outputs.case_dir / "DATBOX" / "PTPT3_NETWORK.DAT").string() +
                       " does not exist");
      return false;
    }
    if (!network_links_3d(scene, *outputs.ptpt3_network, length, scene.point_links, summary.error)) {
      summary.failure = RunFailure::data;
      return false;
    }
  } else if (scene.x_period > 0.0 || scene.y_period > 0.0 || length == LinkLength::current) {
    scene.point_links = link_points_3d(scene, length);
  }
  if (options.source_first > 0)
    init_source_point(
        scene, static_cast<std::size_t>(options.source_first - 1), options.source_radius,
        Eigen::Vector3d(options.source_point[0], options.source_point[1], options.source_point[2]),
        options.source_point_absolute);

  if (options.zero_initial_velocity)
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      scene.bodies.velocity_begin[i].setZero();
      scene.bodies.velocity[i].setZero();
    }

  state = RunState3D{};
  state.step = outputs.initial_step;
  state.time = outputs.initial_time;
  state.h = options.dt;
  state.theta = options.theta;
  state.scramble = QuickScramble(options.nlgs.scramble_seed);
  if (outputs.warm_start) {
    const WarmStart3D warm = warm_start_3d(*outputs.warm_start, scene, options.dt);
    store_interactions(state, warm.interactions, warm.law_states);
  }

  if (outputs.exact_state && !restore_exact_state(*outputs.exact_state, scene, state, summary.error)) {
    summary.error = "DATBOX/EXACT_STATE.INI: " + summary.error;
    summary.failure = RunFailure::data;
    return false;
  }
  return true;
}

RunSummary run_3d(Scene3D& scene, const run::RunOptions& options, const RunOutputs3D& outputs) {
  RunSummary summary;
  namespace fs = std::filesystem;
  const fs::path outbox = outputs.case_dir / "OUTBOX";
  std::error_code ec;
  fs::create_directories(outbox, ec);
  RunState3D state;
  if (!start_run_3d(scene, options, outputs, state, summary)) return summary;

  Postpro3D postpro;
  if (!outputs.postpro.empty() &&
      !postpro.open(outputs.case_dir / "POSTPRO", outputs.postpro, summary.error)) {
    summary.failure = RunFailure::output;
    return summary;
  }
  DisplayWriter3D display(outputs.case_dir / "DISPLAY");
  const RunDimension<Scene3D, RunState3D> dimension{
      [](Scene3D& s, RunState3D& st, const NlgsOptions& o) { return step_3d(s, st, o); },
      [](const Scene3D& s) { return kinetic_energy(s.bodies); },
      non_finite_3d,
      [](const Scene3D& s, const RunState3D& st) { return grammar::write_dof(dof_file_3d(s, st)); },
      [](const Scene3D& s, const RunState3D& st) {
        return grammar::write_vloc_rloc(vloc_rloc_file_3d(s, st));
      },
      [](const Scene3D& s, const RunState3D& st) { return write_exact_state(s, st); },
  };
  return run_loop(scene, state, options, outputs.case_dir, postpro, !outputs.postpro.empty(), display,
                  dimension);
}

}  // namespace lmgc::solver
