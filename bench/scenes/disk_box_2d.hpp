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

// disk_box_2d's box with its run state (h = 2e-4), after 100 steps that let the packing load: the
// state the scaling benches time steps from.
struct SettledDiskBox2D {
  solver::Scene2D scene;
  solver::RunState2D run;
};
SettledDiskBox2D settled_disk_box_2d(int disks, int rows, const solver::NlgsOptions& options);

}  // namespace lmgc::bench
