// Two contactors of one type read a '$seety' row either way round, as LMGC90's get_isee_specific
// does, and the lower index stays the candidate (Bridge_PR's REDXx and BLEUx blocks have a
// (REDXx, BLEUx) row only).
#include <gtest/gtest.h>

#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector3d;

TEST(VisibilityRoles3D, SameTypePairKeepsTheLowerIndexAsCandidateWhicheverWayItsRowReads) {
  SceneBuilder3D b;
  b.add_sphere(Vector3d(0.0, 0.0, 0.0), 0.05, 1000.0, "BLEUx");
  b.add_sphere(Vector3d(0.0, 0.0, 0.0999), 0.05, 1000.0, "REDXx");
  b.add_law("iqs", IqsClb{0.3});
  b.see("SPHER", "REDXx", "iqs", "SPHER", "BLEUx", 0.001);
  Scene3D scene = b.build();
  RunState3D state;
  state.h = 1e-3;
  select_prox_tactors(scene, state);
  ASSERT_EQ(state.contacts.size(), 1u);
  EXPECT_EQ(state.contacts[0].candidate, 0);
  EXPECT_EQ(state.contacts[0].antagonist, 1);
  // The normal points from the antagonist to the candidate.
  EXPECT_LT(state.contacts[0].frame.col(1).z(), 0.0);
}

}  // namespace
}  // namespace lmgc::solver
