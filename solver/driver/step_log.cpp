#include "solver/driver/step_log.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace lmgc::solver {

StepLog::StepLog(const std::filesystem::path& outbox, const RunOptions& options)
    : report_(outbox / "run_report.csv", std::ios::trunc),
      total_steps_(options.steps),
      progress_(!options.quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {
  report_ << "step,time,contacts,active,iterations,converged,mean_dvor,quad_dv,quad_dvr,"
             "residual_natural_map_over_q,kinetic_energy,step_seconds,nlgs_seconds\n";
}

StepLog::~StepLog() {
  if (progress_ && recorded_ > 0) std::fprintf(stderr, "\n");
}

void StepLog::record(long step, double time, std::size_t contacts, const NlgsResult& result,
                     double kinetic_energy, double step_seconds, RunSummary& summary) {
  ++summary.steps_done;
  if (!result.converged) ++summary.steps_not_converged;
  summary.worst_residual = std::max(summary.worst_residual, result.residual_relative);
  report_ << fmt::format("{},{:.10g},{},{},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.10e},{:.6e},{:.6e}\n", step,
                         time, contacts, result.active, result.iterations, result.converged ? 1 : 0,
                         result.norms.mean_dvor, result.norms.quad_dv, result.norms.quad_dvr,
                         result.residual_relative, kinetic_energy, step_seconds, result.seconds);
  report_.flush();
  ++recorded_;
  if (!progress_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = elapsed / static_cast<double>(recorded_) * static_cast<double>(total_steps_ - recorded_);
  std::fprintf(stderr, "\\rstep %ld/%ld  t=%.6g  contacts=%zu  iterations=%d  residual=%.2e  ETA %.0fs   ",
               step, total_steps_, time, contacts, result.iterations, result.residual_relative, eta);
}

}  // namespace lmgc::solver
