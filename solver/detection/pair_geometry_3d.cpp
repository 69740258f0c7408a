// docs/lmgc90-facts/numerics.md §2 (comp_rep, SPSPx tangents), §5.3 (SPSPx, SPPLx). Operation order follows
// LMGC90's (mod_algebra cross_product/length3) so that the results match it to the last bit.
#include "solver/detection/pair_geometry_3d.hpp"

#include <cmath>

namespace lmgc::solver {

using Eigen::Vector3d;

namespace {
double dot3(const Vector3d& a, const Vector3d& b) {
  return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
}
Vector3d cross3(const Vector3d& a, const Vector3d& b) {
  return Vector3d(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(),
                  a.x() * b.y() - a.y() * b.x());
}
double length3(const Vector3d& v) {
  return std::sqrt(dot3(v, v));
}
}  // namespace

void tangents_of_normal(const Vector3d& normal, Vector3d& tangent, Vector3d& second_tangent) {
  // §2 comp_rep: a normal lying in a coordinate plane gets the in-plane perpendicular, any other
  // t ∝ e1 × n; always s = t × n.
  const Vector3d n = normal;
  Vector3d t;
  if (std::fabs(n.x()) < 1e-15) {
    t = Vector3d(n.x(), -n.z(), n.y());  // y-z plane
  } else if (std::fabs(n.y()) < 1e-15) {
    t = Vector3d(-n.z(), n.y(), n.x());  // z-x plane
  } else if (std::fabs(n.z()) < 1e-15) {
    t = Vector3d(-n.y(), n.x(), n.z());  // x-y plane
  } else {
    t = cross3(Vector3d::UnitX(), n);
  }
  t /= length3(t);
  tangent = t;
  second_tangent = cross3(t, n);
}

void sphere_sphere_tangents(const Vector3d& normal, Vector3d& tangent, Vector3d& second_tangent) {
  // §2 SPSPx construction. The first branch is LMGC90's cyclic permutation t = (n3, n1, n2): it is
  // orthonormal to n only when two components vanish (axis-aligned n); with exactly one zero
  // component t is not perpendicular to n, and this is kept as LMGC90 has it.
  const Vector3d n = normal;
  const double n1 = n.x(), n2 = n.y(), n3 = n.z();
  Vector3d t;
  if (n1 * n2 == 0.0 || n2 * n3 == 0.0 || n3 * n1 == 0.0) {
    t = Vector3d(n3, n1, n2);
  } else {
    const double den =
        std::sqrt((n2 * n3) * (n2 * n3) + (n1 * n3) * (n1 * n3) + 4.0 * ((n1 * n2) * (n1 * n2)));
    t = Vector3d(-n2 * n3 / den, -n3 * n1 / den, 2.0 * n1 * n2 / den);
  }
  tangent = t;
  second_tangent = cross3(t, n);
}

bool detect_sphere_sphere(const Vector3d& candidate_centre, double candidate_radius,
                          const Vector3d& antagonist_centre, double antagonist_radius, double alert,
                          ContactGeometry3D& geometry) {
  // §5.3 SPSPx.
  const Vector3d sep = candidate_centre - antagonist_centre;
  const double distance = length3(sep);
  if (distance < 1e-18) return false;  // LMGC90 stops here
  const double gap = distance - (candidate_radius + antagonist_radius);
  if (gap > alert) return false;  // a gap equal to the alert distance is kept
  geometry.normal = sep / distance;
  geometry.gap = gap;
  // Midway between the two surface points along n.
  geometry.point = 0.5 * ((candidate_centre + antagonist_centre) +
                          geometry.normal * (antagonist_radius - candidate_radius));
  sphere_sphere_tangents(geometry.normal, geometry.tangent, geometry.second_tangent);
  return true;
}

bool detect_sphere_plane(const Vector3d& centre, double radius, const Vector3d& plane_centre,
                         const Eigen::Matrix3d& plane_frame, const Vector3d& half_axes, double alert,
                         ContactGeometry3D& geometry) {
  // §5.3 SPPLx. LMGC90 takes S as minus the second axis of the PLANx frame, so that S = T × N; the
  // caller passes (T, S, N) already built that way.
  const Vector3d T = plane_frame.col(0), S = plane_frame.col(1), N = plane_frame.col(2);
  const double axe1 = half_axes.x(), axe2 = half_axes.y(), axe3 = half_axes.z();
  const double reach = radius + axe3;
  const Vector3d sep = centre - plane_centre;
  const double x_n = dot3(sep, N);
  const bool above = !(x_n < 0.0);
  // Only the distance along N is compared with the alert distance (strictly); the edge branch below
  // keeps its contact even when its own gap exceeds the alert distance.
  if (!(std::fabs(x_n) - reach < alert)) return false;
  const double x_t = dot3(sep, T), x_s = dot3(sep, S);
  if (!(std::fabs(x_t) < radius + axe1 + axe3 && std::fabs(x_s) < radius + axe2 + axe3)) return false;
  if (std::fabs(x_t) < axe1 && std::fabs(x_s) < axe2) {
    // Face: the whole frame flips on the −N side, (t, n, s) = −(T, N, S), so there s = −(t × n).
    const double side = above ? 1.0 : -1.0;
    const double gap = side * x_n - reach;
    geometry.normal = side * N;
    geometry.tangent = side * T;
    geometry.second_tangent = side * S;
    geometry.gap = gap;
    geometry.point = centre - geometry.normal * (radius + 0.5 * gap);
    return true;
  }
  // Edge or corner (including |x_T| = axe1 exactly): closest point of the mid-plane rectangle, which
  // the plate's half-thickness axe3 rounds. LMGC90 "projects" with centre + x_N N on the −N side;
  // only the T and S coordinates of that point are used, so the sign does not matter.
  const Vector3d projected = (above ? Vector3d(centre - x_n * N) : Vector3d(centre + x_n * N)) - plane_centre;
  double p_t = dot3(projected, T);
  if (std::fabs(p_t) > axe1) p_t = std::copysign(axe1, p_t);
  double p_s = dot3(projected, S);
  if (std::fabs(p_s) > axe2) p_s = std::copysign(axe2, p_s);
  const Vector3d closest = plane_centre + p_t * T + p_s * S;
  const Vector3d d = centre - closest;
  const double distance = length3(d);
  if (distance < 1e-18) return false;  // centre on the rectangle's border: LMGC90 divides by zero
  geometry.normal = d / distance;
  geometry.gap = distance - radius - axe3;
  geometry.point = centre - geometry.normal * (radius + 0.5 * geometry.gap);
  tangents_of_normal(geometry.normal, geometry.tangent, geometry.second_tangent);
  return true;
}

}  // namespace lmgc::solver
