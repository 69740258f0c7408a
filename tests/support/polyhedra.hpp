#pragma once
// Polyhedra for the POLYR tests: a box about the origin, faces oriented as LMGC90 orients them.
#include <Eigen/Core>

#include "solver/bodies/polyhedron.hpp"

namespace lmgc::test {

// A box of half-sizes h centred at the origin (8 vertices, 12 triangles).
inline solver::Polyhedron box_polyhedron(const Eigen::Vector3d& h) {
  solver::Polyhedron p;
  for (int z : {-1, 1})
    for (int y : {-1, 1})
      for (int x : {-1, 1}) p.vertices.emplace_back(x * h.x(), y * h.y(), z * h.z());
  p.faces = {{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
             {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}};
  solver::orient_faces(p.vertices, p.faces);
  solver::finish_polyhedron(p);
  return p;
}

}  // namespace lmgc::test
