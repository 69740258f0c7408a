#include "solver/detection/cylinder_contact.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace lmgc::solver {

using Eigen::Vector3d;

namespace {

// 1 − β² below this: the axes count as parallel (mod_CDCDx, about 1.8°).
constexpr double kParallel = 1e-3;

// One CDCDx point from a point C on the candidate's axis and A on the antagonist's.
bool axis_points_contact(const Vector3d& C, const Vector3d& A, double r_cd, double r_an, double alert,
                         ContactGeometry3D& g) {
  const Vector3d d = C - A;
  const double distance = d.norm();
  if (distance <= 0.0) return false;
  const double gap = distance - r_cd - r_an;
  if (gap > alert) return false;
  g.normal = d / distance;
  tangents_of_normal(g.normal, g.tangent, g.second_tangent);
  const Vector3d on_cd = C - r_cd * g.normal, on_an = A + r_an * g.normal;
  g.point = 0.5 * (on_cd + on_an);
  g.gap = gap;
  return true;
}

// Closest points of the segments p0 + s (p1 − p0) and q0 + t (q1 − q0), s, t in [0, 1].
void closest_points(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1, double& s,
                    double& t) {
  const Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double c = d1.dot(r), b = d1.dot(d2), denominator = a * e - b * b;
  s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

}  // namespace

bool detect_sphere_cylinder(const Vector3d& x, double r_s, const PlacedCylinder& c, double alert,
                            ContactGeometry3D& g) {
  const Vector3d d = x - c.centre;
  const double h = d.dot(c.axis);
  const Vector3d radial = d - h * c.axis;
  const double rho = radial.norm();
  if (std::abs(h) < c.half_length) {  // beside the cylinder
    if (rho <= 0.0) return false;
    g.gap = rho - r_s - c.radius;
    g.normal = radial / rho;
  } else {
    const double side = h > 0.0 ? 1.0 : -1.0;
    if (rho <= c.radius) {  // over the disc of an end
      g.gap = std::abs(h) - c.half_length - r_s;
      g.normal = side * c.axis;
    } else {  // off the rim: its closest point
      const Vector3d rim = c.centre + side * c.half_length * c.axis + c.radius * radial / rho;
      const Vector3d v = x - rim;
      const double distance = v.norm();
      if (distance <= 0.0) return false;
      g.gap = distance - r_s;
      g.normal = v / distance;
    }
  }
  if (g.gap > alert) return false;
  g.point = x - r_s * g.normal;
  sphere_sphere_tangents(g.normal, g.tangent, g.second_tangent);
  g.second_tangent = g.normal.cross(g.tangent);  // SPCDx: s = n × t
  return true;
}

bool detect_sphere_tube(const Vector3d& x, double r_s, const PlacedCylinder& c, double alert,
                        ContactGeometry3D& g) {
  const Vector3d d = x - c.centre;
  const double h = d.dot(c.axis);
  if (std::abs(h) >= c.half_length) return false;
  const Vector3d radial = d - h * c.axis;
  const double rho = radial.norm();
  if (rho <= 0.0) return false;
  g.gap = c.radius - rho - r_s;
  if (g.gap >= alert) return false;
  g.normal = -radial / rho;
  g.point = x - r_s * g.normal;
  sphere_sphere_tangents(g.normal, g.tangent, g.second_tangent);
  g.second_tangent = g.normal.cross(g.tangent);  // SPDCx: s = n × t, as SPCDx
  return true;
}

bool detect_cylinder_cylinder(const PlacedCylinder& cd, const PlacedCylinder& an, double alert,
                              CylinderContact& out) {
  out.count = 0;
  const Vector3d cd1 = cd.centre - cd.half_length * cd.axis, cd2 = cd.centre + cd.half_length * cd.axis;
  const Vector3d an1 = an.centre - an.half_length * an.axis, an2 = an.centre + an.half_length * an.axis;
  const auto add = [&](const Vector3d& C, const Vector3d& A) {
    if (out.count < 2 && axis_points_contact(C, A, cd.radius, an.radius, alert,
                                             out.points[static_cast<std::size_t>(out.count)]))
      ++out.count;
  };
  const double beta = cd.axis.dot(an.axis);
  if (1.0 - beta * beta < kParallel) {
    // Parallel: the candidate's caps over the antagonist's axis, then the antagonist's over the
    // candidate's, two points at most; end to end, the two facing caps.
    const double L_an = 2.0 * an.half_length, L_cd = 2.0 * cd.half_length;
    const double tolerance = 1e-12 * std::max(L_an, L_cd);
    const double p1 = (cd1 - an1).dot(an.axis), p2 = (cd2 - an1).dot(an.axis);
    if (p1 < tolerance && p2 < tolerance) {
      add(p1 > p2 ? cd1 : cd2, an1);
    } else if (p1 > L_an - tolerance && p2 > L_an - tolerance) {
      add(p1 < p2 ? cd1 : cd2, an2);
    } else {
      if (p1 >= -tolerance && p1 <= L_an + tolerance) add(cd1, an1 + p1 * an.axis);
      if (p2 >= -tolerance && p2 <= L_an + tolerance) add(cd2, an1 + p2 * an.axis);
      const double q1 = (an1 - cd1).dot(cd.axis), q2 = (an2 - cd1).dot(cd.axis);
      if (q1 >= -tolerance && q1 <= L_cd + tolerance) add(cd1 + q1 * cd.axis, an1);
      if (q2 >= -tolerance && q2 <= L_cd + tolerance) add(cd1 + q2 * cd.axis, an2);
    }
  } else {
    double s = 0.0, t = 0.0;
    closest_points(cd1, cd2, an1, an2, s, t);
    add(cd1 + s * (cd2 - cd1), an1 + t * (an2 - an1));
  }
  return out.count > 0;
}

}  // namespace lmgc::solver
