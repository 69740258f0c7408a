#pragma once
// Contact detection of a rigid 3D scene: rough detection on a grid of bounding spheres, fine
// detection per pair family, the interactions in LMGC90's order. docs/lmgc90-facts/numerics.md §5,
// rigid-3d.md §3.
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

// Detection on the θ configuration: centre = reference + X_begin + (1-θ) h v_begin, frame turned
// from the begin frame by (1-θ) ω_begin. Writes state.contacts (and their law states) in LMGC90's
// order: the families as its 3D NLGS sweeps them, in a family the pairs as its rough detection
// enumerates them, a pair's points as its fine detection finds them.
void select_prox_tactors(Scene3D& scene, RunState3D& state);

// Whether a law of the scene's visibility rows keeps a LawState3D per interaction.
bool scene_keeps_law_state_3d(const Scene3D& scene);

}  // namespace lmgc::solver
