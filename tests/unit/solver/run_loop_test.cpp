// The run loop's stops: a state that is no longer finite ends the run before any output of that
// step and without .LAST (no NaN is ever written); a stop signal ends it after the step in
// progress, with .LAST written.
#include "solver/driver/run_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <limits>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;

struct ToyScene {
  double x = 0.0, v = 1.0;
  long nan_at = -1;  // the step whose end state is NaN
};
struct ToyState {
  long step = 0;
  double time = 0.0;
  std::vector<int> contacts;
};
struct NoPostpro {
  bool write(const ToyScene&, const ToyState&, const NlgsResult&, std::string&) { return true; }
  bool close(std::string&) { return true; }
};
struct NoDisplay {
  bool write(const ToyScene&, const ToyState&, std::string&) { return true; }
};

const RunDimension<ToyScene, ToyState> kToy{
    [](ToyScene& s, ToyState& st, const NlgsOptions&) {
      ++st.step;
      st.time += 0.1;
      s.x += 0.1 * s.v;
      if (st.step == s.nan_at) s.x = std::numeric_limits<double>::quiet_NaN();
      return NlgsResult{};
    },
    [](const ToyScene& s) { return 0.5 * s.v * s.v; },
    [](const ToyScene& s, const ToyState&) {
      return std::isfinite(s.x) ? std::string() : "body 1: displacement X";
    },
    [](const ToyScene& s, const ToyState& st) {
      return "step " + std::to_string(st.step) + " x " + std::to_string(s.x) + "\n";
    },
    [](const ToyScene&, const ToyState&) { return std::string("no interaction\n"); },
    [](const ToyScene& s, const ToyState&) { return std::to_string(s.x); },
};

RunSummary run_toy(ToyScene& scene, long steps, const fs::path& dir) {
  fs::create_directories(dir / "OUTBOX");
  run::RunOptions options;
  options.steps = steps;
  options.write_every = 1;
  options.quiet = true;
  ToyState state;
  NoPostpro postpro;
  NoDisplay display;
  return run_loop(scene, state, options, dir, postpro, false, display, kToy);
}

TEST(RunLoop, ANonFiniteStateStopsTheRunBeforeItsOutputsAndWithoutLast) {
  const fs::path dir = test::scratch_dir("run_loop_nan");
  ToyScene scene;
  scene.nan_at = 3;
  const RunSummary summary = run_toy(scene, 10, dir);
  EXPECT_EQ(summary.failure, RunFailure::non_finite);
  EXPECT_NE(summary.error.find("after step 3"), std::string::npos) << summary.error;
  EXPECT_NE(summary.error.find("body 1: displacement X"), std::string::npos) << summary.error;
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "DOF.OUT.2"));
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.OUT.3"));
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
  EXPECT_EQ(test::read_file(dir / "OUTBOX" / "run_report.csv").find("nan"), std::string::npos);
}

TEST(RunLoop, AStopSignalEndsTheRunAfterTheStepWithLastWritten) {
  install_interrupt_handler();
  for (int signal : {SIGTERM, SIGHUP, SIGINT}) {
    const fs::path dir = test::scratch_dir("run_loop_signal_" + std::to_string(signal));
    g_stop_signal.store(0);
    std::raise(signal);  // the handler only records it
    ASSERT_EQ(g_stop_signal.load(), signal);
    ToyScene scene;
    const RunSummary summary = run_toy(scene, 10, dir);
    g_stop_signal.store(0);
    EXPECT_EQ(summary.stop_signal, signal);
    EXPECT_EQ(summary.failure, RunFailure::none);
    EXPECT_EQ(summary.steps_done, 1);
    EXPECT_EQ(test::read_file(dir / "OUTBOX" / "DOF.LAST"), "step 1 x 0.100000\n");
  }
}

}  // namespace
}  // namespace lmgc::solver
