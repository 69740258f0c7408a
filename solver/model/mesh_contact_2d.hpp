#pragma once
// The side of a 2D interaction that lies on a mesh (CLALp, CLJCx, PLALp, DKALp): two nodes of the mesh and
// their interpolation weights. A CLxxx point is (1 − apab) x_a + apab x_b; a point of an ALpxx
// segment k is (1 − β) x_k + β x_k+1; the point's velocity and the distribution of a reaction on
// the nodes take the same weights (docs/lmgc90-facts/mailx-2d-contact.md §2, §4). For such a side,
// the interaction's lever (lever_candidate or lever_antagonist) holds the two weights: a node has
// no rotational dof, and the record keeps its size.
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

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
  if (t.shape == MeshContactorShape::candidate_point) {
    s.nodes = {t.nodes[0], t.nodes[1]};
  } else {
    const auto k = static_cast<std::size_t>(c.antagonist_segment - 1);  // ALpxx: always the antagonist
    s.nodes = {t.nodes[k], t.nodes[k + 1]};
  }
  s.weights = side == 0 ? c.lever_candidate : c.lever_antagonist;
  return s;
}

// The velocity of a mesh side's point from the nodal velocities v (node × 2 + component).
inline Eigen::Vector2d mesh_side_velocity(const MeshSide2D& s, const Eigen::VectorXd& v) {
  const auto a = static_cast<Eigen::Index>(2 * s.nodes[0]), b = static_cast<Eigen::Index>(2 * s.nodes[1]);
  return s.weights(0) * Eigen::Vector2d(v(a), v(a + 1)) + s.weights(1) * Eigen::Vector2d(v(b), v(b + 1));
}

// Adds the force f at a mesh side's point to the nodal vector `impulse`, by the weights.
inline void add_to_mesh_side(const MeshSide2D& s, const Eigen::Vector2d& f, Eigen::VectorXd& impulse) {
  for (int k = 0; k < 2; ++k) {
    const auto i = static_cast<Eigen::Index>(2 * s.nodes[static_cast<std::size_t>(k)]);
    impulse(i) += s.weights(k) * f.x();
    impulse(i + 1) += s.weights(k) * f.y();
  }
}

}  // namespace lmgc::solver
