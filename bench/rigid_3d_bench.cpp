// Rigid 3D step: time per step against the number of contacts (scaling), with the achieved
// residual of every timing. Spheres on a cubic lattice in a box of five planes
// (bench/scenes/sphere_box_3d.hpp), brought to rest (or, for comparison, stepped 50 times), then
// timed at a fixed number of sweeps per step (the 3D twin of rigid_2d_bench).
#include <benchmark/benchmark.h>

#include "bench/scenes/sphere_box_3d.hpp"
#include "bench/settled_steps.hpp"

namespace {

using namespace lmgc;

void step_sphere_box(benchmark::State& state, bench::SphereBoxState box_state) {
  solver::NlgsOptions options;
  options.tolerance = 1e-12;  // fixed work per step: always gs_it1 × gs_it2 sweeps
  options.gs_it1 = 25;
  options.gs_it2 = 2;
  bench::SettledSphereBox3D settled =
      bench::settled_sphere_box_3d(static_cast<int>(state.range(0)), options, box_state);
  bench::time_settled_steps(state, settled.scene, settled.run, 5, 55.0,
                            [&](solver::Scene3D& timed, solver::RunState3D& timed_run) {
                              return solver::step_3d(timed, timed_run, options);
                            });
  state.counters["settling_steps"] = settled.settling_steps;
}

// The box at rest: every sphere carried, a third of the contacts loaded at every size.
void BM_StepSphereBox(benchmark::State& state) {
  step_sphere_box(state, bench::SphereBoxState::at_rest);
}
// The box after 50 steps, still coming down (the state of every figure up to stop 30).
void BM_StepSphereBoxCompacting(benchmark::State& state) {
  step_sphere_box(state, bench::SphereBoxState::compacting);
}
BENCHMARK(BM_StepSphereBox)->Apply(bench::scaling_sizes);
BENCHMARK(BM_StepSphereBoxCompacting)->Apply(bench::scaling_sizes);

}  // namespace

BENCHMARK_MAIN();
