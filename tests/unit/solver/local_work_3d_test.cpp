// The 3D NLGS counts its Coulomb local solves (NlgsResult::local_solves, step_3d.cpp): the work of a
// step, which the sweeps alone do not tell once they stand still and the rest of a block is skipped.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Scene3D sphere_on_ground() {
  const double r = 0.05;
  SceneBuilder3D b;
  b.add_sphere(Vector3d(0.0, 0.0, r), r, 1000.0);
  b.add_fixed_plane(Vector3d(0.0, 0.0, -0.05), Matrix3d::Identity(), Vector3d(1.0, 1.0, 0.05));
  b.add_law("iqs", IqsClb{0.3});
  b.see("SPHER", "BLEUx", "iqs", "PLANx", "VERTx", 0.001);
  return b.build();
}

// One loaded contact: each sweep run solves it once, and so do the check after the block and the
// post sweep (mod_nlgs_3D i_post) that ends the solve.
TEST(LocalWork3D, OneLoadedContactIsSolvedOncePerSweepRunOncePerCheckAndOnceInThePostSweep) {
  for (const int gs_it1 : {1, 2, 10}) {
    Scene3D scene = sphere_on_ground();
    scene.bodies.velocity[0](0) = scene.bodies.velocity_begin[0](0) = 2.0;  // thrown: it slides
    RunState3D state;
    state.h = 1e-3;
    NlgsOptions options;
    options.gs_it1 = gs_it1;
    options.gs_it2 = 1;
    const NlgsResult result = step_3d(scene, state, options);
    ASSERT_EQ(result.active, 1u);
    ASSERT_EQ(result.iterations, gs_it1);
    EXPECT_EQ(result.local_solves, result.iterations - result.sweeps_skipped + 2) << gs_it1;
  }
}

}  // namespace
}  // namespace lmgc::solver
