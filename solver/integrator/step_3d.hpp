#pragma once
// One Moreau–Jean θ-scheme step of a rigid 3D scene, as the stages of LMGC90's step
// (docs/lmgc90-facts/numerics.md §1.2, §2-§5): each stage a plain function over the scene's flat arrays.
#include <span>
#include <string_view>
#include <vector>

#include "solver/detection/detection_3d.hpp"
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"
#include "solver/nlgs/nlgs_3d.hpp"

namespace lmgc::solver {

// The clock moves on by h; X, V to their begin values, impulses to 0, driven velocities at t_begin.
void increment_step(Scene3D& scene, StepContext& step);
// Gravity, the explicit gyroscopic torque at t_begin, driven forces.
void compute_external_forces(Scene3D& scene, const StepContext& step);
void compute_free_velocity(Scene3D& scene, const StepContext& step);
void recup_rloc(RunState3D& state);
// The verlet list the next recup_rloc reads: `interactions` in their order, with the internals of
// `law_states` (index for index, or empty: internals 0).
void store_interactions(RunState3D& state, std::span<const Interaction3D> interactions,
                        std::span<const LawState3D> law_states);
// X = X_begin + h((1-θ) V_begin + θ V); frame per the scene's rotation scheme.
void compute_dof(Scene3D& scene, const StepContext& step);
void update_step(Scene3D& scene, RunState3D& state);

// init4fd_source_point_RBDY3: body `first` (0-based) starts at `point` (its reference moved to 0),
// every later body whose first contactor is a SPHER or POLYR (colour other than BASEx) waits at 0,
// at rest and invisible.
// `absolute` (init4fd_source_point_RBDY3, RBDY3_SetSourcePointWithIni): the point is a position and
// the references of body `first` and of the waiting bodies are zeroed; otherwise
// (init_source_point_RBDY3, RBDY3_SetSourcePoint) a translation from each body's own reference.
void init_source_point(Scene3D& scene, std::size_t first, double radius, const Eigen::Vector3d& point,
                       bool absolute = true);
// check_source_point_RBDY3, after compute_dof: the next waiting body enters at the point when the
// last one is farther than the radius from it.
void check_source_point(Scene3D& scene);

// A stage of the step under the name of the chipy call of LMGC90's command.py that runs it.
struct StepStage3D {
  std::string_view name;
  void (*run)(Scene3D& scene, RunState3D& state, const NlgsOptions& options, NlgsResult& result);
};
// The step: the stages in LMGC90's order (its macro time loop). UpdateStep stores the verlet list
// too (StockRloc's work in 2D).
std::span<const StepStage3D> step_stages_3d();

// Runs the step's stages in order; returns the solver statistics of the step.
NlgsResult step_3d(Scene3D& scene, RunState3D& state, const NlgsOptions& options);

}  // namespace lmgc::solver
