// The open-contact schedule of the NLGS sweeps: which sweeps solve a contact without reaction, and
// that it is the schedule's first form, which counted the sweeps that passed a contact by.
#include "solver/nlgs/open_contact_visits.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lmgc::solver {
namespace {

// The reference: the schedule as a count of the sweeps without reaction since the restart, solved
// when the count reaches a triangular number (1, 3, 6, 10...).
struct CountedVisits {
  std::int32_t count = 0, threshold = 1;
  bool skip() {
    const bool passes = count + 1 < threshold * (threshold + 1) / 2;
    ++count;
    if (!passes) ++threshold;
    return passes;
  }
  void restart_if(bool condition) {
    count = condition ? 0 : count;
    threshold = condition ? 1 : threshold;
  }
};

TEST(OpenContactSchedule, SolvesTheFirstThirdSixthAndTenthSweepWithoutReaction) {
  OpenContactSchedule v;
  std::vector<int> solved;
  for (int sweep = 0; sweep < 15; ++sweep)
    if (!v.skip(sweep)) solved.push_back(sweep + 1);
  EXPECT_EQ(solved, (std::vector<int>{1, 3, 6, 10, 15}));
}

TEST(OpenContactSchedule, PassesByAnswersWhatSkipWillWithoutCountingAVisit) {
  OpenContactSchedule v;
  for (int sweep = 0; sweep < 200; ++sweep) {
    if (sweep == 77) v.restart();
    const bool predicted = v.passes_by(sweep);
    EXPECT_EQ(predicted, v.passes_by(sweep));  // asking twice changes nothing
    EXPECT_EQ(predicted, v.skip(sweep));
  }
}

// A contact through a random run of sweeps (its solves returning a reaction or not, checks between
// blocks): the schedule passes it by at exactly the sweeps the counted form does.
TEST(OpenContactSchedule, PassesByAtTheSweepsTheCountedFormDoes) {
  std::mt19937 random(2026);
  for (int run = 0; run < 200; ++run) {
    CountedVisits counted;
    OpenContactSchedule schedule;
    bool reaction = random() % 2 == 0;  // the warm start
    const int block = 1 + static_cast<int>(random() % 40);
    const int reaction_odds = static_cast<int>(random() % 5);  // in 8: how often a solve gives one
    for (int sweep = 0; sweep < 400; ++sweep) {
      if (sweep > 0 && sweep % block == 0) {  // a check
        counted.restart_if(true);
        schedule.restart();
      }
      if (!reaction) {
        const bool passed = counted.skip();
        ASSERT_EQ(passed, schedule.skip(sweep)) << "run " << run << ", sweep " << sweep;
        if (passed) continue;
      }
      reaction = static_cast<int>(random() % 8) < reaction_odds;
      counted.restart_if(reaction);
      schedule.restart_if(reaction);
    }
  }
}

}  // namespace
}  // namespace lmgc::solver
