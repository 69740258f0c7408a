#pragma once
// The run loop of a rigid 3D case: steps, OUTBOX state files (DOF, Vloc_Rloc .OUT.n and .LAST), the
// run report, progress on a terminal, clean stop on Ctrl-C. docs/lmgc90-facts/state-and-outputs.md §1, §2.2.
#include <filesystem>
#include <vector>

#include "grammar/ptpt3_network/ast.hpp"
#include "grammar/vloc_rloc/ast.hpp"
#include "run/run_options.hpp"
#include "solver/driver/run_loop.hpp"
#include "solver/integrator/step_3d.hpp"
#include "solver/io/postpro_3d.hpp"

namespace lmgc::solver {

struct RunOutputs3D {
  // The step and time of DOF.INI's header: a run continues from them (Read_in_dof_Ol sets Nstep and
  // TPS; drivers, write periods and headers use those absolute values).
  long initial_step = 0;
  double initial_time = 0.0;
  // DATBOX/EXACT_STATE.INI, when present: the full-precision state that replaces DOF.INI's and
  // Vloc_Rloc.INI's 7 digits (solver/io/exact_state.hpp).
  const std::string* exact_state = nullptr;
  std::filesystem::path case_dir;                            // OUTBOX/ and POSTPRO/ are created here
  std::vector<PostproCommand2D> postpro;                     // from POSTPRO.DAT (those Postpro3D provides)
  const grammar::VlocRlocFile* warm_start = nullptr;         // Vloc_Rloc.INI
  const grammar::Ptpt3NetworkFile* ptpt3_network = nullptr;  // PTPT3_NETWORK.DAT, when present
};

// Before the first step: periods, PTPT3 links, the source point, the state at DOF.INI's step and
// time, the warm start of Vloc_Rloc.INI, EXACT_STATE.INI. False, with the summary's failure set,
// when the case cannot start.
bool start_run_3d(Scene3D& scene, const run::RunOptions& options, const RunOutputs3D& outputs,
                  RunState3D& state, RunSummary& summary);

// The first body whose state is not finite, as "body N: velocity V" (empty when every one is).
std::string non_finite_3d(const Scene3D& scene, const RunState3D& state);

RunSummary run_3d(Scene3D& scene, const run::RunOptions& options, const RunOutputs3D& outputs);

}  // namespace lmgc::solver
