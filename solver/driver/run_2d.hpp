#pragma once
// The run loop of a rigid 2D case: steps, outputs (OUTBOX state files, DISPLAY, POSTPRO, run
// report), progress on a terminal, clean stop on a signal (solver/driver/run_loop.hpp). spec:
// state-and-outputs.md §1, §2.2.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "grammar/vloc_rloc/ast.hpp"
#include "run/run_options.hpp"
#include "solver/driver/run_loop.hpp"
#include "solver/driver/step_log.hpp"
#include "solver/integrator/step_2d.hpp"
#include "solver/io/postpro_2d.hpp"

namespace lmgc::solver {

struct RunOutputs2D {
  // The step and time of DOF.INI's header: a run continues from them (Read_in_dof_Ol sets Nstep and
  // TPS; drivers, write periods and headers use those absolute values).
  long initial_step = 0;
  double initial_time = 0.0;
  // DATBOX/EXACT_STATE.INI, when present: the full-precision state that replaces DOF.INI's and
  // Vloc_Rloc.INI's 7 digits (solver/io/exact_state.hpp).
  const std::string* exact_state = nullptr;
  std::filesystem::path case_dir;         // OUTBOX/, DISPLAY/, POSTPRO/ are created here
  std::vector<PostproCommand2D> postpro;  // from POSTPRO.DAT
  // Vloc_Rloc.INI: the interactions of the step before the first one (warm start), if any.
  const grammar::VlocRlocFile* warm_start = nullptr;
};

// Before the first step: the run's options on the scene (bounds, period), the state at DOF.INI's
// step and time, the warm start of Vloc_Rloc.INI, EXACT_STATE.INI. False, with the summary's
// failure set, when the case cannot start.
bool start_run_2d(Scene2D& scene, const run::RunOptions& options, const RunOutputs2D& outputs,
                  RunState2D& state, RunSummary& summary);

// The first body whose state is not finite, as "body N: velocity V" (empty when every one is).
std::string non_finite_2d(const Scene2D& scene, const RunState2D& state);

RunSummary run_2d(Scene2D& scene, const run::RunOptions& options, const RunOutputs2D& outputs);

}  // namespace lmgc::solver
