#pragma once
// A box of n disks (radii 0.8-1.2 mm) on a square lattice between JONCx walls, for scaling and
// speed benchmarks of the rigid 2D solver.
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::bench {

solver::Scene2D disk_box_2d(int disks);

}  // namespace lmgc::bench
