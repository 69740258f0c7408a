#pragma once
// A box of n disks (radii 0.995-1 mm) on a square lattice between JONCx walls, for scaling and
// speed benchmarks of the rigid 2D solver. Square (rows = 0), or `rows` rows high and as wide as n
// needs: a layer whose depth, hence whose load paths and Gauss–Seidel convergence, do not change
// with n.
#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::bench {

solver::Scene2D disk_box_2d(int disks, int rows = 0);

// The scaling benches' NLGS options: a tolerance out of reach, so that every step does the same
// work, gs_it1 × gs_it2 = 50 sweeps.
solver::NlgsOptions fixed_work_options();

// The state the scaling benches time steps from. The lattice starts 1 mm above the floor with its
// rows a few micrometres apart: it falls, lands (steps 70-80 at h = 2e-4) and comes to rest.
enum class DiskBoxState {
  // After 100 steps, the landing's aftermath (the benches' state up to stop 29). It is not the same
  // physics at every size: the 1k box and the layers of every width (32 rows) have most disks in
  // flight again, a tenth of their contacts loaded, while the 16k and 64k boxes, whose landing the
  // fixed sweeps resolve less well, have half and a quarter of theirs loaded (0.49, 0.26).
  landing,
  // At rest: every disk carried (loaded contacts at least 98% of the disks: one below each) for 10
  // steps in a row, half of the contacts loaded at every size. 1k disks come to rest after about 200
  // steps, the 64k layer after about 200 and the 64k box after about 140.
  at_rest,
};

// disk_box_2d's box with its run state (h = 2e-4), stepped with `options` into `state`. Throws
// std::runtime_error when the box is not at rest after 1000 steps.
struct SettledDiskBox2D {
  solver::Scene2D scene;
  solver::RunState2D run;
  int settling_steps = 0;
};
SettledDiskBox2D settled_disk_box_2d(int disks, int rows, const solver::NlgsOptions& options,
                                     DiskBoxState state = DiskBoxState::at_rest);

}  // namespace lmgc::bench
