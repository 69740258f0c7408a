#pragma once
// The side of a 2D interaction that lies on a mesh (CLALp, CLJCx, P2P2L, PLALp, DKALp, DKDKL): two nodes
// of the mesh and their interpolation weights. A CLxxx or PT2DL point is (1 − apab) x_a + apab x_b; a
// point of an ALpxx segment k is (1 − β) x_k + β x_k+1; the point's velocity and the distribution of a
// reaction on the nodes take the same weights (docs/lmgc90-facts/mailx-2d-contact.md §2, §4). For such
// a side, the interaction's lever (lever_candidate or lever_antagonist) holds the two weights: a node
// has no rotational dof, and the record keeps its size. A DISKL side (DKDKL's antagonist) is a disk
// carried by its edge (a, b): its lever holds the edge b − a at detection, and its velocity and
// reaction maps are mod_DISKL's (mesh_side_rows).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

// P2P2L's pairs of PT2DL points: made once, at the run's first detection, of the points then within
// their visibility row's alert of each other, and kept for the whole run (mod_P2P2L compute_box). A
// pair whose points coincided then is glued: its frame is fixed (t = e_x, n = e_y) and its gap 0.
struct PointPair2D {
  std::int32_t candidate = 0, antagonist = 0;  // mesh contactors, candidate the lower index
  std::int32_t row = 0;                        // its visibility row
  bool glued = false;
};
struct PointPairs2D {
  bool made = false;
  std::vector<PointPair2D> pairs;
};

struct MeshSide2D {
  std::int32_t mesh = 0;
  std::array<std::int32_t, 2> nodes{};  // 0-based nodes of the mesh
  Eigen::Vector2d weights = Eigen::Vector2d::Zero();
};

// Side `side` (0 candidate, 1 antagonist) of an interaction whose side_on_mesh(family, side).
inline MeshSide2D mesh_side(const Scene2D& scene, const Interaction2D& c, int side) {
  const MeshContactor& t =
      scene.deformable.meshes.contactors[static_cast<std::size_t>(side == 0 ? c.candidate : c.antagonist)];
  MeshSide2D s;
  s.mesh = t.mesh;
  if (t.shape != MeshContactorShape::polyline) {
    s.nodes = {t.nodes[0], t.nodes[1]};
  } else {
    const auto k = static_cast<std::size_t>(c.antagonist_segment - 1);  // ALpxx: always the antagonist
    s.nodes = {t.nodes[k], t.nodes[k + 1]};
  }
  s.weights = t.shape == MeshContactorShape::disk ? Eigen::Vector2d(1.0 - t.apab, t.apab)
                                                  : (side == 0 ? c.lever_candidate : c.lever_antagonist);
  return s;
}

// H of a mesh side on the four dofs (a_x, a_y, b_x, b_y) of its two nodes, per local component (t, n):
// `velocity` gives the side's local velocity from the nodes' (the relative velocity is the candidate
// side's minus the antagonist's); `reaction` the nodes' share of the contact's impulse (t, n), which
// the candidate side receives and the antagonist side receives negated. For a point they are the
// weights times the direction. For a DISKL they are mod_DISKL's get_vlocy and add_reac composed with
// the disk's lever −r n (its rotation ω = (v_b,y − v_a,y)/|ab|), which are not each other's transpose.
struct MeshSideRows {
  MeshSide2D side;
  std::array<std::array<double, 4>, 2> velocity{}, reaction{};
};

inline MeshSideRows mesh_side_rows(const Scene2D& scene, const Interaction2D& c, int side) {
  MeshSideRows rows;
  rows.side = mesh_side(scene, c, side);
  const Eigen::Vector2d t = c.tangent(), n = c.normal;
  const MeshContactor& tactor =
      scene.deformable.meshes.contactors[static_cast<std::size_t>(side == 0 ? c.candidate : c.antagonist)];
  if (tactor.shape != MeshContactorShape::disk) {
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d) {
        const std::size_t e = static_cast<std::size_t>(2 * k + d);
        rows.velocity[0][e] = rows.reaction[0][e] = rows.side.weights(k) * t(d);
        rows.velocity[1][e] = rows.reaction[1][e] = rows.side.weights(k) * n(d);
      }
    return rows;
  }
  const Eigen::Vector2d edge = side == 0 ? c.lever_candidate : c.lever_antagonist;
  const double length = edge.norm(), radius = tactor.disk_radius();
  const double offset = radius - tactor.arc_height;  // from the edge's point to the centre
  const Eigen::Vector2d te = edge / length, ne(-te.y(), te.x());
  const Eigen::Vector2d w = rows.side.weights;
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 2; ++d) {
      const std::size_t e = static_cast<std::size_t>(2 * k + d);
      // get_vlocy_DISKL: the edge point's (t, n) velocity, ω, and the centre's normal velocity
      // shifted by −ω (r − h).
      const double omega = d == 1 ? (k == 1 ? 1.0 : -1.0) / length : 0.0;
      const double vt = w(k) * te(d), vn = w(k) * ne(d) - omega * offset;
      const Eigen::Vector2d v = vt * te + vn * ne;
      rows.velocity[0][e] = v.dot(t) - radius * omega;
      rows.velocity[1][e] = v.dot(n);
    }
  // add_reac_DISKL for a unit impulse along t (force −t, moment r) and along n (force −n): the moment
  // brought to the edge's point, then split on a and b; the rows are its negation (the side's sign).
  for (int component = 0; component < 2; ++component) {
    const Eigen::Vector2d force = component == 0 ? Eigen::Vector2d(-t) : Eigen::Vector2d(-n);
    const double moment = component == 0 ? radius : 0.0;
    const double ft = te.dot(force), fn = ne.dot(force);
    const double mz = moment - ft * offset;
    const double fan = (1.0 - w(1)) * fn - mz / length, fbn = fn - fan;
    const double fat = (1.0 - w(1)) * ft, fbt = w(1) * ft;
    const Eigen::Vector2d fa = fat * te + fan * ne, fb = fbt * te + fbn * ne;
    const auto k = static_cast<std::size_t>(component);
    rows.reaction[k] = {-fa.x(), -fa.y(), -fb.x(), -fb.y()};
  }
  return rows;
}

// The side's local (t, n) velocity from its mesh's nodal velocities v (node × 2 + component).
inline Eigen::Vector2d mesh_side_local_velocity(const MeshSideRows& rows, const Eigen::VectorXd& v) {
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t e = 0; e < 4; ++e)
      u(static_cast<Eigen::Index>(k)) +=
          rows.velocity[k][e] * v(2 * rows.side.nodes[e / 2] + static_cast<Eigen::Index>(e % 2));
  return u;
}

}  // namespace lmgc::solver
