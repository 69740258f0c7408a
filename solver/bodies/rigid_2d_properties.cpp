#include "solver/bodies/rigid_2d_properties.hpp"

#include <algorithm>
#include <cmath>

#include "solver/bodies/lmgc_pi.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using grammar::Real;

double value_at(const std::vector<Real>& values, std::size_t i) {
  return i < values.size() ? values[i].value : 0.0;
}

}  // namespace

ContactorInertia2D contactor_inertia_2d(const grammar::Contactor& c) {
  ContactorInertia2D k;
  const std::string& type = c.type.value;
  if (type == "DISKx" || type == "DISKb") {
    const double r = value_at(c.values, 0);
    k.area = lmgc_pi * r * r;
    k.radius = r;
    k.gyration_radius = r / std::sqrt(2.0);
    if (type == "DISKb") k.shift = Vector2d(value_at(c.values, 1), value_at(c.values, 2));
  } else if (type == "xKSID") {
    const double r = value_at(c.values, 0);
    k.area = -lmgc_pi * r * r;  // a hole: no mass
  } else if (type == "JONCx") {
    // Stadium area; LMGC90's gyration formula (not the exact stadium inertia) reproduced as is.
    const double a1 = value_at(c.values, 0), a2 = value_at(c.values, 1);
    k.area = 4.0 * a1 * a2 + lmgc_pi * a2 * a2;
    k.radius = std::sqrt(k.area / lmgc_pi);
    const double g2 =
        (lmgc_pi * a2 * a2 * (a1 * a1 + 0.5 * a2 * a2) + 2.0 * a1 * a2 * (a1 * a1 + a2 * a2)) / k.area;
    k.gyration_radius = std::sqrt(g2);
  } else if (type == "POLYG") {
    const std::size_t n = c.vertices.size();
    double area2 = 0.0;
    Vector2d centroid = Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const Vector2d a(c.vertices[i][0].value, c.vertices[i][1].value);
      const Vector2d b(c.vertices[(i + 1) % n][0].value, c.vertices[(i + 1) % n][1].value);
      const double cross = a.x() * b.y() - b.x() * a.y();
      area2 += cross;
      centroid += (a + b) * cross;
    }
    k.area = 0.5 * area2;
    if (k.area > 0.0) {
      centroid /= 6.0 * k.area;
      double second = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const Vector2d a = Vector2d(c.vertices[i][0].value, c.vertices[i][1].value) - centroid;
        const Vector2d b =
            Vector2d(c.vertices[(i + 1) % n][0].value, c.vertices[(i + 1) % n][1].value) - centroid;
        const double cross = a.x() * b.y() - b.x() * a.y();
        second += (a.squaredNorm() + a.dot(b) + b.squaredNorm()) * cross;
      }
      k.radius = std::sqrt(k.area / lmgc_pi);
      k.gyration_radius = std::sqrt(second / (12.0 * k.area));
      k.shift = centroid;
    }
  } else if (type == "PT2Dx") {
    k.shift = Vector2d(value_at(c.values, 0), value_at(c.values, 1));
  }
  return k;
}

double polygon_outer_radius(const std::vector<Vector2d>& vertices) {
  if (vertices.empty()) return 0.0;
  double d1 = 0.0, d2 = 0.0;
  for (const Vector2d& v : vertices) {
    d1 += v.x();
    d2 += v.y();
  }
  d1 /= static_cast<double>(vertices.size());
  d2 /= static_cast<double>(vertices.size());
  double radius = 0.0;
  for (const Vector2d& v : vertices)
    radius = std::max(radius, std::sqrt((d1 - v.x()) * (d1 - v.x()) + (d2 - v.y()) * (d2 - v.y())));
  return radius;
}

void normalise_rigid_body_2d(grammar::Body& body, RigidContactorFrames2D* frames) {
  if (body.type != grammar::BodyType::rbdy2 || !body.rigid_bulk || body.nodes.empty()) return;
  grammar::RigidBulk& bulk = *body.rigid_bulk;
  grammar::Node& node = body.nodes.front();
  while (node.coordinates.size() < 3) node.coordinates.push_back(Real{0.0});
  const bool compute_bulk = bulk.avrd.value == 0.0 || bulk.gyrd.value == 0.0;
  double norm2 = 0.0;
  for (const Real& x : node.coordinates) norm2 += x.value * x.value;
  const bool compute_node = norm2 == 0.0;

  std::vector<ContactorInertia2D> parts;
  for (const auto& c : body.contactors) parts.push_back(contactor_inertia_2d(c));

  // Polygon vertices are held relative to their centroid (their shift).
  auto recentre_polygon = [](grammar::Contactor& c, const Vector2d& centroid) {
    for (auto& v : c.vertices) {
      v[0].value -= centroid.x();
      v[1].value -= centroid.y();
    }
  };
  // Writes a contactor's shift back into its card (DISKb/PT2Dx offsets; POLYG vertices).
  auto store_shift = [](grammar::Contactor& c, const Vector2d& shift) {
    const std::string& type = c.type.value;
    if (type == "DISKb" && c.values.size() >= 3) {
      c.values[1].value = shift.x();
      c.values[2].value = shift.y();
    } else if (type == "PT2Dx" && c.values.size() >= 2) {
      c.values[0].value = shift.x();
      c.values[1].value = shift.y();
    } else if (type == "POLYG") {
      for (auto& v : c.vertices) {
        v[0].value += shift.x();
        v[1].value += shift.y();
      }
    }
  };

  for (std::size_t i = 0; i < parts.size(); ++i)
    if (body.contactors[i].type.value == "POLYG") recentre_polygon(body.contactors[i], parts[i].shift);
  if (frames) {
    frames->polygon_vertices.assign(parts.size(), {});
    for (std::size_t i = 0; i < parts.size(); ++i)
      if (body.contactors[i].type.value == "POLYG")
        for (const auto& v : body.contactors[i].vertices)
          frames->polygon_vertices[i].emplace_back(v[0].value, v[1].value);
  }

  if (parts.size() == 1) {
    if (compute_bulk) {
      bulk.avrd.value = parts[0].radius;
      bulk.gyrd.value = parts[0].gyration_radius;
    }
    if (compute_node) {
      node.coordinates[0].value = parts[0].shift.x();
      node.coordinates[1].value = parts[0].shift.y();
      for (std::size_t d = 2; d < node.coordinates.size(); ++d) node.coordinates[d].value = 0.0;
    } else if (parts[0].shift.squaredNorm() >= 1e-6) {
      node.coordinates[0].value += parts[0].shift.x();
      node.coordinates[1].value += parts[0].shift.y();
    }
    // A single contactor always ends centred on the body.
    parts[0].shift.setZero();
    if (body.contactors[0].type.value != "POLYG") store_shift(body.contactors[0], Vector2d::Zero());
  } else if (parts.size() > 1) {
    if (compute_node) {
      // Centre of the cluster, weighted by rdg² (LMGC90 omits π here).
      double weight = 0.0;
      Vector2d centre = Vector2d::Zero();
      for (const auto& p : parts) {
        weight += p.radius * p.radius;
        centre += p.radius * p.radius * p.shift;
      }
      if (weight > 0.0) centre /= weight;
      for (auto& p : parts) p.shift -= centre;
      node.coordinates[0].value = centre.x();
      node.coordinates[1].value = centre.y();
      for (std::size_t d = 2; d < node.coordinates.size(); ++d) node.coordinates[d].value = 0.0;
    }
    if (compute_bulk) {
      double mass = 0.0, inertia = 0.0;
      for (const auto& p : parts) {
        const double m = lmgc_pi * p.radius * p.radius;
        mass += m;
        inertia += m * p.gyration_radius * p.gyration_radius + m * p.shift.squaredNorm();
      }
      bulk.avrd.value = std::sqrt(mass / lmgc_pi);
      bulk.gyrd.value = mass > 0.0 ? std::sqrt(inertia / mass) : 0.0;
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const std::string& type = body.contactors[i].type.value;
      if (type == "POLYG" || type == "DISKb" || type == "PT2Dx") {
        if (type != "POLYG") store_shift(body.contactors[i], Vector2d::Zero());
        store_shift(body.contactors[i], parts[i].shift);
      }
    }
  }
  if (frames) {
    frames->shift.clear();
    for (const auto& p : parts) frames->shift.push_back(p.shift);
  }
}

}  // namespace lmgc::solver
