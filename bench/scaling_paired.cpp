// The 2D scaling ratio measured as a ratio in one run: (large s/step ÷ small s/step) ÷ (large contacts
// ÷ small contacts), with the two sizes' timings interleaved in blocks, so that both sizes see the
// same spells of a shared machine's load. Run by run, rigid_2d_bench's 1k and 64k timings are taken
// a minute apart, and on a machine shared with other tenants single runs' ratios spread from 0.8 to
// 1.8; here every block gives a paired ratio and the median over blocks is the figure.
//
//   scaling_paired [--scene layer|box] [--state rest|landing] [--small N] [--large N] [--blocks K]
//
// Each size is built and settled as rigid_2d_bench does (fixed 50 sweeps per step; at rest, or 100
// steps for the landing: bench/scenes/disk_box_2d.hpp), then
// each block times, for both sizes, 10 steps from the settled state repeated max(1, 16000/n) times,
// as rigid_2d_bench times one run. The order within a block alternates (small first, then large
// first), so a drift in the machine's speed does not favour one size; the small size also runs one
// untimed round first, so that it does not start with the caches the large one left.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench/scenes/disk_box_2d.hpp"
#include "solver/integrator/step_2d.hpp"

namespace {

using namespace lmgc;
using Clock = std::chrono::steady_clock;

constexpr int kStepsPerRound = 10;

struct SettledScene {
  int disks = 0;
  solver::Scene2D settled;
  solver::RunState2D settled_run;
  solver::Scene2D scene;
  solver::RunState2D run;
};

SettledScene settle(int disks, int rows, const solver::NlgsOptions& options, bench::DiskBoxState state) {
  SettledScene s;
  s.disks = disks;
  bench::SettledDiskBox2D settled = bench::settled_disk_box_2d(disks, rows, options, state);
  std::printf("n = %d: %d settling steps\n", disks, settled.settling_steps);
  s.settled = settled.scene;
  s.settled_run = settled.run;
  s.scene = std::move(settled.scene);
  s.run = std::move(settled.run);
  return s;
}

struct Timing {
  double seconds_per_step = 0;
  double contacts_per_step = 0;
};

// One timed measurement, as one rigid_2d_bench run: rounds of 10 steps from the settled state, the
// copies back to it not timed.
Timing time_rounds(SettledScene& s, const solver::NlgsOptions& options, bool timed) {
  const int rounds = timed ? std::max(1, 16000 / s.disks) : 1;
  double seconds = 0, contacts = 0;
  long steps = 0;
  for (int round = 0; round < rounds; ++round) {
    s.scene = s.settled;
    s.run = s.settled_run;
    const auto start = Clock::now();
    for (int i = 0; i < kStepsPerRound; ++i) {
      solver::step_2d(s.scene, s.run, options);
      contacts += static_cast<double>(s.run.contacts.size());
      ++steps;
    }
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
  }
  return {seconds / static_cast<double>(steps), contacts / static_cast<double>(steps)};
}

double quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(position);
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--scene layer|box] [--state rest|landing] [--small N] [--large N] [--blocks K]\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_name = "layer", state_name = "rest";
  int small = 1000, large = 64000, blocks = 12;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--scene") == 0 && has_value)
      scene_name = argv[++i];
    else if (std::strcmp(argv[i], "--state") == 0 && has_value)
      state_name = argv[++i];
    else if (std::strcmp(argv[i], "--small") == 0 && has_value)
      small = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--large") == 0 && has_value)
      large = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--blocks") == 0 && has_value)
      blocks = std::atoi(argv[++i]);
    else
      return usage(argv[0]);
  }
  if ((scene_name != "layer" && scene_name != "box") || (state_name != "rest" && state_name != "landing") ||
      small < 1 || large <= small || blocks < 1)
    return usage(argv[0]);
  const int rows = scene_name == "layer" ? 32 : 0;  // as BM_StepDiskLayer and BM_StepDiskBox

  const solver::NlgsOptions options = bench::fixed_work_options();
  const bench::DiskBoxState state =
      state_name == "rest" ? bench::DiskBoxState::at_rest : bench::DiskBoxState::landing;
  SettledScene sizes[2] = {settle(small, rows, options, state), settle(large, rows, options, state)};

  std::vector<double> ratios, small_times, large_times;
  double contacts[2] = {0, 0};
  std::printf("block  %s s/step  %s s/step  ratio\n", std::to_string(small).c_str(),
              std::to_string(large).c_str());
  for (int block = 0; block < blocks; ++block) {
    Timing timing[2];
    for (int k = 0; k < 2; ++k) {
      const int which = block % 2 == 0 ? k : 1 - k;  // small first, then large first
      if (which == 0) time_rounds(sizes[0], options, false);
      timing[which] = time_rounds(sizes[which], options, true);
    }
    for (int which = 0; which < 2; ++which) {
      // The steps are deterministic: every block sees the same contacts.
      if (block > 0 && timing[which].contacts_per_step != contacts[which]) {
        std::fprintf(stderr, "contacts changed between blocks at n = %d\n", sizes[which].disks);
        return 1;
      }
      contacts[which] = timing[which].contacts_per_step;
    }
    const double ratio =
        (timing[1].seconds_per_step / timing[0].seconds_per_step) / (contacts[1] / contacts[0]);
    ratios.push_back(ratio);
    small_times.push_back(timing[0].seconds_per_step);
    large_times.push_back(timing[1].seconds_per_step);
    std::printf("%5d  %.4e  %.4e  %.3f\n", block + 1, timing[0].seconds_per_step, timing[1].seconds_per_step,
                ratio);
    std::fflush(stdout);
  }
  const double contact_growth = contacts[1] / contacts[0];
  const double fastest = (*std::min_element(large_times.begin(), large_times.end()) /
                          *std::min_element(small_times.begin(), small_times.end())) /
                         contact_growth;
  std::printf(
      "%s (%s) %d -> %d: contacts %.0f -> %.0f; paired ratio median %.3f (quartiles %.3f %.3f, "
      "%d blocks); fastest at each size %.3f (%.0f ns -> %.0f ns per contact and step)\n",
      scene_name.c_str(), state_name.c_str(), small, large, contacts[0], contacts[1], quantile(ratios, 0.5),
      quantile(ratios, 0.25), quantile(ratios, 0.75), blocks, fastest,
      1e9 * *std::min_element(small_times.begin(), small_times.end()) / contacts[0],
      1e9 * *std::min_element(large_times.begin(), large_times.end()) / contacts[1]);
  return 0;
}
