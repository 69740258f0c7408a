// The open-contact visits of the NLGS sweeps: which zero visits solve a contact, and the look-ahead
// the 3D sweeps prefetch by.
#include "solver/nlgs/open_contact_visits.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lmgc::solver {
namespace {

TEST(OpenContactVisits, SolvesTheFirstThirdSixthAndTenthZeroVisits) {
  OpenContactVisits v;
  std::vector<int> solved;
  for (int visit = 1; visit <= 15; ++visit)
    if (!v.skip()) solved.push_back(visit);
  EXPECT_EQ(solved, (std::vector<int>{1, 3, 6, 10, 15}));
}

TEST(OpenContactVisits, SkipsNextAnswersWhatSkipWillWithoutCountingAVisit) {
  OpenContactVisits v;
  for (int visit = 0; visit < 200; ++visit) {
    if (visit == 77) v.restart();
    const bool predicted = v.skips_next();
    EXPECT_EQ(predicted, v.skips_next());  // asking twice changes nothing
    EXPECT_EQ(predicted, v.skip());
  }
}

// A contact through a random run of sweeps (its solves returning a reaction or not, checks between
// blocks): OpenContactSchedule passes it by at exactly the sweeps OpenContactVisits does.
TEST(OpenContactSchedule, PassesByAtTheSweepsOpenContactVisitsDoes) {
  std::mt19937 random(2026);
  for (int run = 0; run < 200; ++run) {
    OpenContactVisits visits;
    OpenContactSchedule schedule;
    bool reaction = random() % 2 == 0;  // the warm start
    const int block = 1 + static_cast<int>(random() % 40);
    const int reaction_odds = static_cast<int>(random() % 5);  // in 8: how often a solve gives one
    for (int sweep = 0; sweep < 400; ++sweep) {
      if (sweep > 0 && sweep % block == 0) {  // a check
        visits.restart();
        schedule.restart();
      }
      if (!reaction) {
        const bool passed = visits.skip();
        ASSERT_EQ(passed, schedule.skip(sweep)) << "run " << run << ", sweep " << sweep;
        if (passed) continue;
      }
      reaction = static_cast<int>(random() % 8) < reaction_odds;
      visits.restart_if(reaction);
      schedule.restart_if(reaction);
    }
  }
}

}  // namespace
}  // namespace lmgc::solver
