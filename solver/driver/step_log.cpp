#include "solver/driver/step_log.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>

namespace lmgc::solver {

namespace {

// On small cases a step takes a few microseconds, and a line of numbers formatted through printf
// (fmt 9 formats a given precision that way) about as long: std::to_chars writes the same digits as
// printf's %.Ne / %.Ng, several times faster. (POSTPRO lines are written the same way,
// grammar/common/fortran_format.cpp.)
constexpr double kFlushSeconds = 0.25;
constexpr double kProgressSeconds = 0.1;

void append(std::string& line, double value, std::chars_format format, int precision) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, format, precision);
  line.append(buffer, error == std::errc() ? end : buffer);
  line.push_back(',');
}

template <typename Integer>
void append(std::string& line, Integer value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  line.append(buffer, error == std::errc() ? end : buffer);
  line.push_back(',');
}

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

StepLog::StepLog(const std::filesystem::path& outbox, const run::RunOptions& options)
    : path_(outbox / "run_report.csv"),
      report_(path_, std::ios::trunc),
      total_steps_(options.steps),
      progress_(!options.quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_flush_(start_),
      last_progress_(start_) {
  report_ << "step,time,contacts,active,iterations,converged,mean_dvor,quad_dv,quad_dvr,"
             "residual_natural_map_over_q,kinetic_energy,step_seconds,nlgs_seconds,sweep_seconds,"
             "sweeps_skipped\n";
}

std::string StepLog::error() const {
  return "cannot write '" + path_.string() + "' (disk full?)";
}

bool StepLog::close() {
  if (!report_.is_open()) return true;
  report_.flush();
  const bool ok = static_cast<bool>(report_);
  report_.close();
  return ok;
}

StepLog::~StepLog() {
  if (progress_ && recorded_ > 0) std::fprintf(stderr, "\n");
}

void StepLog::record(long step, double time, std::size_t contacts, const NlgsResult& result,
                     double kinetic_energy, double step_seconds, RunSummary& summary) {
  ++summary.steps_done;
  if (!result.converged) ++summary.steps_not_converged;
  summary.worst_residual = std::max(summary.worst_residual, result.residual_relative);
  // step,time,contacts,active,iterations,converged,mean_dvor,quad_dv,quad_dvr,residual,energy,
  // step, NLGS and sweep seconds, sweeps skipped
  std::string line;
  line.reserve(192);
  append(line, step);
  append(line, time, std::chars_format::general, 10);
  append(line, contacts);
  append(line, result.active);
  append(line, result.iterations);
  append(line, result.converged ? 1 : 0);
  append(line, result.norms.mean_dvor, std::chars_format::scientific, 6);
  append(line, result.norms.quad_dv, std::chars_format::scientific, 6);
  append(line, result.norms.quad_dvr, std::chars_format::scientific, 6);
  append(line, result.residual_relative, std::chars_format::scientific, 6);
  append(line, kinetic_energy, std::chars_format::scientific, 10);
  append(line, step_seconds, std::chars_format::scientific, 6);
  append(line, result.seconds, std::chars_format::scientific, 6);
  append(line, result.sweep_seconds, std::chars_format::scientific, 6);
  append(line, result.sweeps_skipped);
  line.back() = '\n';
  report_ << line;
  ++recorded_;
  const auto now = std::chrono::steady_clock::now();
  if (seconds_between(last_flush_, now) >= kFlushSeconds || recorded_ == total_steps_) {
    report_.flush();
    last_flush_ = now;
  }
  if (!progress_) return;
  if (seconds_between(last_progress_, now) < kProgressSeconds && recorded_ != total_steps_) return;
  last_progress_ = now;
  const double elapsed = seconds_between(start_, now);
  const double eta = elapsed / static_cast<double>(recorded_) * static_cast<double>(total_steps_ - recorded_);
  std::fprintf(stderr, "\\rstep %ld/%ld  t=%.6g  contacts=%zu  iterations=%d  residual=%.2e  ETA %.0fs   ",
               step, total_steps_, time, contacts, result.iterations, result.residual_relative, eta);
}

}  // namespace lmgc::solver
