#include "validate/rigid_layout.hpp"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "validate/case_index.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

double value_or_zero(const std::vector<grammar::Real>& values, std::size_t k) {
  return k < values.size() ? values[k].value : 0.0;
}

void set_round_box(PlacedContactor& p, int dimension) {
  p.lo = p.centre - Eigen::Vector3d::Constant(p.radius);
  p.hi = p.centre + Eigen::Vector3d::Constant(p.radius);
  if (dimension == 2) p.lo.z() = p.hi.z() = 0.0;
}

// Distance from a point to the segment [-h, h] x {0} of a stadium, in its frame.
double stadium_distance(const PlacedContactor& s, const Eigen::Vector3d& point) {
  const Eigen::Vector3d local = s.axes.transpose() * (point - s.centre);
  const double x = std::max(-s.half.x(), std::min(s.half.x(), local.x()));
  return std::hypot(local.x() - x, local.y());
}

// Signed distance from a point to a box (negative inside).
double box_distance(const PlacedContactor& b, const Eigen::Vector3d& point) {
  const Eigen::Vector3d local = b.axes.transpose() * (point - b.centre);
  const Eigen::Vector3d q = local.cwiseAbs() - b.half;
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : q.maxCoeff();
}

}  // namespace

RigidLayout place_rigid_contactors(const CaseFiles& files) {
  RigidLayout layout;
  if (!files.bodies) return layout;
  layout.dimension = case_dimension(files);
  const BodyIndex index(*files.bodies);
  const InitialDisplacements displacements(files);

  // Bodies whose translation velocity DRV_DOF.DAT imposes (walls, pistons).
  std::unordered_set<const grammar::Body*> driven;
  if (files.drv_dof)
    for (const auto& body : files.drv_dof->bodies)
      for (const auto& node : body.nodes)
        for (const auto& dof : node.dofs)
          if (dof.kind.value == "vlocy" && dof.dof.value >= 1 && dof.dof.value <= layout.dimension)
            if (const grammar::Body* b = index.find(body.body_type.value, body.rank.value)) driven.insert(b);

  const auto& bodies = files.bodies->bodies;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const grammar::Body& body = bodies[i];
    if (body.type == grammar::BodyType::mailx || body.nodes.empty() || body.contactors.empty()) continue;
    const std::size_t rank = index.rank_of(body);
    const auto& x = displacements.of(static_cast<int>(body.type), rank);
    const auto& coordinates = body.nodes.front().coordinates;
    const bool planar = body.type == grammar::BodyType::rbdy2;
    Eigen::Vector3d centre(value_or_zero(coordinates, 0) + value_or_zero(x, 0),
                           value_or_zero(coordinates, 1) + value_or_zero(x, 1),
                           planar ? 0.0 : value_or_zero(coordinates, 2) + value_or_zero(x, 2));
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    if (planar) {
      const double theta = value_or_zero(coordinates, 2) + value_or_zero(x, 2);
      rotation << std::cos(theta), -std::sin(theta), 0.0, std::sin(theta), std::cos(theta), 0.0, 0.0, 0.0,
          1.0;
    } else if (const auto& frame = displacements.frame_of(static_cast<int>(body.type), rank);
               frame.size() == 9) {
      // DOF.INI's a, b, c: the body's axes in the global frame (datbox-inputs.md §6).
      for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
          rotation(row, column) = frame[static_cast<std::size_t>(3 * column + row)].value;
      if (!(std::fabs(rotation.determinant()) > 0.5)) rotation = Eigen::Matrix3d::Identity();  // not a frame
    }
    for (const grammar::Contactor& c : body.contactors) {
      PlacedContactor p;
      p.body = &body;
      p.rank = rank;
      p.body_index = i;
      p.contactor = &c;
      p.see_class = see_class(body, c);
      p.translation_driven = driven.count(&body) > 0;
      const std::string& type = c.type.value;
      const auto& v = c.values;
      if (type == "DISKx" || type == "DISKb" || type == "SPHER" || type == "SPHEb") {
        p.shape = planar ? RigidShape::disk : RigidShape::sphere;
        p.radius = value_or_zero(v, 0);
        const Eigen::Vector3d offset(value_or_zero(v, 1), value_or_zero(v, 2),
                                     planar ? 0.0 : value_or_zero(v, 3));
        p.centre = centre + rotation * offset;
        set_round_box(p, layout.dimension);
      } else if (type == "JONCx") {
        p.shape = RigidShape::stadium;
        p.centre = centre;
        p.axes = rotation;
        p.half = Eigen::Vector3d(value_or_zero(v, 0), value_or_zero(v, 1), 0.0);
        const Eigen::Vector3d along = p.axes.col(0) * p.half.x();
        p.lo = p.centre - along.cwiseAbs() - Eigen::Vector3d(p.half.y(), p.half.y(), 0.0);
        p.hi = p.centre + along.cwiseAbs() + Eigen::Vector3d(p.half.y(), p.half.y(), 0.0);
      } else if (type == "PLANx") {
        p.shape = RigidShape::box;
        p.half = Eigen::Vector3d(value_or_zero(v, 0), value_or_zero(v, 1), value_or_zero(v, 2));
        if (!c.frame.empty()) {
          const grammar::LocalFrame& f = c.frame.front();
          for (int k = 0; k < 3; ++k) {
            p.axes(k, 0) = f.alpha[static_cast<std::size_t>(k)].value;
            p.axes(k, 1) = f.beta[static_cast<std::size_t>(k)].value;
            p.axes(k, 2) = f.gamma[static_cast<std::size_t>(k)].value;
          }
          p.centre =
              centre + rotation * Eigen::Vector3d(f.shift[0].value, f.shift[1].value, f.shift[2].value);
        } else {
          p.centre = centre;
        }
        p.axes = rotation * p.axes;
        const Eigen::Vector3d extent = p.axes.cwiseAbs() * p.half;
        p.lo = p.centre - extent;
        p.hi = p.centre + extent;
      } else if (type == "POLYG" && !c.vertices.empty()) {
        p.shape = RigidShape::polygon;
        // Vertices are global when the node coordinates are all zero (datbox-inputs.md §1.3).
        const bool global = value_or_zero(coordinates, 0) == 0.0 && value_or_zero(coordinates, 1) == 0.0;
        p.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
        p.hi = -p.lo;
        for (const auto& vertex : c.vertices) {
          const Eigen::Vector3d local(vertex[0].value, vertex[1].value, 0.0);
          const Eigen::Vector3d world =
              global ? Eigen::Vector3d(local + Eigen::Vector3d(value_or_zero(x, 0), value_or_zero(x, 1), 0.0))
                     : Eigen::Vector3d(centre + rotation * local);
          p.lo = p.lo.cwiseMin(world);
          p.hi = p.hi.cwiseMax(world);
        }
        p.centre = 0.5 * (p.lo + p.hi);
      } else {
        continue;
      }
      layout.contactors.push_back(std::move(p));
    }
  }
  return layout;
}

double penetration(const PlacedContactor& a, const PlacedContactor& b) {
  const PlacedContactor* round = &a;
  const PlacedContactor* other = &b;
  auto is_round = [](const PlacedContactor& p) {
    return p.shape == RigidShape::disk || p.shape == RigidShape::sphere;
  };
  if (!is_round(a)) std::swap(round, other);
  if (!is_round(*round)) return std::numeric_limits<double>::quiet_NaN();
  switch (other->shape) {
    case RigidShape::disk:
    case RigidShape::sphere:
      return round->radius + other->radius - (round->centre - other->centre).norm();
    case RigidShape::stadium:
      return round->radius + other->half.y() - stadium_distance(*other, round->centre);
    case RigidShape::box:
      return round->radius - box_distance(*other, round->centre);
    case RigidShape::polygon:
      break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace lmgc::validate
