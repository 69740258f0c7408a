// Rigid 2D step: time per step against the number of contacts (scaling), with the achieved
// residual of every timing. Disks are first settled for a while, then timed.
#include <benchmark/benchmark.h>

#include "bench/scenes/disk_box_2d.hpp"
#include "bench/settled_steps.hpp"
#include "solver/integrator/step_2d.hpp"

namespace {

using namespace lmgc;

// rows = 0: a square box; else a layer of that many rows.
void step_disk_box(benchmark::State& state, int rows, bench::DiskBoxState box_state) {
  const solver::NlgsOptions options = bench::fixed_work_options();
  bench::SettledDiskBox2D settled =
      bench::settled_disk_box_2d(static_cast<int>(state.range(0)), rows, options, box_state);
  solver::Scene2D& scene = settled.scene;
  solver::RunState2D& run = settled.run;
  bench::time_settled_steps(state, scene, run, 10, 50.0,
                            [&](solver::Scene2D& timed, solver::RunState2D& timed_run) {
                              return solver::step_2d(timed, timed_run, options);
                            });
  state.counters["settling_steps"] = settled.settling_steps;
}
// Square boxes at rest: the deeper the pile, the slower Gauss–Seidel carries its weight down, so the
// residual within the fixed sweeps grows with n; the share of loaded contacts does not (one half).
void BM_StepDiskBox(benchmark::State& state) {
  step_disk_box(state, 0, bench::DiskBoxState::at_rest);
}
// Layers 32 disks high (the 1k square box's height) at rest, wider with n: the same physics in every
// column, so the time per contact measures the implementation alone.
void BM_StepDiskLayer(benchmark::State& state) {
  step_disk_box(state, 32, bench::DiskBoxState::at_rest);
}
// The same layers after 100 steps, most disks in flight after the landing (a tenth of the contacts
// loaded): the state BM_StepDiskLayer timed up to stop 29, kept for comparison with those figures.
void BM_StepDiskLayerLanding(benchmark::State& state) {
  step_disk_box(state, 32, bench::DiskBoxState::landing);
}

BENCHMARK(BM_StepDiskBox)->Apply(bench::scaling_sizes);
BENCHMARK(BM_StepDiskLayer)->Apply(bench::scaling_sizes);
BENCHMARK(BM_StepDiskLayerLanding)->Apply(bench::scaling_sizes);

}  // namespace

BENCHMARK_MAIN();
