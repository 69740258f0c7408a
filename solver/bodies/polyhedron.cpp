#include "solver/bodies/polyhedron.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

namespace lmgc::solver {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

double signed_volume(const std::vector<Vector3d>& v, const std::vector<std::array<std::int32_t, 3>>& faces) {
  double volume = 0.0;
  for (const auto& f : faces)
    volume += v[static_cast<std::size_t>(f[0])].dot(
                  v[static_cast<std::size_t>(f[1])].cross(v[static_cast<std::size_t>(f[2])])) /
              6.0;
  return volume;
}

}  // namespace

void orient_faces(const std::vector<Vector3d>& vertices, std::vector<std::array<std::int32_t, 3>>& faces) {
  const auto nv = static_cast<std::int32_t>(vertices.size());
  for (const auto& f : faces)
    for (std::int32_t k : f)
      if (k < 0 || k >= nv) return;
  if (faces.empty()) return;
  const std::size_t n = faces.size();
  // Neighbours, from the input faces: for each edge k (vertex k to k+1) in the face's own order, the
  // lowest-numbered other face holding both its vertices (edges without one are left out).
  std::vector<std::vector<std::size_t>> faces_of_vertex(static_cast<std::size_t>(nv));
  for (std::size_t i = 0; i < n; ++i)
    for (std::int32_t v : faces[i]) faces_of_vertex[static_cast<std::size_t>(v)].push_back(i);
  std::vector<std::array<std::size_t, 3>> neighbours(n);
  std::vector<std::uint8_t> neighbour_count(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int32_t a = faces[i][k], b = faces[i][(k + 1) % 3];
      for (std::size_t g : faces_of_vertex[static_cast<std::size_t>(a)]) {
        if (g == i) continue;
        const auto& other = faces[g];
        if (other[0] == b || other[1] == b || other[2] == b) {
          neighbours[i][neighbour_count[i]++] = g;
          break;
        }
      }
    }
  // Breadth-first from face 0 by whole levels; within a level, in list order, each face is oriented
  // against the first tagged face of its own neighbour list (faces of this level done before it
  // included), then tagged.
  std::vector<std::uint8_t> tagged(n, 0), listed(n, 0);
  tagged[0] = listed[0] = 1;
  std::vector<std::size_t> level{0}, next;
  for (;;) {
    next.clear();
    for (std::size_t f : level)
      for (std::uint8_t k = 0; k < neighbour_count[f]; ++k) {
        const std::size_t g = neighbours[f][k];
        if (!listed[g]) {
          listed[g] = 1;
          next.push_back(g);
        }
      }
    if (next.empty()) break;
    for (std::size_t e : next) {
      std::size_t reference = n;
      for (std::uint8_t k = 0; k < neighbour_count[e] && reference == n; ++k)
        if (tagged[neighbours[e][k]]) reference = neighbours[e][k];
      if (reference != n) {
        // The shared edge: its first and second vertices in e's order (positions i0 < i1) and their
        // positions in the reference.
        auto& face = faces[e];
        const auto& ref = faces[reference];
        int found = 0, i0 = 0, i1 = 0, j0 = 0, j1 = 0;
        for (int i = 0; i < 3 && found < 2; ++i)
          for (int j = 0; j < 3; ++j)
            if (face[static_cast<std::size_t>(i)] == ref[static_cast<std::size_t>(j)]) {
              (found == 0 ? i0 : i1) = i;
              (found == 0 ? j0 : j1) = j;
              ++found;
              break;
            }
        if (found == 2) {
          const bool forward_in_reference = j1 - j0 == 1 || j1 - j0 == -2;
          const bool forward_in_face = i1 - i0 == 1;
          // Run the same way in both: e is the other way round; swap the shared vertices.
          if (forward_in_reference == forward_in_face)
            std::swap(face[static_cast<std::size_t>(i0)], face[static_cast<std::size_t>(i1)]);
        }
      }
      tagged[e] = 1;
    }
    level.swap(next);
  }
  if (signed_volume(vertices, faces) < 0.0)
    for (auto& f : faces) std::swap(f[1], f[2]);
}

void finish_polyhedron(Polyhedron& p) {
  p.face_normals.clear();
  for (const auto& f : p.faces) {
    const Vector3d& a = p.vertices[static_cast<std::size_t>(f[0])];
    const Vector3d& b = p.vertices[static_cast<std::size_t>(f[1])];
    const Vector3d& c = p.vertices[static_cast<std::size_t>(f[2])];
    p.face_normals.push_back((b - a).cross(c - a).normalized());
  }
  p.radius = 0.0;
  for (const Vector3d& v : p.vertices) p.radius = std::max(p.radius, v.norm());
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::size_t>> edge_faces;
  for (std::size_t f = 0; f < p.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = p.faces[f][static_cast<std::size_t>(k)],
                         b = p.faces[f][static_cast<std::size_t>((k + 1) % 3)];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  p.edges.clear();
  for (const auto& [edge, faces] : edge_faces) {
    const bool flat =
        faces.size() == 2 && p.face_normals[faces[0]].dot(p.face_normals[faces[1]]) > 1.0 - 1e-9;
    if (!flat) p.edges.push_back({edge.first, edge.second});
  }
  p.edge_directions.clear();
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const Vector3d d = (p.vertices[static_cast<std::size_t>(p.edges[e][1])] -
                        p.vertices[static_cast<std::size_t>(p.edges[e][0])])
                           .normalized();
    bool seen = false;
    for (const std::int32_t k : p.edge_directions) {
      const auto& other = p.edges[static_cast<std::size_t>(k)];
      const Vector3d o =
          (p.vertices[static_cast<std::size_t>(other[1])] - p.vertices[static_cast<std::size_t>(other[0])])
              .normalized();
      if (d.cross(o).norm() <= 1e-12) seen = true;
    }
    if (!seen) p.edge_directions.push_back(static_cast<std::int32_t>(e));
  }
}

PolyhedronMass polyhedron_mass(const Polyhedron& p) {
  // Each face and the origin span a signed tetrahedron; its second moments are
  // V/20 (Σ x_i x_iᵀ + (Σ x_i)(Σ x_i)ᵀ) over its three non-origin corners.
  PolyhedronMass m;
  Matrix3d second = Matrix3d::Zero();  // ∫ x xᵀ dV about the origin
  Vector3d first = Vector3d::Zero();   // ∫ x dV
  for (const auto& f : p.faces) {
    const Vector3d& a = p.vertices[static_cast<std::size_t>(f[0])];
    const Vector3d& b = p.vertices[static_cast<std::size_t>(f[1])];
    const Vector3d& c = p.vertices[static_cast<std::size_t>(f[2])];
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vector3d sum = a + b + c;
    m.volume += v;
    first += v * sum / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  if (m.volume == 0.0) return m;
  m.centroid = first / m.volume;
  const Matrix3d central = second - m.volume * m.centroid * m.centroid.transpose();
  m.inertia = central.trace() * Matrix3d::Identity() - central;
  return m;
}

}  // namespace lmgc::solver
