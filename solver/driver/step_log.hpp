#pragma once
// What both run loops (2D and 3D) do after every step: the line of OUTBOX/run_report.csv
// (flushed at least every kFlushSeconds, so an interrupted run keeps what it did), the run
// summary's counters, and the progress line on a terminal (redrawn at most kProgressSeconds apart).
#include <chrono>
#include <filesystem>
#include <fstream>

#include "run/run_options.hpp"
#include "solver/nlgs/nlgs_check.hpp"

namespace lmgc::solver {

// Why a run stopped before its last step, if it did (each has its own exit code in lmgc-solve).
enum class RunFailure {
  none,
  data,           // the case cannot run as given (found when the run starts)
  output,         // an output file could not be written (disk full, ...)
  non_finite,     // a body's state became NaN or infinite
  not_converged,  // a Newton loop failed at the smallest time step allowed
};

struct RunSummary {
  long steps_done = 0;
  long steps_not_converged = 0;
  double worst_residual = 0.0;  // largest natural-map residual ÷ ‖q‖ of the run
  double final_time = 0.0;
  int stop_signal = 0;  // SIGINT, SIGTERM or SIGHUP ended the run after a step
  RunFailure failure = RunFailure::none;
  std::string error;  // what failed, for the message
  // Keeps the first failure: a later one (the .LAST write after a full disk) is its consequence.
  void fail(RunFailure kind, std::string message) {
    if (failure != RunFailure::none) return;
    failure = kind;
    error = std::move(message);
  }
};

class StepLog {
 public:
  StepLog(const std::filesystem::path& outbox, const run::RunOptions& options);
  ~StepLog();
  void record(long step, double time, std::size_t contacts, const NlgsResult& result, double kinetic_energy,
              double step_seconds, RunSummary& summary);
  // Whether every line so far reached the file's buffer (and the flushed ones the disk).
  bool good() const { return static_cast<bool>(report_); }
  std::string error() const;
  // Flushes and closes the report; false when its last lines could not be written.
  bool close();

 private:
  std::filesystem::path path_;
  std::ofstream report_;
  long total_steps_;
  bool progress_;
  long recorded_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_flush_, last_progress_;
};

}  // namespace lmgc::solver
