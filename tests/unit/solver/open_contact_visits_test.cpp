// The open-contact visits of the NLGS sweeps: which zero visits solve a contact, and the look-ahead
// the 3D sweeps prefetch by.
#include "solver/nlgs/open_contact_visits.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lmgc::solver
