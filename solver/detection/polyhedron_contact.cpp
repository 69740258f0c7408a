#include "solver/detection/polyhedron_contact.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "solver/detection/pair_geometry_3d.hpp"

namespace lmgc::solver {

using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// Cundall's search constants (mod_PRPRx): tilt angles from 0.087 rad down to 0.0017 rad, a move
// accepted when it raises the gap by 1e-6 of the reference size; the band half-width around the
// plane is 0.1 of the bodies' support distances.
constexpr double kTiltMax = 0.087;
constexpr double kTiltMin = 0.0017;
constexpr double kGainTolerance = 1e-6;
constexpr double kBandFraction = 0.1;
constexpr int kTrialDirections = 8;
constexpr double kFaceSideTolerance = 1e-3;

double cross2(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Separation of the two bodies along n: min over the candidate, max over the antagonist.
struct Separation {
  double gap = 0.0;
  std::size_t candidate_vertex = 0, antagonist_vertex = 0;
};
// The first vertex of the extreme value wins, as with `if (d < low)`; the selections are written
// without branches (which vertex is lowest along a trial axis is as good as random: the Cundall
// search and the axis candidates call this some 200 times per pair and step).
Separation separation(const PlacedPolyhedron& cd, const PlacedPolyhedron& an, const Vector3d& n) {
  Separation s;
  double low = std::numeric_limits<double>::infinity(), high = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < cd.vertices.size(); ++k) {
    const double d = n.dot(cd.vertices[k]);
    const bool lower = d < low;
    low = lower ? d : low;
    s.candidate_vertex = lower ? k : s.candidate_vertex;
  }
  for (std::size_t k = 0; k < an.vertices.size(); ++k) {
    const double d = n.dot(an.vertices[k]);
    const bool higher = d > high;
    high = higher ? d : high;
    s.antagonist_vertex = higher ? k : s.antagonist_vertex;
  }
  s.gap = low - high;
  return s;
}

double support_low(const PlacedPolyhedron& p, const Vector3d& n) {
  double low = std::numeric_limits<double>::infinity();
  for (const Vector3d& x : p.vertices) low = std::min(low, n.dot(x));
  return low;
}

// compute_shadow_overlap: false when a face normal (or the centre line) separates the bodies by
// more than alert; otherwise the starting normal of the common plane.
bool shadow_overlap(const PlacedPolyhedron& cd, const PlacedPolyhedron& an, double alert, Vector3d& normal) {
  Vector3d sep = cd.centre - an.centre;
  if (sep.squaredNorm() < 1e-24) sep = Vector3d::UnitZ();
  sep.normalize();
  const double gap0 = separation(cd, an, sep).gap;
  if (gap0 > alert) return false;
  double best_an = gap0, best_cd = gap0;
  int face_an = -1, face_cd = -1;
  for (std::size_t f = 0; f < an.normals.size(); ++f) {
    const Vector3d& nf = an.normals[f];
    if (nf.dot(sep) < -kFaceSideTolerance) continue;
    const double plane = nf.dot(an.vertices[static_cast<std::size_t>(an.shape->faces[f][0])]);
    const double d = support_low(cd, nf) - plane;
    if (d > alert) return false;
    if (d > best_an) best_an = d, face_an = static_cast<int>(f);
  }
  for (std::size_t f = 0; f < cd.normals.size(); ++f) {
    const Vector3d& nf = cd.normals[f];
    if (nf.dot(sep) > kFaceSideTolerance) continue;
    const double plane = nf.dot(cd.vertices[static_cast<std::size_t>(cd.shape->faces[f][0])]);
    const double d = support_low(an, nf) - plane;
    if (d > alert) return false;
    if (d > best_cd) best_cd = d, face_cd = static_cast<int>(f);
  }
  if (face_an >= 0 && face_cd >= 0) {
    normal =
        0.5 * (an.normals[static_cast<std::size_t>(face_an)] - cd.normals[static_cast<std::size_t>(face_cd)]);
    if (normal.squaredNorm() < 1e-24) normal = an.normals[static_cast<std::size_t>(face_an)];
    normal.normalize();
  } else if (face_cd >= 0) {
    normal = -cd.normals[static_cast<std::size_t>(face_cd)];
  } else if (face_an >= 0) {
    normal = an.normals[static_cast<std::size_t>(face_an)];
  } else {
    normal = sep;
  }
  return true;
}

// The separating-axis candidates of two convex polyhedra (face normals of each, cross products of
// their feature edges): the best of them and `start` by gap(n). For penetrating polyhedra the best
// axis is exact (least penetration); for separated ones it starts Cundall's search near the optimum,
// where the search alone can stall on a ridge of gap(n).
Vector3d best_axis(const PlacedPolyhedron& cd, const PlacedPolyhedron& an, const Vector3d& start) {
  Vector3d best = start;
  double best_gap = separation(cd, an, start).gap;
  const auto consider = [&](const Vector3d& n) {
    const double gap = separation(cd, an, n).gap;
    if (gap > best_gap) best_gap = gap, best = n;
  };
  for (const Vector3d& nf : an.normals) consider(nf);
  for (const Vector3d& nf : cd.normals) consider(-nf);
  // One edge per direction of each body: parallel edges give the same axes.
  for (const std::int32_t ka : cd.shape->edge_directions) {
    const auto& ea = cd.shape->edges[static_cast<std::size_t>(ka)];
    const Vector3d a =
        cd.vertices[static_cast<std::size_t>(ea[1])] - cd.vertices[static_cast<std::size_t>(ea[0])];
    for (const std::int32_t kb : an.shape->edge_directions) {
      const auto& eb = an.shape->edges[static_cast<std::size_t>(kb)];
      const Vector3d b =
          an.vertices[static_cast<std::size_t>(eb[1])] - an.vertices[static_cast<std::size_t>(eb[0])];
      Vector3d n = a.cross(b);
      const double length = n.norm();
      if (length <= 1e-9 * a.norm() * b.norm()) continue;  // parallel edges
      n /= length;
      // Oriented from the antagonist to the candidate.
      if (n.dot(cd.centre - an.centre) < 0.0) n = -n;
      consider(n);
    }
  }
  return best;
}

// compute_cundall_common_plane: tilt n by `angle` towards 8 azimuths, keep the best gain, halve the
// angle when none gains enough.
Vector3d cundall_plane(const PlacedPolyhedron& cd, const PlacedPolyhedron& an, Vector3d n,
                       double reference_size, int max_iterations) {
  Separation current = separation(cd, an, n);
  Vector3d t = an.vertices[current.antagonist_vertex] - cd.vertices[current.candidate_vertex];
  t -= t.dot(n) * n;
  Vector3d s;
  if (t.norm() < 1e-6 * reference_size) {
    tangents_of_normal(n, t, s);
  } else {
    t.normalize();
    s = t.cross(n);
  }
  const double c45 = std::cos(std::numbers::pi / 4.0), s45 = std::sin(std::numbers::pi / 4.0);
  double angle = kTiltMax;
  for (int iteration = 0; iteration < max_iterations && angle >= kTiltMin; ++iteration) {
    double best_gap = current.gap;
    Vector3d best_n = n, best_t = t;
    Separation best = current;
    Vector3d tk = t, sk = s;
    for (int k = 0; k < kTrialDirections; ++k) {
      tk = (c45 * tk + s45 * sk).normalized();
      sk = tk.cross(n);
      const Vector3d nk = (std::cos(angle) * n + std::sin(angle) * tk).normalized();
      const Separation trial = separation(cd, an, nk);
      if (trial.gap > best_gap) best_gap = trial.gap, best_n = nk, best_t = tk, best = trial;
    }
    if (best_gap > current.gap && (best_gap - current.gap) / reference_size >= kGainTolerance) {
      n = best_n;
      t = (best_t - best_t.dot(n) * n).normalized();
      s = t.cross(n);
      current = best;
    } else {
      angle *= 0.5;
    }
  }
  return n.normalized();
}

// Convex hull, counter-clockwise, without duplicate or collinear points (monotone chain); one or
// two points for degenerate sets.
std::vector<Vector2d> convex_hull(std::vector<Vector2d> p, double tolerance) {
  std::sort(p.begin(), p.end(), [](const Vector2d& a, const Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Vector2d> unique;
  for (const Vector2d& q : p)
    if (unique.empty() || (q - unique.back()).norm() > tolerance) unique.push_back(q);
  if (unique.size() < 3) return unique;
  std::vector<Vector2d> hull(2 * unique.size());
  std::size_t k = 0;
  const double area_tolerance = tolerance * tolerance;
  for (const Vector2d& q : unique) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], q - hull[k - 2]) <= area_tolerance) --k;
    hull[k++] = q;
  }
  for (std::size_t i = unique.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 1] - hull[k - 2], unique[i] - hull[k - 2]) <= area_tolerance) --k;
    hull[k++] = unique[i];
  }
  hull.resize(k - 1);
  if (hull.size() < 2) {  // all collinear: the two extreme points
    return {unique.front(), unique.back()};
  }
  return hull;
}

// Sutherland–Hodgman: `subject` (any point list, read as a closed loop) clipped by the convex
// counter-clockwise polygon `clipper` (3 vertices or more).
std::vector<Vector2d> clip(std::vector<Vector2d> subject, const std::vector<Vector2d>& clipper,
                           double tolerance) {
  for (std::size_t e = 0; e < clipper.size() && !subject.empty(); ++e) {
    const Vector2d a = clipper[e], b = clipper[(e + 1) % clipper.size()];
    const Vector2d edge = b - a;
    const double length = edge.norm();
    // Distance inside the edge pushed out by the tolerance: a point is kept at >= 0, and an edge of the
    // subject crosses where it changes sign. Measured from the pushed-out line, the crossing lies
    // within the subject's edge: two points on the clipper's edge up to round-off (faces that
    // coincide, as a bridge's voussoirs do) would otherwise give sp ≈ sq and a crossing far outside
    // both polygons.
    const auto side = [&](const Vector2d& q) { return cross2(edge, q - a) / length + tolerance; };
    std::vector<Vector2d> kept;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Vector2d p = subject[i], q = subject[(i + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) kept.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) kept.push_back(p + (q - p) * std::clamp(sp / (sp - sq), 0.0, 1.0));
    }
    subject = std::move(kept);
  }
  return subject;
}

// Overlap of two degenerate hulls (points or segments).
std::vector<Vector2d> degenerate_overlap(const std::vector<Vector2d>& a, const std::vector<Vector2d>& b,
                                         double tolerance) {
  if (a.size() == 2 && b.size() == 2) {
    const Vector2d d1 = a[1] - a[0], d2 = b[1] - b[0];
    const double denominator = cross2(d1, d2);
    if (std::abs(denominator) > tolerance * (d1.norm() + d2.norm())) {  // crossing edges
      const double u = cross2(b[0] - a[0], d2) / denominator, v = cross2(b[0] - a[0], d1) / denominator;
      const double slack = tolerance / std::max(d1.norm(), d2.norm());
      if (u >= -slack && u <= 1.0 + slack && v >= -slack && v <= 1.0 + slack) return {a[0] + u * d1};
      return {};
    }
    // Parallel: the overlap of the two intervals along d1 when the lines coincide.
    const Vector2d dir = d1.normalized();
    if (std::abs(cross2(dir, b[0] - a[0])) > tolerance) return {};
    const double lo = std::max(0.0, std::min(dir.dot(b[0] - a[0]), dir.dot(b[1] - a[0])));
    const double hi = std::min(d1.norm(), std::max(dir.dot(b[0] - a[0]), dir.dot(b[1] - a[0])));
    if (hi < lo - tolerance) return {};
    return {a[0] + lo * dir, a[0] + std::max(lo, hi) * dir};
  }
  // A point against a point or a segment: kept when it lies on the other.
  const std::vector<Vector2d>& point = a.size() == 1 ? a : b;
  const std::vector<Vector2d>& other = a.size() == 1 ? b : a;
  if (point.empty() || other.empty()) return {};
  Vector2d closest = other[0];
  if (other.size() == 2) {
    const Vector2d d = other[1] - other[0];
    const double u = std::clamp((point[0] - other[0]).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    closest = other[0] + u * d;
  }
  if ((closest - point[0]).norm() > tolerance) return {};
  return {point[0]};
}

// The four sharpest corners of a convex polygon with more than four (smallest cosine between the
// incoming and outgoing edges), kept in polygon order.
std::vector<Vector2d> sharpest_four(const std::vector<Vector2d>& polygon) {
  if (polygon.size() <= kMaxPolyhedronPoints) return polygon;
  const std::size_t m = polygon.size();
  std::vector<std::pair<double, std::size_t>> corners;
  for (std::size_t i = 0; i < m; ++i) {
    const Vector2d in = (polygon[i] - polygon[(i + m - 1) % m]).normalized();
    const Vector2d out = (polygon[(i + 1) % m] - polygon[i]).normalized();
    corners.emplace_back(in.dot(out), i);
  }
  std::sort(corners.begin(), corners.end());
  std::vector<std::size_t> kept;
  for (int k = 0; k < kMaxPolyhedronPoints; ++k) kept.push_back(corners[static_cast<std::size_t>(k)].second);
  std::sort(kept.begin(), kept.end());
  std::vector<Vector2d> out;
  for (std::size_t i : kept) out.push_back(polygon[i]);
  return out;
}

// Parameter along n where the line p + λ n enters (candidate: lower surface, faces turned against n)
// or leaves (antagonist: upper surface, faces turned along n) the body.
double surface_along(const PlacedPolyhedron& body, const Vector3d& p, const Vector3d& n, bool lower) {
  double value = lower ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < body.normals.size(); ++f) {
    const double along = body.normals[f].dot(n);
    if (lower ? along > -kFaceSideTolerance : along < kFaceSideTolerance) continue;
    const Vector3d& x = body.vertices[static_cast<std::size_t>(body.shape->faces[f][0])];
    const double lambda = (x - p).dot(body.normals[f]) / along;
    value = lower ? std::max(value, lambda) : std::min(value, lambda);
  }
  return value;
}

}  // namespace

bool detect_polyhedron_plane(const PlacedPolyhedron& polyhedron, const Vector3d& plane_centre,
                             const Matrix3d& plane_frame, const Vector3d& half_axes, double alert,
                             PolyhedronContact& contact) {
  const Vector3d T = plane_frame.col(0), S = plane_frame.col(1), N = plane_frame.col(2);
  const Vector3d v = plane_centre - polyhedron.centre;
  const double h = v.dot(N);
  // Rough test of creation_tab_visu_PRPLx.
  if (std::abs(h) >= polyhedron.radius + half_axes.z() + alert ||
      std::abs(v.dot(T)) >= polyhedron.radius + half_axes.x() ||
      std::abs(v.dot(S)) >= polyhedron.radius + half_axes.y())
    return false;
  const bool below = h >= 0.0;  // polyhedron centre below the plane centre: n = −N
  contact.normal = below ? Vector3d(-N) : N;
  contact.tangent = below ? Vector3d(-T) : T;
  contact.second_tangent = below ? Vector3d(-S) : S;
  contact.count = 0;
  contact.area = 0.0;
  for (std::size_t k = 0; k < polyhedron.vertices.size(); ++k) {
    const Vector3d w = polyhedron.vertices[k] - plane_centre;
    if (std::abs(w.dot(T)) > half_axes.x() + alert || std::abs(w.dot(S)) > half_axes.y() + alert) continue;
    const double gap = contact.normal.dot(w) - half_axes.z();
    if (gap >= alert) continue;
    int slot = contact.count;
    if (contact.count == kMaxPolyhedronPoints) {  // replace the largest gap if this one is smaller
      slot =
          static_cast<int>(std::max_element(contact.gaps.begin(), contact.gaps.end()) - contact.gaps.begin());
      if (gap >= contact.gaps[static_cast<std::size_t>(slot)]) continue;
    } else {
      ++contact.count;
    }
    contact.points[static_cast<std::size_t>(slot)] = polyhedron.vertices[k];
    contact.gaps[static_cast<std::size_t>(slot)] = gap;
    contact.vertices[static_cast<std::size_t>(slot)] = static_cast<int>(k);
  }
  return contact.count > 0;
}

bool detect_polyhedron_polyhedron(const PlacedPolyhedron& cd, const PlacedPolyhedron& an, double alert,
                                  double reference_size, int max_iterations, PolyhedronContact& contact) {
  contact.count = 0;
  Vector3d n;
  if (!shadow_overlap(cd, an, alert, n)) return false;
  n = cundall_plane(cd, an, best_axis(cd, an, n), reference_size, max_iterations);
  const Separation plane = separation(cd, an, n);
  if (plane.gap > alert) return false;
  Vector3d t, s;
  tangents_of_normal(n, t, s);
  contact.normal = n;
  contact.tangent = t;
  contact.second_tangent = s;

  // The near-plane band of each body (mod_PRPRx, after the Cundall search).
  const Vector3d& low = cd.vertices[plane.candidate_vertex];
  const Vector3d& high = an.vertices[plane.antagonist_vertex];
  const Vector3d mid = 0.5 * (low + high);
  const double ref = std::min(std::abs(n.dot(high - an.centre)), std::abs(n.dot(low - cd.centre)));
  const double band = std::max(0.0, 0.5 * plane.gap) + kBandFraction * ref;
  const double tolerance = 1e-9 * std::max(cd.radius, an.radius);
  std::vector<Vector2d> cd_points, an_points;
  for (const Vector3d& x : cd.vertices)
    if (n.dot(x - mid) <= band) cd_points.emplace_back(s.dot(x - mid), t.dot(x - mid));
  for (const Vector3d& x : an.vertices)
    if (n.dot(x - mid) >= -band) an_points.emplace_back(s.dot(x - mid), t.dot(x - mid));
  const std::vector<Vector2d> cd_hull = convex_hull(cd_points, tolerance);
  const std::vector<Vector2d> an_hull = convex_hull(an_points, tolerance);
  std::vector<Vector2d> overlap;
  if (an_hull.size() >= 3) {
    overlap = clip(cd_hull, an_hull, tolerance);
  } else if (cd_hull.size() >= 3) {
    overlap = clip(an_hull, cd_hull, tolerance);
  } else {
    overlap = degenerate_overlap(cd_hull, an_hull, tolerance);
  }
  overlap = convex_hull(overlap, tolerance);
  contact.area = 0.0;
  if (overlap.size() >= 3)
    for (std::size_t k = 0; k < overlap.size(); ++k)
      contact.area += 0.5 * cross2(overlap[k], overlap[(k + 1) % overlap.size()]);
  overlap = sharpest_four(overlap);
  if (overlap.empty()) overlap.emplace_back(0.0, 0.0);  // last chance: the two extreme vertices

  // Each point: where the line along n meets both surfaces; gap = their distance, point midway.
  for (const Vector2d& q : overlap) {
    const Vector3d p = mid + q.x() * s + q.y() * t;
    const double enter = surface_along(cd, p, n, /*lower=*/true);
    const double leave = surface_along(an, p, n, /*lower=*/false);
    double gap = std::isfinite(enter) && std::isfinite(leave) ? enter - leave : plane.gap;
    gap = std::clamp(gap, plane.gap, plane.gap + 2.0 * band);
    const double centre = std::isfinite(enter) && std::isfinite(leave) ? 0.5 * (enter + leave) : 0.0;
    const auto k = static_cast<std::size_t>(contact.count++);
    contact.points[k] = p + std::clamp(centre, -band, band) * n;
    contact.gaps[k] = gap;
    contact.vertices[k] = -1;
  }
  return contact.count > 0;
}

namespace {

// The point of triangle (a, b, c) nearest to p, by the region of p among the triangle's vertices,
// edges and face (Voronoi regions of the triangle).
Vector3d closest_point_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                   const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

bool detect_sphere_polyhedron(const Vector3d& centre, double radius, const PlacedPolyhedron& polyhedron,
                              double alert, ContactGeometry3D& geometry) {
  const auto& faces = polyhedron.shape->faces;
  // The face whose plane the centre is farthest in front of (least deep when it is inside).
  double deepest = -std::numeric_limits<double>::infinity();
  std::size_t front = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const double d =
        polyhedron.normals[f].dot(centre - polyhedron.vertices[static_cast<std::size_t>(faces[f][0])]);
    if (d > deepest) {
      deepest = d;
      front = f;
    }
  }
  if (faces.empty() || deepest - radius > alert) return false;
  if (deepest <= 0.0) {
    geometry.normal = polyhedron.normals[front];
    geometry.point = centre - deepest * geometry.normal;
    geometry.gap = deepest - radius;
  } else {
    // Outside a convex polyhedron the nearest surface point lies on a face the centre is in front of.
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Vector3d& a = polyhedron.vertices[static_cast<std::size_t>(faces[f][0])];
      if (polyhedron.normals[f].dot(centre - a) <= 0.0) continue;
      const Vector3d q =
          closest_point_on_triangle(centre, a, polyhedron.vertices[static_cast<std::size_t>(faces[f][1])],
                                    polyhedron.vertices[static_cast<std::size_t>(faces[f][2])]);
      const double distance = (centre - q).squaredNorm();
      if (distance < best) {
        best = distance;
        geometry.point = q;
      }
    }
    const double distance = std::sqrt(best);
    if (distance - radius > alert) return false;
    geometry.normal =
        distance > 0.0 ? Vector3d((centre - geometry.point) / distance) : polyhedron.normals[front];
    geometry.gap = distance - radius;
  }
  tangents_of_normal(geometry.normal, geometry.tangent, geometry.second_tangent);
  return true;
}

}  // namespace lmgc::solver
