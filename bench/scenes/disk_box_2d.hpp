#pragma once
// A box of n disks (radii 0.995-1 mm) on a square lattice between JONCx walls, for scaling and
// speed benchmarks of the rigid 2D solver. Square (rows = 0), or `rows` rows high and as wide as n
// needs: a layer whose depth, hence whose load paths and Gauss–Seidel convergence, do not change
// with n.
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::bench {

solver::Scene2D disk_box_2d(int disks, int rows = 0);

}  // namespace lmgc::bench
