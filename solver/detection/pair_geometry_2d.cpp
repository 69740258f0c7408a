#include "solver/detection/pair_geometry_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;

// Contact point halfway through the gap, on the candidate side of the antagonist surface.
Vector2d middle_point(const Vector2d& candidate_surface, const Vector2d& normal, double gap) {
  return candidate_surface - 0.5 * gap * normal;
}

// Closest point of the segment [a, b] to p.
Vector2d closest_on_segment(const Vector2d& a, const Vector2d& b, const Vector2d& p) {
  const Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + s * ab;
}

// Distance from a point to the JONCx core segment, with the outward direction.
void joncx_core(const Joncx& wall, const Vector2d& p, Vector2d& direction, double& distance) {
  const Vector2d d = p - wall.centre;
  const double d1 = d.dot(wall.axis);
  const Vector2d side(-wall.axis.y(), wall.axis.x());
  const double d2 = d.dot(side);
  if (std::fabs(d1) <= wall.half_length) {
    // Flat side: normal along ±side (spec: numerics.md §5.3 DKJCx).
    direction = d2 >= 0.0 ? side : Vector2d(-side);
    distance = std::fabs(d2);
  } else {
    // Rounded end centred at ±ax1 on the axis.
    const Vector2d end = wall.centre + (d1 > 0.0 ? wall.half_length : -wall.half_length) * wall.axis;
    const Vector2d v = p - end;
    distance = v.norm();
    direction = distance > 0.0 ? Vector2d(v / distance) : side;
  }
}

}  // namespace

bool disk_disk(const Vector2d& c, double rc, const Vector2d& a, double ra, PairContact2D& out) {
  const Vector2d d = c - a;
  const double distance = d.norm();
  if (distance < 1e-18) return false;
  out.normal = d / distance;
  out.gap = distance - (rc + ra);
  out.point = c - (rc + 0.5 * out.gap) * out.normal;
  return true;
}

bool disk_in_hollow_disk(const Vector2d& disk, double radius, const Vector2d& hollow, double outer,
                         PairContact2D& out) {
  const Vector2d d = disk - hollow;
  const double distance = d.norm();
  // Contact on the inner wall of the hollow disk: normal points inward (towards its centre).
  out.normal = distance > 1e-18 ? Vector2d(-d / distance) : Vector2d(0.0, 1.0);
  out.gap = outer - radius - distance;
  out.point = disk - (radius + 0.5 * out.gap) * out.normal;
  return true;
}

bool disk_joncx(const Vector2d& disk, double radius, const Joncx& wall, PairContact2D& out) {
  Vector2d direction;
  double distance;
  joncx_core(wall, disk, direction, distance);
  out.normal = direction;
  out.gap = distance - (wall.half_width + radius);
  out.point = disk - (radius + 0.5 * out.gap) * out.normal;
  return true;
}

bool disk_polygon(const Vector2d& disk, double radius, std::span<const Vector2d> polygon, PairContact2D& out) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  // Largest signed distance to an edge line: > 0 outside; when inside, the least penetration.
  double best = -std::numeric_limits<double>::infinity();
  std::size_t edge = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector2d a = polygon[i], b = polygon[(i + 1) % n];
    const Vector2d e = b - a;
    const Vector2d outward = Vector2d(e.y(), -e.x()).normalized();  // counter-clockwise polygon
    const double s = (disk - a).dot(outward);
    if (s > best) {
      best = s;
      edge = i;
    }
  }
  out.antagonist_segment = static_cast<int>(edge) + 1;
  if (best <= 0.0) {
    const Vector2d e = polygon[(edge + 1) % n] - polygon[edge];
    out.normal = Vector2d(e.y(), -e.x()).normalized();
    out.gap = best - radius;
  } else {
    // Outside: closest point of the boundary (an edge or a vertex).
    double nearest = std::numeric_limits<double>::infinity();
    Vector2d closest = polygon[0];
    for (std::size_t i = 0; i < n; ++i) {
      const Vector2d p = closest_on_segment(polygon[i], polygon[(i + 1) % n], disk);
      const double d2 = (disk - p).squaredNorm();
      if (d2 < nearest) {
        nearest = d2;
        closest = p;
        out.antagonist_segment = static_cast<int>(i) + 1;
      }
    }
    const double distance = std::sqrt(nearest);
    if (distance < 1e-18) return false;
    out.normal = (disk - closest) / distance;
    out.gap = distance - radius;
  }
  out.point = disk - (radius + 0.5 * out.gap) * out.normal;
  return true;
}

int polygon_joncx(std::span<const Vector2d> polygon, const Joncx& wall, double alert, std::array<PairContact2D, 2>& out) {
  // Vertices within the alert distance; keep the two closest.
  int count = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    Vector2d direction;
    double distance;
    joncx_core(wall, polygon[i], direction, distance);
    PairContact2D c;
    c.gap = distance - wall.half_width;
    if (c.gap > alert) continue;
    c.normal = direction;
    c.point = middle_point(polygon[i], c.normal, c.gap);
    c.candidate_vertex = static_cast<int>(i) + 1;
    if (count < 2) {
      out[static_cast<std::size_t>(count++)] = c;
    } else {
      const std::size_t worst = out[0].gap > out[1].gap ? 0 : 1;
      if (c.gap < out[worst].gap) out[worst] = c;
    }
  }
  if (count == 2 && out[0].candidate_vertex > out[1].candidate_vertex) std::swap(out[0], out[1]);
  return count;
}

int polygon_polygon(std::span<const Vector2d> cd, std::span<const Vector2d> an, double alert,
                    std::array<PairContact2D, 2>& out) {
  if (cd.size() < 3 || an.size() < 3) return 0;
  // Separating axis with the largest separation over the edge normals of both polygons.
  auto max_separation = [](std::span<const Vector2d> ref, std::span<const Vector2d> other, std::size_t& edge) {
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ref.size(); ++i) {
      const Vector2d e = ref[(i + 1) % ref.size()] - ref[i];
      const Vector2d outward = Vector2d(e.y(), -e.x()).normalized();
      double deepest = std::numeric_limits<double>::infinity();
      for (const Vector2d& p : other) deepest = std::min(deepest, (p - ref[i]).dot(outward));
      if (deepest > best) {
        best = deepest;
        edge = i;
      }
    }
    return best;
  };
  std::size_t edge_an = 0, edge_cd = 0;
  const double sep_an = max_separation(an, cd, edge_an);
  const double sep_cd = max_separation(cd, an, edge_cd);
  if (std::min(sep_an, sep_cd) > alert && std::max(sep_an, sep_cd) > alert) return 0;
  // Reference edge on the antagonist unless the candidate's edge separates clearly better
  // (small bias keeps the choice stable for parallel faces).
  const bool antagonist_reference = sep_an >= sep_cd - 1e-9 * (1.0 + std::fabs(sep_cd));
  const std::span<const Vector2d> ref = antagonist_reference ? an : cd;
  const std::span<const Vector2d> inc = antagonist_reference ? cd : an;
  const std::size_t ref_edge = antagonist_reference ? edge_an : edge_cd;
  const Vector2d r1 = ref[ref_edge], r2 = ref[(ref_edge + 1) % ref.size()];
  const Vector2d tangent = (r2 - r1).normalized();
  const Vector2d outward(tangent.y(), -tangent.x());
  // Incident points: vertices of the other polygon in front of the reference edge, within alert.
  int count = 0;
  for (std::size_t i = 0; i < inc.size(); ++i) {
    const Vector2d p = inc[i];
    const double along = (p - r1).dot(tangent);
    const double length = (r2 - r1).norm();
    if (along < -1e-12 * length || along > length * (1.0 + 1e-12)) continue;
    PairContact2D c;
    c.gap = (p - r1).dot(outward);
    if (c.gap > alert) continue;
    // n points from antagonist to candidate.
    c.normal = antagonist_reference ? outward : Vector2d(-outward);
    c.point = antagonist_reference ? middle_point(p, c.normal, c.gap) : Vector2d(p - 0.5 * c.gap * outward);
    c.candidate_vertex = antagonist_reference ? static_cast<int>(i) + 1 : 0;
    c.antagonist_segment = antagonist_reference ? static_cast<int>(ref_edge) + 1 : 0;
    if (count < 2) {
      out[static_cast<std::size_t>(count++)] = c;
    } else {
      const std::size_t worst = out[0].gap > out[1].gap ? 0 : 1;
      if (c.gap < out[worst].gap) out[worst] = c;
    }
  }
  if (count == 0) {
    // Vertex–vertex approach: closest pair of vertices against the reference edge's end.
    double nearest = std::numeric_limits<double>::infinity();
    PairContact2D c;
    for (std::size_t i = 0; i < cd.size(); ++i)
      for (std::size_t j = 0; j < an.size(); ++j) {
        const Vector2d p = closest_on_segment(an[j], an[(j + 1) % an.size()], cd[i]);
        const double d = (cd[i] - p).norm();
        if (d < nearest && d > 1e-18) {
          nearest = d;
          c.normal = (cd[i] - p) / d;
          c.gap = d;
          c.point = middle_point(cd[i], c.normal, d);
          c.candidate_vertex = static_cast<int>(i) + 1;
          c.antagonist_segment = static_cast<int>(j) + 1;
        }
      }
    if (nearest <= alert) out[static_cast<std::size_t>(count++)] = c;
  }
  if (count == 2) {
    // Edge–edge contact: each point carries half the shared length.
    const double shared = (out[0].point - out[1].point).norm();
    out[0].length = out[1].length = 0.5 * shared;
  }
  return count;
}

bool point_point(const Vector2d& c, const Vector2d& a, PairContact2D& out) {
  const Vector2d d = c - a;
  const double distance = d.norm();
  out.normal = distance > 1e-18 ? Vector2d(d / distance) : Vector2d(0.0, 1.0);
  out.gap = distance;
  out.point = 0.5 * (c + a);
  return true;
}

}  // namespace lmgc::solver
