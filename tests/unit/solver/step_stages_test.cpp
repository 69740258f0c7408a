// The step is a table of LMGC90's stages: each row named by the chipy call of command.py that runs
// it, in the order of LMGC90's time loop; a driver that calls them one by one by name (as a script
// does) gets the step of step_2d / step_3d bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "grammar/command_py/chipy_catalogue.hpp"
#include "solver/integrator/step_2d.hpp"
#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::solver {
namespace {

template <class Stages>
std::vector<std::string> names_of(const Stages& stages) {
  std::vector<std::string> names;
  for (const auto& stage : stages) names.emplace_back(stage.name);
  return names;
}

TEST(StepStages, AreLmgc90TimeLoopInOrder) {
  const std::vector<std::string> loop_2d{"IncrementStep",     "ComputeFext", "ComputeFreeVelocity",
                                         "SelectProxTactors", "RecupRloc",   "ExSolver",
                                         "StockRloc",         "ComputeDof",  "UpdateStep"};
  EXPECT_EQ(names_of(step_stages_2d()), loop_2d);
  // 3D: UpdateStep stores the verlet list.
  const std::vector<std::string> loop_3d{"IncrementStep",     "ComputeFext", "ComputeFreeVelocity",
                                         "SelectProxTactors", "RecupRloc",   "ExSolver",
                                         "ComputeDof",        "UpdateStep"};
  EXPECT_EQ(names_of(step_stages_3d()), loop_3d);
}

TEST(StepStages, EveryStageIsAChipyCallLmgcRuns) {
  std::vector<std::string_view> names;
  for (const auto& s : step_stages_2d()) names.push_back(s.name);
  for (const auto& s : step_stages_3d()) names.push_back(s.name);
  for (std::string_view name : names) {
    const grammar::ChipyFunction* f = grammar::find_chipy_function(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_EQ(f->match, grammar::ChipyMatch::exact) << name;
    EXPECT_EQ(f->support, grammar::CommandSupport::run) << name;
  }
}

NlgsOptions options() {
  NlgsOptions o;
  o.norm = NlgsNorm::quad;
  o.tolerance = 1e-10;
  o.gs_it1 = 20;
  o.gs_it2 = 50;
  return o;
}

Scene2D pile_2d() {
  SceneBuilder2D b;
  b.add_disk(0.0, 0.1, 0.1, 1000.0);
  b.add_disk(0.05, 0.29, 0.1, 1000.0);
  b.add_disk(-0.04, 0.48, 0.1, 1000.0);
  b.add_fixed_joncx(0.0, -0.05, 0.0, 1.0, 0.05);
  b.add_law("iqsc0", IqsClb{0.5});
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 0.01);
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 0.01);
  return b.build();
}

TEST(StepStages, CalledOneByOneGiveTheStep2D) {
  Scene2D by_step = pile_2d(), by_stage = pile_2d();
  RunState2D s1, s2;
  s1.visibility = build_visibility_index(by_step);
  s2.visibility = build_visibility_index(by_stage);
  for (int k = 0; k < 30; ++k) {
    step_2d(by_step, s1, options());
    NlgsResult result;
    for (const StepStage2D& stage : step_stages_2d()) stage.run(by_stage, s2, options(), result);
  }
  EXPECT_EQ(s1.step, 30);
  EXPECT_EQ(s1.time, s2.time);
  for (std::size_t i = 0; i < by_step.bodies.size(); ++i) {
    EXPECT_EQ(by_step.bodies.displacement[i], by_stage.bodies.displacement[i]);
    EXPECT_EQ(by_step.bodies.velocity[i], by_stage.bodies.velocity[i]);
  }
  ASSERT_GE(s1.contacts.size(), 3u);  // the pile stands on the wall
  ASSERT_EQ(s1.contacts.size(), s2.contacts.size());
  for (std::size_t k = 0; k < s1.contacts.size(); ++k) EXPECT_EQ(s1.contacts[k].r, s2.contacts[k].r);
}

TEST(StepStages, TheClockIsTheStepContext) {
  Scene2D scene = pile_2d();
  RunState2D state;
  state.h = 2e-3;
  state.visibility = build_visibility_index(scene);
  StepContext& clock = state;
  step_2d(scene, state, options());
  step_2d(scene, state, options());
  EXPECT_EQ(clock.step, 2);
  EXPECT_DOUBLE_EQ(clock.time, 4e-3);
  EXPECT_DOUBLE_EQ(clock.begin_time(), 2e-3);
}

}  // namespace
}  // namespace lmgc::solver
