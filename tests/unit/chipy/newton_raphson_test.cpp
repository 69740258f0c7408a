// LMGC90's Newton-loop control (chipy/newton_raphson.hpp): convergence codes and the adaptive
// time step of mod_overall's check_newton_convergence and Compute_newton_time_step.
#include "chipy/newton_raphson.hpp"

#include <gtest/gtest.h>

namespace lmgc::chipy {
namespace {

NewtonRaphson control(int max_iterations, int patience) {
  NewtonRaphson n;
  n.final_time = 1.0;
  n.min_step = 1e-4;
  n.max_step = 0.1;
  n.max_iterations = max_iterations;
  n.good_iterations = 3;
  n.bad_iterations = 6;
  n.patience = patience;
  return n;
}

TEST(NewtonRaphson, ConvergesBelowTheToleranceAndDivergesAtTheLastIteration) {
  NewtonRaphson n = control(3, 2);
  n.initialize(1e-3);
  EXPECT_EQ(n.check(1.0), NewtonRaphson::iterate);
  EXPECT_EQ(n.check(1e-3), NewtonRaphson::iterate);  // not strictly below
  EXPECT_EQ(n.check(1.0), NewtonRaphson::diverged);
  n.initialize(1e-3);
  EXPECT_EQ(n.check(1e-4), NewtonRaphson::converged);
  EXPECT_EQ(n.iterations, 1);
}

TEST(NewtonRaphson, AStepThatUsedEveryIterationIsRedoneWithASmallerStep) {
  NewtonRaphson n = control(3, 2);
  n.initialize(1e-3);
  for (int k = 0; k < 3; ++k) n.check(1.0);
  const auto next = n.compute(0.5, 0.01, 10);
  EXPECT_EQ(next.state, NewtonRaphson::redo);
  EXPECT_DOUBLE_EQ(next.h, 0.01 / std::sqrt(2.0));
}

TEST(NewtonRaphson, GoodStepsInARowGrowTheStepUpToItsMaximum) {
  NewtonRaphson n = control(20, 2);
  double h = 0.08;
  for (int step = 2; step <= 3; ++step) {
    n.initialize(1e-3);
    n.check(1e-4);
    const auto next = n.compute(0.2, h, step);
    EXPECT_EQ(next.state, NewtonRaphson::go_on);
    if (step == 2) {
      EXPECT_EQ(next.h, h);  // one good step: not yet
    } else {
      EXPECT_DOUBLE_EQ(next.h, 0.1);  // √2 × 0.08 capped at the maximum
    }
  }
  // Bad steps in a row shrink it.
  for (int step = 4; step <= 5; ++step) {
    n.initialize(1e-3);
    for (int k = 0; k < 7; ++k) n.check(k == 6 ? 1e-4 : 1.0);
    const auto next = n.compute(0.3, 0.1, step);
    if (step == 5) {
      EXPECT_DOUBLE_EQ(next.h, 0.1 / std::sqrt(2.0));
    }
  }
}

TEST(NewtonRaphson, TheLastStepEndsOnTheFinalTimeAndTheNextStops) {
  NewtonRaphson n = control(20, 1000);
  n.initialize(1e-3);
  n.check(1e-4);
  auto next = n.compute(0.95, 0.1, 7);  // 0.95 + 0.1 passes 1: cut to 0.05
  EXPECT_EQ(next.state, NewtonRaphson::go_on);
  EXPECT_NEAR(next.h, 0.05, 1e-15);
  next = n.compute(1.0, 0.05, 8);  // at the final time: nothing left, stop
  EXPECT_EQ(next.state, NewtonRaphson::stop);
  EXPECT_TRUE(next.final_time_reached);
  // A step below the minimum away from the final time: stop, not at the final time.
  NewtonRaphson m = control(3, 2);
  m.initialize(1e-3);
  for (int k = 0; k < 3; ++k) m.check(1.0);
  next = m.compute(0.5, 1.2e-4, 9);
  EXPECT_EQ(next.state, NewtonRaphson::stop);
  EXPECT_FALSE(next.final_time_reached);
}

}  // namespace
}  // namespace lmgc::chipy
