#pragma once
// A box of n spheres (radius 5 mm less 0, 2 or 4%) on a cubic lattice between five PLANx walls, for
// the 3D scaling bench: the 3D twin of disk_box_2d.hpp.
#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::bench {

solver::Scene3D sphere_box_3d(int spheres);

// The state the 3D scaling bench times steps from. The lattice's pitch is the largest diameter, so
// the smaller spheres start with a gap below them and come down onto the ones below.
enum class SphereBoxState {
  // After 50 steps, still coming down (the bench's state up to stop 30): the share of loaded contacts
  // falls with size, 0.088 at 1k to 0.023 at 64k, as the taller piles take longer to come down.
  compacting,
  // At rest: every sphere carried (loaded contacts at least 98% of the spheres) for 10 steps in a row,
  // a third of the contacts loaded at every size (1k after 116 steps, 4k 151, 16k 201, 64k 261).
  at_rest,
};

// sphere_box_3d's box with its run state (h = 2e-4), stepped with `options` into `state`. Throws
// std::runtime_error when the box is not at rest after 1000 steps.
struct SettledSphereBox3D {
  solver::Scene3D scene;
  solver::RunState3D run;
  int settling_steps = 0;
};
SettledSphereBox3D settled_sphere_box_3d(int spheres, const solver::NlgsOptions& options,
                                         SphereBoxState state = SphereBoxState::at_rest);

}  // namespace lmgc::bench
