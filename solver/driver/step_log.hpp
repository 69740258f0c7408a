#pragma once
// What both run loops (2D and 3D) do after every step: the line of OUTBOX/run_report.csv
// (flushed at least every kFlushSeconds, so an interrupted run keeps what it did), the run
// summary's counters, and the progress line on a terminal (redrawn at most kProgressSeconds apart).
#include <chrono>
#include <filesystem>
#include <fstream>

#include "solver/driver/run_options.hpp"
#include "solver/nlgs/nlgs_check.hpp"

namespace lmgc::solver {

struct RunSummary {
  long steps_done = 0;
  long steps_not_converged = 0;
  double worst_residual = 0.0;  // largest natural-map residual ÷ ‖q‖ of the run
  double final_time = 0.0;
  bool interrupted = false;
  std::string error;  // an output could not be written
};

class StepLog {
 public:
  StepLog(const std::filesystem::path& outbox, const RunOptions& options);
  ~StepLog();
  void record(long step, double time, std::size_t contacts, const NlgsResult& result, double kinetic_energy,
              double step_seconds, RunSummary& summary);

 private:
  std::ofstream report_;
  long total_steps_;
  bool progress_;
  long recorded_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_flush_, last_progress_;
};

}  // namespace lmgc::solver
