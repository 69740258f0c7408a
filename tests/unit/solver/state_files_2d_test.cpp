// Vloc_Rloc files of a rigid 2D run whose law has internal variables (solver/io/state_files_2d): the
// internals, kept beside the interactions (LawState2D), are written, read back as a warm start
// beside the interactions they belong to, and a run restarted from them takes the step the run
// itself takes next. docs/lmgc90-facts/state-and-outputs.md §1.4.
#include "solver/io/state_files_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "tests/support/nlgs_options.hpp"

namespace lmgc::solver {
namespace {

constexpr double kH = 1e-3;

// Two disks hanging in a chain under a fixed JONCx, both interfaces IQS_MAC_CZM, sound from the first
// step (β = 1); the lower disk is pulled down, so the interfaces open and store their jumps.
struct SceneRun {
  Scene2D scene;
  RunState2D state;
};

SceneRun run(int steps) {
  const double r = 0.1;
  SceneBuilder2D b;
  b.add_disk(0.0, -r, r, 1000.0);
  const int lower = b.add_disk(0.0, -3.0 * r, r, 1000.0);
  b.add_fixed_joncx(0.0, 0.05, 0.0, 1.0, 0.05);
  b.add_law("mac01", IqsMacCzm{0.3, 0.3, 1e7, 1e7, 0.0, 1e3});
  b.see("DISKx", "BLEUx", "mac01", "JONCx", "WALLx", 0.01);
  b.see("DISKx", "BLEUx", "mac01", "DISKx", "BLEUx", 0.01);
  b.set_velocity(lower, Eigen::Vector3d(0.0, -0.05, 0.0));
  SceneRun s{b.build(), {}};
  s.state.h = kH;
  s.state.visibility = build_visibility_index(s.scene);
  for (int i = 0; i < steps; ++i)
    EXPECT_TRUE(step_2d(s.scene, s.state, test::converged_nlgs_options(20, 1e-12)).converged);
  return s;
}

grammar::VlocRlocFile parse_vloc(const std::string& text) {
  grammar::DiagnosticSink sink;
  grammar::VlocRlocFile f = grammar::parse_vloc_rloc(grammar::SourceText("Vloc_Rloc.OUT.1", text), sink);
  EXPECT_FALSE(sink.has_errors());
  return f;
}

void expect_close(double expected, double actual, const char* what) {
  EXPECT_NEAR(actual, expected, 1e-6 * std::max(1.0, std::abs(expected))) << what;
}

TEST(StateFiles2D, WarmStartCarriesTheLawsInternalsAndRestartsTheRun) {
  SceneRun r = run(5);
  ASSERT_EQ(r.state.contacts.size(), 2u);
  ASSERT_EQ(r.state.law_states.size(), 2u);  // IQS_MAC_CZM has internals: kept beside the list
  const WarmStart2D warm =
      warm_start_2d(parse_vloc(grammar::write_vloc_rloc(vloc_rloc_file_2d(r.scene, r.state))), r.scene, kH);
  ASSERT_EQ(warm.interactions.size(), 2u);
  ASSERT_EQ(warm.law_states.size(), 2u);
  bool opened = false;
  for (std::size_t k = 0; k < 2; ++k) {
    const Interaction2D& c = warm.interactions[k];
    // The file lists the interactions in the run's order here (one per family, sorted alike).
    EXPECT_EQ(c.candidate, r.state.contacts[k].candidate);
    EXPECT_EQ(c.antagonist, r.state.contacts[k].antagonist);
    // The five internals IQS_MAC_CZM writes (the sixth, the β in use, is not written).
    for (std::size_t i = 0; i < 5; ++i)
      expect_close(r.state.law_states[k].internal[i], warm.law_states[k].internal[i], "internal");
    opened |= r.state.law_states[k].internal[2] > 0.0;  // δn
  }
  EXPECT_TRUE(opened);

  SceneRun restarted = r;
  store_interactions(restarted.state, warm.interactions, warm.law_states);
  step_2d(r.scene, r.state, test::converged_nlgs_options(20, 1e-12));
  step_2d(restarted.scene, restarted.state, test::converged_nlgs_options(20, 1e-12));
  ASSERT_EQ(restarted.state.contacts.size(), 2u);
  ASSERT_EQ(restarted.state.law_states.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    for (int d = 0; d < 2; ++d) expect_close(r.state.contacts[k].r(d), restarted.state.contacts[k].r(d), "r");
    for (std::size_t i = 0; i < 5; ++i)
      expect_close(r.state.law_states[k].internal[i], restarted.state.law_states[k].internal[i], "internal");
  }
}

}  // namespace
}  // namespace lmgc::solver
