// command.py read without running it: literals, names bound to literals, chipy calls with their
// arguments and conditions, and the time loop.
#include <gtest/gtest.h>

#include "grammar/command_py/chipy_catalogue.hpp"
#include "grammar/command_py/script.hpp"

namespace lmgc::grammar {
namespace {

constexpr const char* kScript = R"(import sys
from pylmgc90 import chipy

chipy.Initialize()
dt = 1e-4
nb_steps = 1200
theta = 0.5
Rloc_tol = 1.e-2
norm = 'Quad '
gs_it1 = 100
half = nb_steps // 2 + 1   # arithmetic on literals
solver_type='Stored_Delassus_Loops         '

if "--norand" not in sys.argv:
  chipy.nlgs_SetWithQuickScramble()

chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ExSolver(solver_type, norm,
               1e-4, 1.0, gs_it1, 10)  # a call over two lines
chipy.SetPeriodicCondition(xperiod=2.5)
#chipy.PRPRx_SetCundallNeighbor(1e-1)
for k in range(0, nb_steps):
  chipy.IncrementStep()
  chipy.RecupRloc(Rloc_tol)
  x = chipy.RBDY2_GetBodyVector('Coor_', 1)
)";

TEST(CommandScript, ResolvesLiteralsAndNamesBoundToThem) {
  const CommandScript s = read_command_script("command.py", kScript);
  EXPECT_DOUBLE_EQ(*s.assignments.at("dt").number, 1e-4);
  EXPECT_DOUBLE_EQ(*s.assignments.at("Rloc_tol").number, 1e-2);
  EXPECT_EQ(*s.assignments.at("norm").text, "Quad ");
  EXPECT_DOUBLE_EQ(*s.assignments.at("half").number, 601.0);
  EXPECT_FALSE(s.assignments.count("x"));  // bound in the loop, to a call's result
}

TEST(CommandScript, ReadsCallsWithTheirArgumentsLinesAndConditions) {
  const CommandScript s = read_command_script("command.py", kScript);
  const auto scramble = s.calls_to("nlgs_SetWithQuickScramble");
  ASSERT_EQ(scramble.size(), 1u);
  EXPECT_TRUE(scramble[0]->conditional);
  EXPECT_EQ(scramble[0]->line, 15u);
  EXPECT_EQ(scramble[0]->column, 9u);
  const auto solver = s.calls_to("ExSolver");
  ASSERT_EQ(solver.size(), 1u);
  EXPECT_EQ(solver[0]->line, 19u);
  ASSERT_EQ(solver[0]->arguments.size(), 6u);
  EXPECT_EQ(*solver[0]->arguments[0].value.text, "Stored_Delassus_Loops         ");
  EXPECT_DOUBLE_EQ(*solver[0]->arguments[2].value.number, 1e-4);
  EXPECT_DOUBLE_EQ(*solver[0]->arguments[4].value.number, 100.0);
  const ScriptArgument* period = script_argument(*s.calls_to("SetPeriodicCondition")[0], 0, "xperiod");
  ASSERT_NE(period, nullptr);
  EXPECT_DOUBLE_EQ(*period->value.number, 2.5);
  EXPECT_TRUE(s.calls_to("PRPRx_SetCundallNeighbor").empty());  // commented out
  EXPECT_TRUE(s.calls_to("RecupRloc")[0]->in_loop);
}

TEST(CommandScript, FindsTheTimeLoopAndItsCount) {
  const CommandScript s = read_command_script("command.py", kScript);
  const ScriptLoop* loop = s.step_loop();
  ASSERT_NE(loop, nullptr);
  EXPECT_EQ(loop->line, 23u);
  ASSERT_TRUE(loop->count.has_value());
  EXPECT_EQ(*loop->count, 1200);
  const CommandScript shifted =
      read_command_script("command.py", "n = 5\nfor k in range(1, n + 1, 1):\n  IncrementStep()\n");
  EXPECT_EQ(shifted.calls.size(), 0u);  // no chipy prefix and no star import: not a chipy call
  const CommandScript starred = read_command_script(
      "command.py", "from pylmgc90.chipy import *\nn = 5\nfor k in range(1, n + 1, 1):\n  IncrementStep()\n");
  ASSERT_NE(starred.step_loop(), nullptr);
  EXPECT_EQ(*starred.step_loop()->count, 5);
}

TEST(CommandScript, UnresolvedValuesStayUnresolved) {
  const CommandScript s = read_command_script(
      "command.py",
      "import math\nfrom pylmgc90 import chipy\ndt = math.sqrt(2.)\nchipy.TimeEvolution_SetTimeStep(dt)\n");
  EXPECT_FALSE(s.assignments.count("dt"));
  ASSERT_EQ(s.calls.size(), 1u);
  EXPECT_FALSE(s.calls[0].arguments[0].value.resolved());
}

TEST(ChipyCatalogue, KnowsTheExamplesCallsAndFamilies) {
  EXPECT_EQ(find_chipy_function("ExSolver")->support, CommandSupport::run);
  EXPECT_EQ(find_chipy_function("RBDY3_GetBodyVector")->support, CommandSupport::run);
  EXPECT_EQ(find_chipy_function("RBDY2_PutBodyVector")->support, CommandSupport::script_only);
  EXPECT_EQ(find_chipy_function("RBDY2_PutBodyValue")->support, CommandSupport::not_run);
  EXPECT_EQ(find_chipy_function("PRPRx_UseNcDetection")->support, CommandSupport::not_run);
  EXPECT_EQ(find_chipy_function("mecaMAILx_ComputeRayleighDamping")->support, CommandSupport::deformable);
  EXPECT_EQ(find_chipy_function("mp_solver_ReadMpBehaviour")->support, CommandSupport::multiphysics);
  EXPECT_EQ(find_chipy_function("NoSuchCall"), nullptr);
}

}  // namespace
}  // namespace lmgc::grammar
