#include "solver/bodies/polyhedron.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <deque>
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
  // Undirected edge -> faces holding it.
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::size_t>> edge_faces;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = faces[i][static_cast<std::size_t>(k)],
                         b = faces[i][static_cast<std::size_t>((k + 1) % 3)];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(i);
    }
  std::vector<std::uint8_t> tagged(faces.size(), 0);
  for (std::size_t seed = 0; seed < faces.size(); ++seed) {  // one pass per connected patch
    if (tagged[seed]) continue;
    tagged[seed] = 1;
    std::deque<std::size_t> queue{seed};
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const std::int32_t a = faces[f][static_cast<std::size_t>(k)],
                           b = faces[f][static_cast<std::size_t>((k + 1) % 3)];
        for (std::size_t g : edge_faces[{std::min(a, b), std::max(a, b)}]) {
          if (tagged[g]) continue;
          auto& face = faces[g];
          for (int m = 0; m < 3; ++m)
            if (face[static_cast<std::size_t>(m)] == a && face[static_cast<std::size_t>((m + 1) % 3)] == b) {
              // Same direction as the tagged face: swap the edge's two vertices.
              std::swap(face[static_cast<std::size_t>(m)], face[static_cast<std::size_t>((m + 1) % 3)]);
              break;
            }
          tagged[g] = 1;
          queue.push_back(g);
        }
      }
    }
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
