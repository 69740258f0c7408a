#include "solver/driver/run_3d.hpp"

#include <chrono>

#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/io/display_3d.hpp"
#include "solver/io/state_files_3d.hpp"

namespace lmgc::solver {

RunSummary run_3d(Scene3D& scene, const RunOptions& options, const RunOutputs3D& outputs) {
  RunSummary summary;
  namespace fs = std::filesystem;
  const fs::path outbox = outputs.case_dir / "OUTBOX";
  std::error_code ec;
  fs::create_directories(outbox, ec);

  scene.x_period = options.x_period;
  scene.y_period = options.y_period;
  // PTPT3 links: the network file's when asked for, else detected (again when periods or current
  // lengths change what the scene's build found).
  const LinkLength length =
      options.ptpt3_current_nonuc0 ? LinkLength::current : LinkLength::reference_configuration;
  if (options.ptpt3_network) {
    if (!outputs.ptpt3_network) {
      summary.error = "--ptpt3-network: " + (outputs.case_dir / "DATBOX" / "PTPT3_NETWORK.DAT").string() +
                      " does not exist";
      return summary;
    }
    if (!network_links_3d(scene, *outputs.ptpt3_network, length, scene.point_links, summary.error))
      return summary;
  } else if (scene.x_period > 0.0 || scene.y_period > 0.0 || length == LinkLength::current) {
    scene.point_links = link_points_3d(scene, length);
  }
  if (options.source_first > 0)
    init_source_point(
        scene, static_cast<std::size_t>(options.source_first - 1), options.source_radius,
        Eigen::Vector3d(options.source_point[0], options.source_point[1], options.source_point[2]));

  RunState3D state;
  state.h = options.dt;
  state.theta = options.theta;
  state.scramble = QuickScramble(options.nlgs.scramble_seed);
  if (outputs.warm_start) {
    const WarmStart3D warm = warm_start_3d(*outputs.warm_start, scene, options.dt);
    store_interactions(state, warm.interactions, warm.law_states);
  }

  Postpro3D postpro;
  if (!outputs.postpro.empty() && !postpro.open(outputs.case_dir / "POSTPRO", outputs.postpro, summary.error))
    return summary;
  DisplayWriter3D display(outputs.case_dir / "DISPLAY");

  StepLog log(outbox, options);
  long written = 0;
  const auto write_state = [&](const std::string& suffix) {
    return grammar::write_file_whole(outbox / ("DOF." + suffix),
                                     grammar::write_dof(dof_file_3d(scene, state)), summary.error) &&
           grammar::write_file_whole(outbox / ("Vloc_Rloc." + suffix),
                                     grammar::write_vloc_rloc(vloc_rloc_file_3d(scene, state)),
                                     summary.error);
  };
  for (long k = 0; k < options.steps; ++k) {
    const auto step_start = std::chrono::steady_clock::now();
    const NlgsResult result = step_3d(scene, state, options.nlgs);
    const double step_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
    log.record(state.step, state.time, state.contacts.size(), result, kinetic_energy(scene.bodies),
               step_seconds, summary);
    if (!outputs.postpro.empty()) postpro.write(scene, state, result);
    if (options.write_every > 0 && state.step % options.write_every == 0)
      if (!write_state("OUT." + std::to_string(++written))) break;
    if (options.display_every > 0 && state.step % options.display_every == 0)
      if (!display.write(scene, state, summary.error)) break;
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
