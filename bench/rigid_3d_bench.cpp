// Rigid 3D step: time per step against the number of contacts (scaling), with the achieved
// residual of every timing. Spheres on a cubic lattice in a box of five planes, first settled for
// a while, then timed at a fixed number of sweeps per step (the 3D twin of rigid_2d_bench).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "bench/settled_steps.hpp"
#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace {

using namespace lmgc;
using Eigen::Matrix3d;
using Eigen::Vector3d;

solver::Scene3D sphere_box_3d(int count) {
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(count))));
  const double r = 0.005, spacing = 2.0 * r, width = side * spacing;
  solver::SceneBuilder3D b;
  int placed = 0;
  for (int k = 0; k < side && placed < count; ++k)
    for (int j = 0; j < side && placed < count; ++j)
      for (int i = 0; i < side && placed < count; ++i, ++placed)
        b.add_sphere(Vector3d(r + i * spacing, r + j * spacing, r + k * spacing),
                     r * (1.0 - 0.02 * ((i + j + k) % 3)), 2600.0);
  const double thick = 0.01, half = 0.5 * width + thick;
  b.add_fixed_plane(Vector3d(0.5 * width, 0.5 * width, -thick), Matrix3d::Identity(),
                    Vector3d(half, half, thick), "WALLx");
  // Walls: PLANx frames whose third axis points into the box.
  const auto wall = [&](const Vector3d& centre, const Vector3d& inward) {
    Matrix3d frame;
    const Vector3d up(0.0, 0.0, 1.0);
    frame.col(2) = inward;
    frame.col(0) = up.cross(inward);
    frame.col(1) = inward.cross(frame.col(0));
    b.add_fixed_plane(centre, frame, Vector3d(half, half, thick), "WALLx");
  };
  const double h = 0.5 * side * spacing;
  wall(Vector3d(-thick, 0.5 * width, h), Vector3d(1, 0, 0));
  wall(Vector3d(width + thick, 0.5 * width, h), Vector3d(-1, 0, 0));
  wall(Vector3d(0.5 * width, -thick, h), Vector3d(0, 1, 0));
  wall(Vector3d(0.5 * width, width + thick, h), Vector3d(0, -1, 0));
  b.add_law("iqsc0", solver::IqsClb{0.4});
  b.see("SPHER", "BLEUx", "iqsc0", "SPHER", "BLEUx", 0.1 * r);
  b.see("SPHER", "BLEUx", "iqsc0", "PLANx", "WALLx", 0.1 * r);
  return b.build();
}

void BM_StepSphereBox(benchmark::State& state) {
  solver::Scene3D scene = sphere_box_3d(static_cast<int>(state.range(0)));
  solver::RunState3D run;
  run.h = 2e-4;
  solver::NlgsOptions options;
  options.tolerance = 1e-12;  // fixed work per step: always gs_it1 × gs_it2 sweeps
  options.gs_it1 = 25;
  options.gs_it2 = 2;
  for (int i = 0; i < 50; ++i) solver::step_3d(scene, run, options);  // let the packing load
  bench::time_settled_steps(state, scene, run, 5, 55.0,
                            [&](solver::Scene3D& timed, solver::RunState3D& timed_run) {
                              return solver::step_3d(timed, timed_run, options);
                            });
}
BENCHMARK(BM_StepSphereBox)->Apply(bench::scaling_sizes);

}  // namespace

BENCHMARK_MAIN();
