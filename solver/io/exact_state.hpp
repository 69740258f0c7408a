#pragma once
// The exact restart state: what a run needs to continue bit for bit, written beside DOF.LAST and
// Vloc_Rloc.LAST as OUTBOX/EXACT_STATE.LAST (LMGC90's files keep 7 digits, so a run restarted from
// them drifts from the run it continues). Copied to DATBOX/EXACT_STATE.INI with the others, it
// replaces their values. A first text line (format, dimension, step, time, bodies) then the
// binary arrays; for the lmgc build that wrote it (the record layouts are checked).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "grammar/common/exact_state_header.hpp"
#include "solver/integrator/step_2d.hpp"
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

std::string write_exact_state(const Scene2D& scene, const RunState2D& state);
std::string write_exact_state(const Scene3D& scene, const RunState3D& state);

// Restores the bodies, the run state and the step and time; false with `error` when the bytes do
// not hold a state of this case (dimension, bodies, record layouts).
bool restore_exact_state(std::string_view bytes, Scene2D& scene, RunState2D& state, std::string& error);
bool restore_exact_state(std::string_view bytes, Scene3D& scene, RunState3D& state, std::string& error);

}  // namespace lmgc::solver
