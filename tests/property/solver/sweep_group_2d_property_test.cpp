// The 2D sweeps' ways of running the same Gauss–Seidel sweep, against the sweeps that walk every
// contact and run every update alone: plain updates four at a time (solver/nlgs/sweep_group_2d.hpp),
// and visits of the due contacts only, found in bitmaps (solver/nlgs/open_contact_visits.hpp). On
// random disk packings with plain, restitution and law-term contacts, relaxation, the quick scramble
// and a disk with one translation driven, whole steps give the same positions, velocities and reactions bit
// for bit. (On a processor without AVX2 the four-at-a-time runs take the scalar path.)
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "solver/nlgs/sweep_group_2d.hpp"

namespace lmgc::solver {
namespace {

struct RandomPacking {
  std::vector<Eigen::Vector3d> disks;  // x, y, radius
  std::vector<int> colors;             // 0: plain IQS_CLB, 1: RST_CLB, 2: ELASTIC_REPELL_CLB
  double mu = 0.3, relax = 1.0;
  bool scramble = false;
  int steps = 20;
  // A disk with one translation driven at zero velocity (its inverse mass then differs along x and
  // y, which a group cannot hold): disk index and dof, or -1.
  int driven_disk = -1, driven_dof = 0;
};

RandomPacking random_packing() {
  RandomPacking p;
  const int columns = *rc::gen::inRange(3, 12), rows = *rc::gen::inRange(2, 10);
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < rows; ++j) {
      const double r = 0.045 + 0.005 * *rc::gen::inRange(0, 10) / 10.0;
      const double jitter = 0.002 * *rc::gen::inRange(-5, 6);
      // Rows and columns 0.093 apart, radii up to 0.05: a packing already in contact, loaded by gravity.
      p.disks.push_back({0.093 * i + jitter, r + 0.093 * j, r});
      p.colors.push_back(*rc::gen::inRange(0, 8) == 0 ? *rc::gen::inRange(1, 3) : 0);
    }
  p.mu = 0.1 * *rc::gen::inRange(0, 8);
  p.relax = *rc::gen::element(1.0, 1.0, 0.8);
  p.scramble = *rc::gen::arbitrary<bool>();
  p.steps = *rc::gen::inRange(5, 30);
  if (*rc::gen::arbitrary<bool>()) {
    p.driven_disk = *rc::gen::inRange(0, static_cast<int>(p.disks.size()));
    p.driven_dof = *rc::gen::inRange(0, 2);
  }
  return p;
}

struct Outcome {
  std::vector<std::uint64_t> bits;  // displacements, velocities, reactions
  int sweeps = 0;
  std::size_t loaded = 0;  // contacts with a reaction at the end
};

// `due_visits_from`: NlgsOptions's (0: always, the largest value: never).
Outcome run(const RandomPacking& p, bool vector_sweeps, std::size_t due_visits_from) {
  SceneBuilder2D b;
  const char* color[] = {"BLEUx", "REDxx", "VERTx"};
  for (std::size_t k = 0; k < p.disks.size(); ++k)
    b.add_disk(p.disks[k].x(), p.disks[k].y(), p.disks[k].z(), 1000.0, color[p.colors[k]]);
  const double width = 0.1 * static_cast<double>(p.disks.size());
  b.add_fixed_joncx(width / 2, -0.02, 0.0, width, 0.02);  // its top at y = 0
  b.add_fixed_joncx(-0.08, 0.5, 1.5707963267948966, 0.6, 0.02);
  b.add_law("plain", IqsClb{p.mu});
  b.add_law("bounce", RstClb{0.5, 0.0, p.mu});
  b.add_law("repel", ElasticRepellClb{1e4, p.mu});
  const char* law[] = {"plain", "bounce", "repel"};
  for (int c = 0; c < 3; ++c) {
    for (int d = 0; d < 3; ++d) b.see("DISKx", color[c], law[std::max(c, d)], "DISKx", color[d], 0.01);
    b.see("DISKx", color[c], law[c], "JONCx", "WALLx", 0.01);
  }
  Scene2D scene = b.build();
  if (p.driven_disk >= 0) {
    DrivenDof2D held;  // vlocy, every coefficient 0: held still along that axis
    held.body = p.driven_disk;
    held.dof = p.driven_dof;
    scene.driven.push_back(held);
    finalise_scene(scene);
  }
  RunState2D state;
  state.h = 1e-3;
  state.visibility = build_visibility_index(scene);
  NlgsOptions options;
  options.tolerance = 1e-6;
  options.gs_it1 = 10;
  options.gs_it2 = 20;
  options.relax = p.relax;
  options.quick_scramble = p.scramble;
  options.vector_sweeps = vector_sweeps;
  options.due_visits_from = due_visits_from;
  Outcome o;
  for (int i = 0; i < p.steps; ++i) o.sweeps += step_2d(scene, state, options).iterations;
  auto keep = [&](double x) { o.bits.push_back(std::bit_cast<std::uint64_t>(x)); };
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    for (int d = 0; d < 3; ++d) {
      keep(scene.bodies.displacement[k](d));
      keep(scene.bodies.velocity[k](d));
    }
  for (const Interaction2D& c : state.contacts) {
    keep(c.r(0));
    keep(c.r(1));
    o.loaded += c.r(1) != 0.0;
  }
  return o;
}

constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

RC_GTEST_PROP(SweepGroup2DProperty, VectorSweepsGiveTheScalarSweepsStateBitForBit, ()) {
  const RandomPacking p = random_packing();
  const Outcome scalar = run(p, false, kNever), vector = run(p, true, kNever);
  RC_ASSERT(vector.sweeps == scalar.sweeps);
  RC_ASSERT(vector.bits == scalar.bits);
  RC_CLASSIFY(scalar.loaded >= 8, "eight loaded contacts or more");
}

// Alone and four at a time: the groups' blocks walk their segments, the others the bitmaps.
RC_GTEST_PROP(SweepGroup2DProperty, SweepsByDueVisitsGiveTheWalkOfEveryContactsStateBitForBit, ()) {
  const RandomPacking p = random_packing();
  const Outcome walk = run(p, false, kNever);
  const Outcome due = run(p, false, 0), due_vector = run(p, true, 0);
  RC_ASSERT(due.sweeps == walk.sweeps);
  RC_ASSERT(due.bits == walk.bits);
  RC_ASSERT(due_vector.sweeps == walk.sweeps);
  RC_ASSERT(due_vector.bits == walk.bits);
  RC_CLASSIFY(walk.loaded >= 8, "eight loaded contacts or more");
}

}  // namespace
}  // namespace lmgc::solver
