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

// Contacts through random blocks of sweeps (their solves returning a reaction or not, as a fixed
// function of contact and sweep): the bitmaps visit, at every sweep, exactly the contacts that the
// walk of every contact does not pass by, in execution order, with the same schedules after; and
// their lookahead names each of those positions, in order, `lookahead` visits before its visit.
TEST(DueVisits, VisitAtEverySweepTheContactsTheWalkDoesNotPassBy) {
  std::mt19937 random(2026);
  for (int run = 0; run < 100; ++run) {
    const std::size_t count = 1 + random() % 300;
    const auto sweeps = static_cast<std::int32_t>(1 + random() % 60);
    const int blocks = 1 + static_cast<int>(random() % 3);
    const std::uint32_t seed = random(), reaction_odds = random() % 5;  // in 8: how often a solve gives one
    // The update's effect on the schedule, as the sweeps make it.
    auto visit = [&](std::vector<OpenContactSchedule>& schedule, std::vector<char>& reaction, std::size_t k,
                     std::int32_t sweep) {
      if (!reaction[k]) schedule[k].count_solve(sweep);
      std::uint32_t h =
          seed ^ static_cast<std::uint32_t>(k * 2654435761u) ^ static_cast<std::uint32_t>(sweep * 40503u);
      h ^= h >> 13;
      h *= 0x5bd1e995u;
      h ^= h >> 15;
      reaction[k] = (h % 8) < reaction_odds;
      schedule[k].restart_if(reaction[k] != 0);
    };
    std::vector<OpenContactSchedule> walked(count), filed(count);
    std::vector<char> walked_reaction(count, 0), filed_reaction(count, 0);
    DueVisits due;
    std::int32_t sweep = 0;
    for (int block = 0; block < blocks; ++block) {
      for (std::size_t k = 0; k < count; ++k) {  // the check before the block
        walked[k].restart();
        filed[k].restart();
      }
      due.start_block(count, sweep, sweeps);
      for (std::int32_t i = 0; i < sweeps; ++i, ++sweep) {
        std::vector<std::size_t> expected, visited;
        for (std::size_t k = 0; k < count; ++k) {
          if (walked[k].passes_by(sweep)) continue;
          expected.push_back(k);
          visit(walked, walked_reaction, k, sweep);
        }
        // The lookahead names every visit's position, `lookahead` calls before the visit itself.
        std::vector<std::size_t> announced;
        bool announced_in_time = true;
        due.sweep(
            sweep,
            [&](std::size_t k) {
              const std::size_t due_by = std::min(visited.size() + DueVisits::lookahead + 1, expected.size());
              announced_in_time = announced_in_time && announced.size() == due_by;
              visited.push_back(k);
              visit(filed, filed_reaction, k, sweep);
              return filed[k];
            },
            [&](std::size_t k) { announced.push_back(k); });
        ASSERT_EQ(visited, expected) << "run " << run << ", sweep " << sweep;
        ASSERT_EQ(announced, expected) << "run " << run << ", sweep " << sweep;
        ASSERT_TRUE(announced_in_time) << "run " << run << ", sweep " << sweep;
        for (std::size_t k = 0; k < count; ++k) {
          ASSERT_EQ(filed[k].next, walked[k].next)
              << "run " << run << ", sweep " << sweep << ", contact " << k;
          ASSERT_EQ(filed[k].threshold, walked[k].threshold);
        }
      }
    }
  }
}

TEST(DueVisits, TheLargestGapOfABlockIsTheScheduleFromItsStart) {
  EXPECT_EQ(DueVisits::largest_gap(1), 1);
  EXPECT_EQ(DueVisits::largest_gap(25), 6);  // solves at sweeps 0, 2, 5, 9, 14, 20 (27 is past the block)
  EXPECT_EQ(DueVisits::ring_length(25), 8u);
  EXPECT_EQ(DueVisits::largest_gap(200), 19);
}

// A contact whose solves return a reaction at random sweeps (restarts in mid-block included) is never
// filed further ahead within its block than largest_gap: the ring never holds two sweeps in one bitmap.
TEST(DueVisits, NoVisitFilesAContactFurtherAheadThanTheLargestGap) {
  std::mt19937 random(7);
  for (std::int32_t sweeps = 1; sweeps <= 200; ++sweeps) {
    const std::int32_t gap = DueVisits::largest_gap(sweeps);
    for (int run = 0; run < 50; ++run) {
      OpenContactSchedule s;
      bool reaction = random() % 2 == 0;
      const std::uint32_t odds = random() % 4;  // in 16: how often a solve gives a reaction
      for (std::int32_t sweep = 0; sweep < sweeps; ++sweep) {
        if (s.passes_by(sweep)) continue;
        if (!reaction) s.count_solve(sweep);
        reaction = random() % 16 < odds;
        s.restart_if(reaction);
        const std::int32_t filed = DueVisits::due_at(s, sweep);
        if (filed < sweeps) {
          ASSERT_LE(filed - sweep, gap) << sweeps << " sweeps, at sweep " << sweep;
        }
      }
    }
  }
}

}  // namespace
}  // namespace lmgc::solver
