#include "solver/driver/run_3d.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>

#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/io/display_3d.hpp"
#include "solver/io/state_files_3d.hpp"

namespace lmgc::solver {

RunSummary run_3d(Scene3D& scene, const RunOptions& options, const RunOutputs3D& outputs) {
  RunSummary summary;
  namespace fs = std::filesystem;
  const fs::path outbox = outputs.case_dir / "OUTBOX";
  std::error_code ec;
  fs::create_directories(outbox, ec);

  RunState3D state;
  state.h = options.dt;
  state.theta = options.theta;
  if (outputs.warm_start) state.previous = warm_start_3d(*outputs.warm_start, scene, options.dt);

  Postpro3D postpro;
  if (!outputs.postpro.empty() && !postpro.open(outputs.case_dir / "POSTPRO", outputs.postpro, summary.error))
    return summary;
  DisplayWriter3D display(outputs.case_dir / "DISPLAY");

  std::ofstream report(outbox / "run_report.csv", std::ios::trunc);
  report << "step,time,contacts,active,iterations,converged,mean_dvor,quad_dv,quad_dvr,"
            "residual_natural_map_over_q,kinetic_energy,step_seconds,nlgs_seconds\n";
  const bool progress = !options.quiet && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
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
    ++summary.steps_done;
    if (!result.converged) ++summary.steps_not_converged;
    summary.worst_residual = std::max(summary.worst_residual, result.residual_relative);
    report << fmt::format("{},{:.10g},{},{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.10e},{:.6e},{:.6e}\n",
                          state.step, state.time, state.contacts.size(), result.active, result.iterations,
                          result.converged ? 1 : 0, result.norms.mean_dvor, result.norms.quad_dv,
                          result.norms.quad_dvr, result.residual_relative, kinetic_energy(scene.bodies),
                          step_seconds, result.seconds);
    report.flush();
    if (!outputs.postpro.empty()) postpro.write(scene, state, result);
    if (options.write_every > 0 && state.step % options.write_every == 0)
      if (!write_state("OUT." + std::to_string(++written))) break;
    if (options.display_every > 0 && state.step % options.display_every == 0)
      if (!display.write(scene, state, summary.error)) break;
    if (progress) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double eta = elapsed / static_cast<double>(k + 1) * static_cast<double>(options.steps - k - 1);
      std::fprintf(stderr, "\rstep %ld/%ld  t=%.6g  contacts=%zu  iterations=%d  residual=%.2e  ETA %.0fs   ",
                   state.step, options.steps, state.time, state.contacts.size(), result.iterations,
                   result.residual_relative, eta);
    }
    if (g_stop_requested.load()) {
      summary.interrupted = true;
      break;
    }
  }
  if (progress) std::fprintf(stderr, "\n");
  summary.final_time = state.time;
  if (summary.error.empty()) write_state("LAST");
  postpro.close();
  return summary;
}

}  // namespace lmgc::solver
