#pragma once
// The timing loop of the scaling benches: steps from a settled scene, with the counters they report
// (contacts, achieved residual, seconds per step, contact updates per second).
#include <benchmark/benchmark.h>

#include <algorithm>

namespace lmgc::bench {

// Times `steps_per_round` calls of step(scene, run) from the settled `scene` and `run`. Small scenes
// repeat the round from the settled state 16000/n times (n = state.range(0)): a 1k-body step takes
// milliseconds, and a single round varied by ±20% from run to run on this shared machine.
// `updates_per_contact` is the local solves per contact and step (sweeps, plus check passes if counted).
template <class Scene, class Run, class Step>
void time_settled_steps(benchmark::State& state, Scene& scene, Run& run, int steps_per_round,
                        double updates_per_contact, Step&& step) {
  const Scene settled = scene;
  const Run settled_run = run;
  double contacts = 0, residual = 0, active = 0, sweep_seconds = 0, sweeps_run = 0, local_solves = 0;
  long steps = 0;
  const int rounds = std::max(1, 16000 / static_cast<int>(state.range(0)));
  for (auto _ : state)
    for (int round = 0; round < rounds; ++round) {
      state.PauseTiming();
      scene = settled;
      run = settled_run;
      state.ResumeTiming();
      for (int i = 0; i < steps_per_round; ++i) {
        const auto result = step(scene, run);
        contacts += static_cast<double>(run.contacts.size());
        residual += result.residual_relative;
        active += static_cast<double>(result.active);
        sweep_seconds += result.sweep_seconds;
        sweeps_run += result.iterations - result.sweeps_skipped;
        local_solves += static_cast<double>(result.local_solves);
        ++steps;
      }
    }
  state.counters["contacts"] = contacts / static_cast<double>(steps);
  state.counters["residual"] = residual / static_cast<double>(steps);
  // What a contact update costs depends on the state: an open contact is mostly passed by, and once
  // a step has converged its updates no longer change the reactions.
  state.counters["active_share"] = contacts > 0 ? active / contacts : 0.0;
  state.counters["sweep_s_per_step"] = sweep_seconds / static_cast<double>(steps);
  // The sweeps actually run: the 3D solve leaves out the rest of a block once a sweep changes no
  // reaction (NlgsResult::sweeps_skipped), so a state near convergence runs fewer than gs_it1 × gs_it2
  // and its time per step is not the same work as a state further from it.
  state.counters["sweeps_run_per_step"] = sweeps_run / static_cast<double>(steps);
  // The 3D local solves per contact and step (NlgsResult::local_solves; none counted in 2D): what a
  // step's time follows, with the open contacts passed by and the skipped sweeps left out.
  if (local_solves > 0) state.counters["local_solves_per_contact"] = local_solves / contacts;
  state.counters["s_per_step"] = benchmark::Counter(
      static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["contact_updates_per_s"] =
      benchmark::Counter(contacts * updates_per_contact, benchmark::Counter::kIsRate);
}

// The scaling benches' sizes (1k to 64k bodies), one timed iteration each.
inline void scaling_sizes(benchmark::internal::Benchmark* b) {
  b->Arg(1000)->Arg(4000)->Arg(16000)->Arg(64000)->Unit(benchmark::kMillisecond)->Iterations(1);
}

}  // namespace lmgc::bench
