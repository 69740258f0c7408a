// The four-lane kernel of the 2D sweeps (solver/nlgs/sweep_group_2d.hpp): what it leaves to the scalar
// update it does not touch, and a lane it takes is solved as the Signorini–Coulomb case it falls in.
#include "solver/nlgs/sweep_group_2d.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "solver/nlgs/local_solver_2d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector3d;

// Four disks of unit mass and inertia 0.5 resting on a wall (body 4, immovable), one contact each:
// normal (0, 1), the wall as antagonist.
struct Fixture {
  SweepGroup2D group{};
  std::vector<ContactReaction2D> reaction = std::vector<ContactReaction2D>(4);
  std::vector<Vector3d> velocity = std::vector<Vector3d>(5, Vector3d::Zero());

  Fixture() {
    for (int lane = 0; lane < 4; ++lane) {
      group.nx[lane] = 0.0;
      group.ny[lane] = 1.0;
      group.lever_cd_t[lane] = 0.1;  // ℓ×t of a disk of radius 0.1 touching below
      group.lever_cd_n[lane] = 0.0;
      group.lever_an_t[lane] = group.lever_an_n[lane] = 0.0;
      group.wtt[lane] = 1.0 + 0.1 * 0.1 * 2.0;
      group.wtn[lane] = 0.0;
      group.wnn[lane] = 1.0;
      group.cov_n[lane] = 0.0;
      group.mu[lane] = 0.5;
      const SignoriniCoulombReciprocals2D inverse =
          signorini_coulomb_reciprocals_2d(group.wtt[lane], group.wtn[lane], group.wnn[lane], group.mu[lane]);
      group.inverse_det[lane] = inverse.det;
      group.inverse_forward[lane] = inverse.forward;
      group.inverse_backward[lane] = inverse.backward;
      group.inverse_mass_cd[lane] = 1.0;
      group.inverse_inertia_cd[lane] = 2.0;
      group.inverse_mass_an[lane] = group.inverse_inertia_an[lane] = 0.0;
      group.cd[lane] = lane;
      group.an[lane] = 4;
      group.position[lane] = static_cast<std::uint32_t>(lane);
      reaction[static_cast<std::size_t>(lane)].rt = 0.0;
      reaction[static_cast<std::size_t>(lane)].rn = 0.01;
      velocity[static_cast<std::size_t>(lane)] = Vector3d(0.0, -1.0, 0.0);  // approaching the wall
    }
  }
  int run() { return sweep_group_2d(group, reaction.data(), velocity.data(), false, 1.0, 0.0); }
};

bool same_bits(const Vector3d& a, const Vector3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

TEST(SweepGroup2D, EveryLaneOfAPlainGroupIsTakenAndStopsItsDisk) {
  if (!sweep_groups_available()) GTEST_SKIP() << "no AVX2 on this processor: every update runs alone";
  Fixture f;
  for (ContactReaction2D& s : f.reaction) s.visits = OpenContactSchedule{9, 4};  // to be restarted
  ASSERT_EQ(f.run(), 0xF);
  for (std::size_t k = 0; k < 4; ++k) {
    // Stick: the disk's normal velocity reaches zero; the impulse takes its free momentum (m = 1:
    // the velocity -1 holds the warm start's 0.01 already, so the free velocity is -1.01).
    EXPECT_NEAR(f.velocity[k].y(), 0.0, 1e-15);
    EXPECT_NEAR(f.reaction[k].rn, 1.01, 1e-15);
    EXPECT_EQ(f.reaction[k].rt, 0.0);
    EXPECT_EQ(f.reaction[k].visits.next, 0);  // restarted: it has a reaction
    EXPECT_EQ(f.reaction[k].visits.threshold, 1);
  }
}

TEST(SweepGroup2D, LanesWithoutReactionOrOutsideThePlainCasesAreLeftUntouched) {
  if (!sweep_groups_available()) GTEST_SKIP() << "no AVX2 on this processor: every update runs alone";
  Fixture f;
  f.reaction[1].rt = f.reaction[1].rn = 0.0;  // without reaction: the schedule's to decide
  f.reaction[1].visits.next = 7;
  f.velocity[1] = Vector3d(-0.0, -0.0, -0.0);                    // a zero injection would turn -0 into +0
  f.velocity[2].y() = std::numeric_limits<double>::quiet_NaN();  // NaN: the dividing fallback's case
  // Lane 3 approaches, but its block has no reciprocals (singular): the dividing fallback's case.
  f.group.inverse_det[3] = f.group.inverse_forward[3] = f.group.inverse_backward[3] = 0.0;
  const std::vector<Vector3d> before = f.velocity;
  const std::vector<ContactReaction2D> reaction_before = f.reaction;
  EXPECT_EQ(f.run(), 0x1);
  EXPECT_NEAR(f.velocity[0].y(), 0.0, 1e-15);
  EXPECT_TRUE(same_bits(f.velocity[1], before[1]));
  EXPECT_TRUE(std::isnan(f.velocity[2].y()));
  EXPECT_TRUE(same_bits(f.velocity[3], before[3]));
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_EQ(std::memcmp(&f.reaction[k].rt, &reaction_before[k].rt, 2 * sizeof(double)), 0);
    EXPECT_EQ(f.reaction[k].visits.next, reaction_before[k].visits.next);
    EXPECT_EQ(f.reaction[k].visits.threshold, reaction_before[k].visits.threshold);
  }
}

TEST(SweepGroup2D, AGroupWithEveryLaneWithoutReactionWritesNothing) {
  if (!sweep_groups_available()) GTEST_SKIP() << "no AVX2 on this processor: every update runs alone";
  Fixture f;
  for (ContactReaction2D& s : f.reaction) s.rt = s.rn = 0.0;
  const std::vector<Vector3d> before = f.velocity;
  EXPECT_EQ(f.run(), 0x0);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_TRUE(same_bits(f.velocity[k], before[k]));
}

// The groups leave out a plain contact's tangential law shift, +0 or -0 (sweep_group_2d.cpp): it only
// decides the sign of a zero q_t. With W_tn = -0, a sticking lane's d_t = -(W_nn q_t - W_tn q_n) is a
// zero of the sign opposite to q_t's, and so is r_t = d_t / det before |r| < 1e-24 is flushed to +0.
// Lanes 0 and 1 have u_t = -0, where the shift decides q_t's sign; lanes 2 and 3 have u_t = +0, where
// r_t is -0 with either shift, so that the group's +0 comes from its flush. With either shift, the
// scalar update's flushed reactions are the group's, bit for bit.
TEST(SweepGroup2D, ATangentialShiftOfEitherZeroGivesTheReactionsTheGroupGives) {
  if (!sweep_groups_available()) GTEST_SKIP() << "no AVX2 on this processor: every update runs alone";
  Fixture f;
  for (int lane = 0; lane < 4; ++lane) {
    const bool minus_zero_ut = lane < 2;
    f.group.nx[lane] = minus_zero_ut ? -0.0 : 0.0;
    f.group.wtn[lane] = -0.0;
    f.velocity[static_cast<std::size_t>(lane)] =
        minus_zero_ut ? Vector3d(-0.0, -1.0, -0.0) : Vector3d(0.0, -1.0, 0.0);
  }
  const double wtt = f.group.wtt[0], wtn = f.group.wtn[0], wnn = f.group.wnn[0], mu = f.group.mu[0];
  const SignoriniCoulombReciprocals2D inverse{f.group.inverse_det[0], f.group.inverse_forward[0],
                                              f.group.inverse_backward[0]};
  ASSERT_EQ(f.run(), 0xF);
  for (std::size_t k = 0; k < 4; ++k) {
    const double ut = k < 2 ? -0.0 : 0.0;
    for (const double shift : {0.0, -0.0}) {
      // The scalar update: q = (u - W r_old) + shift, the plain solve, then the flush.
      const double qt = (ut - (wtt * 0.0 + wtn * 0.01)) + shift;
      const double qn = -1.0 - (wtn * 0.0 + wnn * 0.01);
      double rt = 1, rn = 1;
      ContactStatus status;
      ASSERT_TRUE(solve_signorini_coulomb_2d(wtt, wtn, wnn, inverse, qt, qn, mu, rt, rn, status));
      ASSERT_EQ(status, ContactStatus::stick);
      ASSERT_EQ(rt, 0.0);
      EXPECT_NE(std::signbit(rt), std::signbit(qt)) << "lane " << k;
      if (k < 2) {
        EXPECT_EQ(std::signbit(qt), std::signbit(shift)) << "lane " << k;  // the shift decides
      } else {
        EXPECT_TRUE(std::signbit(rt)) << "lane " << k;  // -0 until the flush
      }
      if (std::fabs(rt) < 1e-24) rt = 0.0;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.reaction[k].rt), std::bit_cast<std::uint64_t>(rt))
          << "lane " << k;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(f.reaction[k].rn), std::bit_cast<std::uint64_t>(rn))
          << "lane " << k;
    }
  }
}

}  // namespace
}  // namespace lmgc::solver
