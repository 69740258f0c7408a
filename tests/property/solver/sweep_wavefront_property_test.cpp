// Properties of the wavefront execution order of a Gauss–Seidel sweep (solver/nlgs/sweep_wavefront.hpp)
// on random contact lists: it is a permutation of the sweep order, every two contacts that share a
// movable body keep their order, and a Gauss–Seidel sweep run in it gives the same velocities bit for
// bit as in the sweep order; for any window of updates, the default one included.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "solver/nlgs/sweep_wavefront.hpp"

namespace lmgc::solver {
namespace {

struct RandomSweep {
  std::size_t bodies = 0;
  std::vector<std::pair<int, int>> contacts;  // body pairs
  std::vector<bool> movable;
  std::vector<std::uint32_t> order;  // a sweep order: a permutation of the contacts
  std::size_t window = 0;            // 0: the wavefront's own choice
};

RandomSweep random_sweep() {
  RandomSweep s;
  s.bodies = *rc::gen::inRange<std::size_t>(2, 40);
  const auto n = *rc::gen::inRange<std::size_t>(0, 120);
  for (std::size_t k = 0; k < n; ++k) {
    const int i = *rc::gen::inRange<int>(0, static_cast<int>(s.bodies));
    int j = *rc::gen::inRange<int>(0, static_cast<int>(s.bodies) - 1);
    if (j >= i) ++j;
    s.contacts.emplace_back(i, j);
  }
  for (std::size_t i = 0; i < s.bodies; ++i) s.movable.push_back(*rc::gen::inRange(0, 5) != 0);
  s.order.resize(n);
  for (std::size_t k = 0; k < n; ++k) s.order[k] = static_cast<std::uint32_t>(k);
  for (std::size_t k = n; k > 1; --k)
    std::swap(s.order[k - 1], s.order[*rc::gen::inRange<std::size_t>(0, k)]);
  // Windows from one update to more than the list, or the wavefront's own.
  if (*rc::gen::inRange(0, 4) != 0) s.window = *rc::gen::inRange<std::size_t>(1, 130);
  return s;
}

std::vector<std::uint32_t> wavefront_of(const RandomSweep& s, SweepWavefront& wavefront) {
  std::vector<std::uint32_t> execution;
  const auto bodies_of = [&](std::uint32_t k) { return s.contacts[k]; };
  const auto movable = [&](int i) { return static_cast<bool>(s.movable[static_cast<std::size_t>(i)]); };
  if (s.window == 0)
    wavefront.reorder(s.order, bodies_of, movable, s.bodies, execution);
  else
    wavefront.reorder(s.order, bodies_of, movable, s.bodies, execution, s.window);
  return execution;
}

// A scalar Gauss–Seidel sweep with a non-linear update per contact: each reads both bodies'
// velocities and moves the movable ones, as the NLGS does.
std::vector<double> sweep(const RandomSweep& s, const std::vector<std::uint32_t>& order) {
  std::vector<double> v(s.bodies);
  for (std::size_t i = 0; i < s.bodies; ++i) v[i] = 0.1 * static_cast<double>(i) - 1.0;
  for (int pass = 0; pass < 3; ++pass)
    for (const std::uint32_t k : order) {
      const auto [i, j] = s.contacts[k];
      const double gap = v[static_cast<std::size_t>(i)] - v[static_cast<std::size_t>(j)] + 0.01 * k;
      const double r = std::max(0.0, -gap) * 0.37 + std::sin(gap) * 1e-3;
      if (s.movable[static_cast<std::size_t>(i)]) v[static_cast<std::size_t>(i)] += r / 3.0;
      if (s.movable[static_cast<std::size_t>(j)]) v[static_cast<std::size_t>(j)] -= r / 7.0;
    }
  return v;
}

RC_GTEST_PROP(SweepWavefrontProperty, IsAPermutationOfTheSweepOrder, ()) {
  const RandomSweep s = random_sweep();
  SweepWavefront wavefront;
  std::vector<std::uint32_t> execution = wavefront_of(s, wavefront);
  std::vector<std::uint32_t> sorted_order = s.order;
  std::sort(execution.begin(), execution.end());
  std::sort(sorted_order.begin(), sorted_order.end());
  RC_ASSERT(execution == sorted_order);
}

RC_GTEST_PROP(SweepWavefrontProperty, ContactsSharingAMovableBodyKeepTheirOrder, ()) {
  const RandomSweep s = random_sweep();
  SweepWavefront wavefront;
  const std::vector<std::uint32_t> execution = wavefront_of(s, wavefront);
  std::vector<std::size_t> position_in_sweep(s.contacts.size()), position_run(s.contacts.size());
  for (std::size_t p = 0; p < s.order.size(); ++p) position_in_sweep[s.order[p]] = p;
  for (std::size_t p = 0; p < execution.size(); ++p) position_run[execution[p]] = p;
  const auto shares_movable = [&](std::size_t a, std::size_t b) {
    for (const int x : {s.contacts[a].first, s.contacts[a].second})
      if (s.movable[static_cast<std::size_t>(x)] && (x == s.contacts[b].first || x == s.contacts[b].second))
        return true;
    return false;
  };
  for (std::size_t a = 0; a < s.contacts.size(); ++a)
    for (std::size_t b = a + 1; b < s.contacts.size(); ++b)
      if (shares_movable(a, b))
        RC_ASSERT((position_in_sweep[a] < position_in_sweep[b]) == (position_run[a] < position_run[b]));
}

RC_GTEST_PROP(SweepWavefrontProperty, SweepingInWavefrontOrderGivesTheSameVelocitiesBitForBit, ()) {
  const RandomSweep s = random_sweep();
  SweepWavefront wavefront;
  const std::vector<std::uint32_t> execution = wavefront_of(s, wavefront);
  RC_ASSERT(sweep(s, execution) == sweep(s, s.order));
}

TEST(SweepWavefront, AChainOfContactsOnOneBodyHasOneLevelPerContact) {
  // Contacts (0,1), (0,2), (0,3) share body 0: three levels. (4,5) shares nothing: level 1, run
  // right after the first contact of the chain.
  RandomSweep s;
  s.bodies = 6;
  s.contacts = {{0, 1}, {0, 2}, {0, 3}, {4, 5}};
  s.movable.assign(6, true);
  s.order = {0, 1, 2, 3};
  SweepWavefront wavefront;
  EXPECT_EQ(wavefront_of(s, wavefront), (std::vector<std::uint32_t>{0, 3, 1, 2}));
  EXPECT_EQ(wavefront.depth(), 3u);
  // With body 0 immovable (a wall), nothing orders the chain: one level, the sweep order.
  s.movable[0] = false;
  EXPECT_EQ(wavefront_of(s, wavefront), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(wavefront.depth(), 1u);
}

TEST(SweepWavefront, LevelsAreFormedWithinEachWindow) {
  // Windows of two updates: {(0,1), (0,2)} then {(0,3), (4,5)}. The second window starts again
  // from level 1: (4,5) now runs after (0,2), in its window's first level beside (0,3).
  RandomSweep s;
  s.bodies = 6;
  s.contacts = {{0, 1}, {0, 2}, {0, 3}, {4, 5}};
  s.movable.assign(6, true);
  s.order = {0, 1, 2, 3};
  s.window = 2;
  SweepWavefront wavefront;
  EXPECT_EQ(wavefront_of(s, wavefront), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(wavefront.depth(), 2u);
  // Windows of three: {(0,1), (0,2), (4,5)} then {(0,3)}: (4,5) joins the first level.
  s.order = {0, 1, 3, 2};
  s.window = 3;
  EXPECT_EQ(wavefront_of(s, wavefront), (std::vector<std::uint32_t>{0, 3, 1, 2}));
  EXPECT_EQ(wavefront.depth(), 2u);
}

TEST(SweepWavefront, AListOfUpTo4096IsOneWindowALongerOneWindowsOf1024) {
  // A chain on one body has one level per contact within a window: the depth is the window's length.
  for (const std::size_t n : {std::size_t{4096}, std::size_t{5000}}) {
    RandomSweep s;
    s.bodies = n + 1;
    for (std::size_t k = 0; k < n; ++k) s.contacts.emplace_back(0, static_cast<int>(k + 1));
    s.movable.assign(n + 1, true);
    for (std::size_t k = 0; k < n; ++k) s.order.push_back(static_cast<std::uint32_t>(k));
    SweepWavefront wavefront;
    EXPECT_EQ(wavefront_of(s, wavefront), s.order);
    EXPECT_EQ(wavefront.depth(), n <= 4096 ? n : 1024u);
  }
}

}  // namespace
}  // namespace lmgc::solver
