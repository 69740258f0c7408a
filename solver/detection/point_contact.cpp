#include "solver/detection/point_contact.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>

namespace lmgc::solver {

using Eigen::Vector3d;

std::vector<PointLink3D> link_points_3d(const Scene3D& scene) {
  std::vector<PointLink3D> links;
  const RigidBodies3D& b = scene.bodies;
  std::vector<std::size_t> points;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k)
    if (scene.contactors[k].shape == ContactorShape3D::point) points.push_back(k);
  const auto reference = [&](const Contactor3D& c) {
    const auto body = static_cast<std::size_t>(c.body);
    return Vector3d(b.reference[body] + b.frame_initial[body] * c.shift);
  };
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Contactor3D& cd = scene.contactors[points[p]];
    for (std::size_t q = p + 1; q < points.size(); ++q) {
      const Contactor3D& an = scene.contactors[points[q]];
      if (cd.body == an.body) continue;
      for (std::size_t row = 0; row < scene.visibility.size(); ++row) {
        const Visibility3D& v = scene.visibility[row];
        if (v.family != PairFamily3D::PTPT3 || v.candidate_color != cd.color ||
            v.antagonist_color != an.color)
          continue;
        const double length = (reference(cd) - reference(an)).norm();
        if (length <= v.alert)
          links.push_back({static_cast<std::int32_t>(points[p]), static_cast<std::int32_t>(points[q]),
                           static_cast<std::int32_t>(row), length});
        break;
      }
    }
  }
  return links;
}

ContactGeometry3D point_point_geometry(const Vector3d& candidate, const Vector3d& antagonist) {
  ContactGeometry3D g;
  g.point = 0.5 * (candidate + antagonist);
  const double distance = (candidate - antagonist).norm();
  if (distance < 1e-20) {
    g.tangent = Vector3d::UnitX();
    g.normal = Vector3d::UnitY();
    g.second_tangent = Vector3d::UnitZ();
    return g;
  }
  Vector3d n = (candidate - antagonist) / distance;
  for (int k = 0; k < 3; ++k)
    if (std::abs(n(k)) < 1e-18) n(k) = 0.0;
  Vector3d t;
  if (n.x() * n.y() == 0.0 && n.y() * n.z() == 0.0 && n.z() * n.x() == 0.0) {
    t = n.x() != 0.0 ? Vector3d::UnitZ() : n.y() != 0.0 ? Vector3d::UnitX() : Vector3d::UnitY();
  } else if (n.x() == 0.0) {
    const double f = -n.y() / n.z();
    t = Vector3d(1.0, 1.0, f) / std::sqrt(f * f + 2.0);
  } else {
    const double f = -(n.y() + n.z()) / n.x();
    t = Vector3d(f, 1.0, 1.0) / std::sqrt(f * f + 2.0);
  }
  g.normal = n;
  g.tangent = t;
  g.second_tangent = t.cross(n);
  g.gap = distance;
  return g;
}

}  // namespace lmgc::solver
