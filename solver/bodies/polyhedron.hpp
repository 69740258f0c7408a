#pragma once
// A convex polyhedron contactor (POLYR) as LMGC90 holds it: a closed triangulated surface whose
// vertices are expressed about a reference point, faces oriented outward.
// docs/lmgc90-facts/datbox-inputs.md §1.4 (POLYR), state-and-outputs.md (BODIES.OUT rewrites the vertices in
// the inertia frame); docs/lmgc90-facts/polyhedra.md.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

struct Polyhedron {
  std::vector<Eigen::Vector3d> vertices;           // about the body's centre of inertia, body axes
  std::vector<std::array<std::int32_t, 3>> faces;  // 0-based vertex ids, counter-clockwise seen from outside
  std::vector<Eigen::Vector3d> face_normals;       // unit outward normals, body axes
  // Feature edges (0-based vertex pairs): edges between two faces that are not coplanar, i.e. not
  // the diagonals of a triangulated flat face. Their cross products are separating-axis candidates.
  std::vector<std::array<std::int32_t, 2>> edges;
  // One feature edge per direction (indices into `edges`; parallel edges, either way round, give the
  // same separating axes): a box's 12 edges have 3 directions.
  std::vector<std::int32_t> edge_directions;
  double radius = 0.0;  // largest vertex distance from the reference point
};

// LMGC90's orientation of a triangulated surface (set_orientation_surface_T3, then the global flip
// of compute_mechanical_properties_surface_T3, mod_DiscreteGeometry): each face's neighbours are, in
// the order of its edges, the lowest-numbered other face sharing the edge; face 1's orientation is
// spread breadth-first by whole levels, each face oriented against the first tagged face of its
// neighbour list (a face running the shared edge the same way has the edge's two vertices swapped);
// then, if the enclosed volume is negative, every face has its 2nd and 3rd vertices swapped. Faces
// not connected to face 1, and faces naming missing vertices, are left as they are.
void orient_faces(const std::vector<Eigen::Vector3d>& vertices,
                  std::vector<std::array<std::int32_t, 3>>& faces);

// Unit outward face normals, the feature edges and the bounding radius about the origin of the
// vertex coordinates.
void finish_polyhedron(Polyhedron& p);

// Volume integrals of a closed, outward-oriented triangulated surface, per unit density: volume,
// centroid and the inertia tensor about the centroid (signed tetrahedra from the origin).
struct PolyhedronMass {
  double volume = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centroid, per unit density
};
PolyhedronMass polyhedron_mass(const Polyhedron& p);

}  // namespace lmgc::solver
