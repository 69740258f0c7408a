// Contact with meshes (CLALp, CLJCx, PLALp: solver/detection/mesh_detection_2d.hpp, solved by the
// coupled NLGS of solver/nlgs/nlgs_coupled_2d.hpp), on random stacks: an elastic block on a wall, a
// block on a block, a rigid square or disk on a block.
// - Every converged contact satisfies Signorini–Coulomb: the natural-map residual of its reaction and
//   of the relative velocity read from the bodies' end-of-step velocities (V = V_free + K̂⁻¹ I for a
//   mesh, a full solve) is at the solver's tolerance; so the W blocks built from each mesh's condensed
//   compliance are the bodies' response.
// - Two blocks glued node to node (COUPLED_DOF on P2P2L pairs of coinciding PT2DL points) move as the
//   one mesh they make together: the glue's exact solution is that mesh's.
// - With θ = 1 and IQS_CLB, contact without initial overlap never creates energy: the discrete energy
//   ½VᵀMV + ½XᵀKX − Fᵀ_gravity X of the meshes plus the rigid bodies' never grows (the contacts' work
//   r·u_end is ≤ 0, the scheme's own dissipation −½ΔVᵀMΔV − ½ΔXᵀKΔX too).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "solver/integrator/step_2d.hpp"
#include "solver/model/mesh_contact_2d.hpp"
#include "solver/model/scene_builder_2d.hpp"
#include "solver/nlgs/local_solver_2d.hpp"
#include "tests/support/fem_meshes.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

double in_range(double low, double high) {
  return low + (high - low) * *rc::gen::inRange(0, 1001) / 1000.0;
}

std::int32_t node_at(const fem::MeshBody& m, double x, double y) {
  for (std::size_t n = 0; n < m.nodes(); ++n)
    if (std::abs(m.coordinates[2 * n] - x) < 1e-12 && std::abs(m.coordinates[2 * n + 1] - y) < 1e-12)
      return static_cast<std::int32_t>(n);
  return -1;
}

// A Q4 block [x0, x0 + w] × [y0, y0 + height] of nx × ny cells.
fem::MeshBody block(double x0, double y0, double w, double height, int nx, int ny,
                    const fem::Material& material) {
  fem::MeshBody m =
      test::rectangle(fem::ElementKind::Q4, nx, ny, w, height, material, fem::Hypothesis::plane_strain);
  for (std::size_t n = 0; n < m.nodes(); ++n) {
    m.coordinates[2 * n] += x0;
    m.coordinates[2 * n + 1] += y0;
  }
  m.lumped_mass = true;
  return m;
}

// Nodes along the bottom edge from right to left, and along the top from left to right: clockwise.
std::vector<int> bottom_clockwise(const fem::MeshBody& m, double x0, double y0, double w, int nx) {
  std::vector<int> nodes;
  for (int i = nx; i >= 0; --i) nodes.push_back(node_at(m, x0 + w * i / nx, y0));
  return nodes;
}
std::vector<int> top_clockwise(const fem::MeshBody& m, double x0, double y_top, double w, int nx) {
  std::vector<int> nodes;
  for (int i = 0; i <= nx; ++i) nodes.push_back(node_at(m, x0 + w * i / nx, y_top));
  return nodes;
}

struct Stack {
  Scene2D scene;
  bool iqs = true;
};

// One of three random stacks, every body 1 mm above what it falls on.
Stack random_stack(bool iqs_only) {
  SceneBuilder2D b;
  const fem::Material material{in_range(1e6, 1e7), in_range(0.0, 0.45), 1000.0};
  const int nx = *rc::gen::inRange(2, 6), ny = *rc::gen::inRange(1, 3);
  const double mu = in_range(0.0, 1.0), gap = 1e-3, w = 1.0, height = 0.5;
  Stack s;
  s.iqs = iqs_only || *rc::gen::arbitrary<bool>();
  if (s.iqs)
    b.add_law("lawxx", IqsClb{mu});
  else
    b.add_law("lawxx", GapSgrClb{mu});
  b.add_fixed_joncx(0.5, -0.05, 0.0, 2.0, 0.05, "WALLx");
  // The lower block on the wall: a CLxxx point on each edge of its bottom. (Two per edge, as LMGC90's
  // examples put them, make more normal unknowns than the edge has nodes: W is singular and the
  // sweeps creep below 1e-9 where the properties below need 1e-10.)
  const int lower = b.add_mesh(block(0.0, gap, w, height, nx, ny, material));
  const fem::MeshBody& lower_mesh = b.scene().deformable.meshes.bodies[static_cast<std::size_t>(lower)];
  const std::vector<int> bottom = bottom_clockwise(lower_mesh, 0.0, gap, w, nx);
  for (std::size_t k = 0; k + 1 < bottom.size(); ++k)
    b.add_candidate_point(lower, bottom[k], bottom[k + 1], in_range(0.2, 0.8), "LOWER");
  b.see("CLxxx", "LOWER", "lawxx", "JONCx", "WALLx", 0.01);
  const int kind = *rc::gen::inRange(0, 4);
  const double top = gap + height;
  const double vx = in_range(-0.5, 0.5), vy = in_range(-1.0, 0.0);
  if (kind >= 1) b.add_polyline(lower, top_clockwise(lower_mesh, 0.0, top, w, nx), "LOWER");
  if (kind == 1) {
    // A second block on the first: CLALp.
    const double x0 = in_range(-0.2, 0.2);
    const int upper = b.add_mesh(block(x0, top + gap, w, height, nx, ny, material));
    const fem::MeshBody& upper_mesh = b.scene().deformable.meshes.bodies[static_cast<std::size_t>(upper)];
    const std::vector<int> edge = bottom_clockwise(upper_mesh, x0, top + gap, w, nx);
    for (std::size_t k = 0; k + 1 < edge.size(); ++k)
      b.add_candidate_point(upper, edge[k], edge[k + 1], in_range(0.2, 0.8), "UPPER");
    b.see("CLxxx", "UPPER", "lawxx", "ALpxx", "LOWER", 0.01);
    Scene2D scene = b.build();
    MeshBodyState& state = scene.deformable.states[static_cast<std::size_t>(upper)];
    for (Eigen::Index i = 0; i < state.v_begin.size(); i += 2) state.v_begin.segment<2>(i) = Vector2d(vx, vy);
    s.scene = std::move(scene);
    return s;
  }
  if (kind == 3) {
    // A rigid disk on the block: DKALp.
    const double radius = in_range(0.05, 0.2);
    b.add_disk(in_range(0.1, 0.9), top + gap + radius, radius, 1000.0, "DISKS");
    b.see("DISKx", "DISKS", "lawxx", "ALpxx", "LOWER", 0.01);
    b.set_velocity(1, Vector3d(vx, vy, in_range(-5.0, 5.0)));
  }
  if (kind == 2) {
    // A rigid square on the block: PLALp.
    const double side = 0.3, x0 = in_range(0.2, 0.8);
    const double half = side / 2.0;
    b.add_polygon(x0, top + gap + half, {{-half, -half}, {half, -half}, {half, half}, {-half, half}}, 1000.0,
                  "SQUAR");
    b.see("POLYG", "SQUAR", "lawxx", "ALpxx", "LOWER", 0.01);
    b.set_velocity(1, Vector3d(vx, vy, in_range(-1.0, 1.0)));
  }
  s.scene = b.build();
  return s;
}

RunState2D start(const Scene2D& scene, double theta) {
  RunState2D state;
  state.h = 1e-3;
  state.theta = theta;
  state.visibility = build_visibility_index(scene);
  return state;
}

// The relative velocity (t, n) of a contact from the bodies' velocities at the end of the step.
Vector2d velocity_from_bodies(const Scene2D& scene, const Interaction2D& c) {
  Vector2d side_velocity[2];
  for (int side = 0; side < 2; ++side) {
    if (side_on_mesh(c.family, side)) {
      const MeshSideRows rows = mesh_side_rows(scene, c, side);
      side_velocity[side] =
          mesh_side_local_velocity(rows, scene.deformable.states[static_cast<std::size_t>(rows.side.mesh)].v);
    } else {
      const Vector3d& v =
          scene.bodies.velocity[static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body)];
      const Vector2d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
      side_velocity[side] = Vector2d(v.head<2>().dot(c.tangent()) + lever(0) * v.z(),
                                     v.head<2>().dot(c.normal) + lever(1) * v.z());
    }
  }
  return side_velocity[0] - side_velocity[1];
}

RC_GTEST_PROP(MeshContact, EveryConvergedContactSatisfiesSignoriniCoulombAtTheBodiesVelocities, ()) {
  Stack s = random_stack(false);
  RunState2D state = start(s.scene, in_range(0.5, 1.0));
  NlgsOptions options;
  options.storage = NlgsStorage::exchange_local_global;  // the bodies take the returned reactions
  options.tolerance = 1e-10;
  options.gs_it1 = 50;
  options.gs_it2 = 1000;
  options.residual_target = 1e-10;
  int contacts = 0;
  for (int step = 0; step < 60; ++step) {
    const NlgsResult result = step_2d(s.scene, state, options);
    if (state.contacts.empty()) continue;
    RC_ASSERT(result.converged);
    double residual2 = 0.0;
    for (const Interaction2D& c : state.contacts) {
      ++contacts;
      const Vector2d u = velocity_from_bodies(s.scene, c);
      RC_ASSERT((u - c.u).norm() <= 1e-9 * (1.0 + result.free_velocity_norm));
      const double shift = s.iqs ? std::max(0.0, c.gap_begin) / state.h : c.gap_begin / state.h;
      RC_ASSERT(c.r(1) >= 0.0);
      RC_ASSERT(std::abs(c.r(0)) <= c.mu * c.r(1) * (1.0 + 1e-9) + 1e-14);
      residual2 += natural_map_residual_squared_2d(c.r, u + Vector2d(0.0, shift), c.mu);
    }
    RC_ASSERT(std::sqrt(residual2) <= 1e-8 * result.free_velocity_norm + 1e-14);
  }
  RC_TAG(contacts > 0 ? "with contacts" : "none");
}

double energy(const Scene2D& scene) {
  double e = 0.0;
  for (std::size_t m = 0; m < scene.deformable.states.size(); ++m) {
    const MeshBodyState& s = scene.deformable.states[m];
    Eigen::VectorXd g(s.x.size());
    for (Eigen::Index i = 0; i < g.size(); ++i) g(i) = scene.gravity(i % 2);
    e += 0.5 * s.v.dot(s.matrices.mass * s.v) + 0.5 * s.x.dot(s.matrices.stiffness * s.x) -
         (s.matrices.mass * g).dot(s.x);
  }
  const RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vector3d& v = b.velocity[i];
    e += 0.5 * b.mass[i] * v.head<2>().squaredNorm() + 0.5 * b.inertia[i] * v.z() * v.z() -
         b.mass[i] * scene.gravity.dot(b.displacement[i].head<2>());
  }
  return e;
}

RC_GTEST_PROP(MeshContact, IqsClbWithoutInitialOverlapNeverCreatesEnergyWithThetaOne, ()) {
  Stack s = random_stack(true);
  RunState2D state = start(s.scene, 1.0);
  NlgsOptions options;
  options.storage = NlgsStorage::exchange_local_global;
  options.tolerance = 1e-10;
  options.gs_it1 = 50;
  options.gs_it2 = 1000;
  options.residual_target = 1e-10;
  // Energy scale: the blocks' weight times their height (1000 kg/m³ × 0.5 m² × 9.81 × 0.5 m).
  const double scale = 2.5e3;
  for (MeshBodyState& m : s.scene.deformable.states) m.v = m.v_begin;
  s.scene.bodies.velocity = s.scene.bodies.velocity_begin;
  double before = energy(s.scene);
  for (int step = 0; step < 60; ++step) {
    step_2d(s.scene, state, options);
    const double after = energy(s.scene);
    RC_ASSERT(after <= before + 1e-9 * scale);
    before = after;
  }
}

// Two blocks of uniform cells dx × dy side by side, glued at their common edge, against the one block
// they make: with the same random initial velocity field (a rotation, a shear and a stretch) and no
// load, every node moves as its twin of the single mesh, to the NLGS's tolerance, for any θ.
RC_GTEST_PROP(MeshContact, BlocksGluedNodeToNodeMoveAsTheMeshTheyMakeTogether, ()) {
  const fem::Material material{in_range(1e6, 1e7), in_range(0.0, 0.45), 1000.0};
  const int nx_left = *rc::gen::inRange(1, 4), nx_right = *rc::gen::inRange(1, 4),
            ny = *rc::gen::inRange(1, 4);
  const double dx = in_range(0.05, 0.2), height = in_range(0.1, 0.4), w_left = nx_left * dx;
  const double spin = in_range(-2.0, 2.0), shear = in_range(-2.0, 2.0), stretch = in_range(-2.0, 2.0);
  const auto velocity = [&](double x, double y) {
    return Vector2d(-spin * y + shear * y + stretch * x, spin * x - 0.5 * stretch * y);
  };
  const auto start_moving = [&](Scene2D& scene) {
    for (std::size_t m = 0; m < scene.deformable.states.size(); ++m) {
      const fem::MeshBody& mesh = scene.deformable.meshes.bodies[m];
      for (std::size_t n = 0; n < mesh.nodes(); ++n)
        scene.deformable.states[m].v_begin.segment<2>(static_cast<Eigen::Index>(2 * n)) =
            velocity(mesh.coordinates[2 * n], mesh.coordinates[2 * n + 1]);
    }
  };
  SceneBuilder2D glued;
  glued.add_law("glued", CoupledDof{});
  const int left = glued.add_mesh(block(0.0, 0.0, w_left, height, nx_left, ny, material));
  const int right = glued.add_mesh(block(w_left, 0.0, nx_right * dx, height, nx_right, ny, material));
  for (int j = 0; j <= ny; ++j) {
    const double y = height * j / ny, other = height * (j == 0 ? 1 : j - 1) / ny;
    const fem::MeshBody& l = glued.scene().deformable.meshes.bodies[static_cast<std::size_t>(left)];
    const fem::MeshBody& r = glued.scene().deformable.meshes.bodies[static_cast<std::size_t>(right)];
    glued.add_point(left, node_at(l, w_left, y), node_at(l, w_left, other), 0.0, "LEFTx");
    glued.add_point(right, node_at(r, w_left, y), node_at(r, w_left, other), 0.0, "RIGHT");
  }
  glued.see("PT2DL", "LEFTx", "glued", "PT2DL", "RIGHT", 1e-3);
  Scene2D two = glued.build();
  SceneBuilder2D single;
  single.add_mesh(block(0.0, 0.0, (nx_left + nx_right) * dx, height, nx_left + nx_right, ny, material));
  Scene2D one = single.build();
  start_moving(two);
  start_moving(one);
  const double theta = in_range(0.5, 1.0);
  RunState2D state_two = start(two, theta), state_one = start(one, theta);
  NlgsOptions options;
  options.tolerance = 1e-13;
  options.gs_it1 = 50;
  options.gs_it2 = 2000;
  options.residual_target = 1e-13;
  const fem::MeshBody& merged = one.deformable.meshes.bodies[0];
  double scale = 0.0;
  for (std::size_t n = 0; n < merged.nodes(); ++n)
    scale = std::max(scale, velocity(merged.coordinates[2 * n], merged.coordinates[2 * n + 1]).norm());
  for (int step = 0; step < 20; ++step) {
    const NlgsResult result = step_2d(two, state_two, options);
    step_2d(one, state_one, options);
    RC_ASSERT(result.converged);
    RC_ASSERT(state_two.contacts.size() == static_cast<std::size_t>(ny + 1));
    for (std::size_t m = 0; m < 2; ++m) {
      const fem::MeshBody& mesh = two.deformable.meshes.bodies[m];
      const MeshBodyState& s = two.deformable.states[m];
      for (std::size_t n = 0; n < mesh.nodes(); ++n) {
        const std::int32_t twin = node_at(merged, mesh.coordinates[2 * n], mesh.coordinates[2 * n + 1]);
        RC_ASSERT(twin >= 0);
        const auto i = static_cast<Eigen::Index>(2 * n), k = static_cast<Eigen::Index>(2 * twin);
        RC_ASSERT((s.v.segment<2>(i) - one.deformable.states[0].v.segment<2>(k)).norm() <= 1e-8 * scale);
        RC_ASSERT((s.x.segment<2>(i) - one.deformable.states[0].x.segment<2>(k)).norm() <=
                  1e-8 * scale * 1e-3 * (step + 1));
      }
    }
  }
}

}  // namespace
}  // namespace lmgc::solver
