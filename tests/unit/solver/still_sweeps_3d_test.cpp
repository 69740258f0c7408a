// The 3D NLGS skips the rest of a block once its sweeps stand still (step_3d.cpp, solve_contacts):
// the skipped sweeps are counted as done, and the step ends exactly as if the block had been that
// much shorter.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A column of ten spheres on the ground, settled: its sweeps converge within a few dozen.
struct SettledColumn {
  Scene3D scene;
  RunState3D state;
};

NlgsOptions options_with_block(int gs_it1) {
  NlgsOptions o;
  o.norm = NlgsNorm::maxm;
  o.tolerance = 1e-8;
  o.gs_it1 = gs_it1;
  o.gs_it2 = 10;
  return o;
}

SettledColumn settled_column() {
  const double r = 0.05;
  SceneBuilder3D b;
  for (int k = 0; k < 10; ++k) b.add_sphere(Vector3d(0.0, 0.0, r + 2.0 * r * k), r, 1000.0);
  b.add_fixed_plane(Vector3d(0.0, 0.0, -0.05), Matrix3d::Identity(), Vector3d(1.0, 1.0, 0.05));
  b.add_law("iqs05", IqsClb{0.5});
  b.see("SPHER", "BLEUx", "iqs05", "PLANx", "VERTx", 0.001);
  b.see("SPHER", "BLEUx", "iqs05", "SPHER", "BLEUx", 0.001);
  SettledColumn column{b.build(), RunState3D{}};
  column.state.h = 1e-3;
  column.state.theta = 0.5;
  for (int i = 0; i < 100; ++i) step_3d(column.scene, column.state, options_with_block(10));
  return column;
}

TEST(StillSweeps3D, ABlockThatStandsStillEndsAsTheShorterBlockWouldBitForBit) {
  const SettledColumn column = settled_column();
  SettledColumn long_block = column;
  const NlgsResult long_result = step_3d(long_block.scene, long_block.state, options_with_block(400));
  ASSERT_TRUE(long_result.converged);
  EXPECT_EQ(long_result.iterations, 400);  // counted as LMGC90 counts: the whole block
  ASSERT_GT(long_result.sweeps_skipped, 0);
  const int run = 400 - long_result.sweeps_skipped;

  SettledColumn short_block = column;
  const NlgsResult short_result = step_3d(short_block.scene, short_block.state, options_with_block(run));
  EXPECT_TRUE(short_result.converged);
  EXPECT_EQ(short_result.iterations, run);
  EXPECT_EQ(short_result.sweeps_skipped, 0);
  ASSERT_EQ(long_block.state.contacts.size(), short_block.state.contacts.size());
  for (std::size_t k = 0; k < long_block.state.contacts.size(); ++k)
    EXPECT_EQ(long_block.state.contacts[k].r, short_block.state.contacts[k].r) << "contact " << k;
  EXPECT_EQ(long_block.scene.bodies.velocity, short_block.scene.bodies.velocity);
  EXPECT_EQ(long_result.residual_relative, short_result.residual_relative);
}

TEST(StillSweeps3D, SweepsThatStillMoveAreNotSkipped) {
  // The settled column solved again without its warm start: the reactions build up from zero
  // through the whole of a short block, none of it stands still.
  SettledColumn column = settled_column();
  column.state = RunState3D{};
  column.state.h = 1e-3;
  column.state.theta = 0.5;
  const NlgsResult result = step_3d(column.scene, column.state, options_with_block(3));
  EXPECT_EQ(result.sweeps_skipped, 0);
}

}  // namespace
}  // namespace lmgc::solver
