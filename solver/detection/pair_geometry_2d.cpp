// docs/lmgc90-facts/rigid-2d.md §4.1-4.8.
#include "solver/detection/pair_geometry_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmgc::solver {

using Eigen::Vector2d;

double cross_2d(const Vector2d& a, const Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

namespace {
std::size_t previous(std::size_t i, std::size_t n) {
  return i == 0 ? n - 1 : i - 1;
}
std::size_t following(std::size_t i, std::size_t n) {
  return i + 1 == n ? 0 : i + 1;
}
}  // namespace

bool disk_disk(const Vector2d& c, double rc, const Vector2d& a, double ra, PairContact2D& out) {
  const Vector2d d = c - a;
  const double distance = d.norm();
  if (distance < 1e-18) return false;
  out.normal = d / distance;
  out.gap = distance - (rc + ra);
  out.point = c - rc * out.normal;  // written: the candidate's surface point
  out.candidate_lever = -rc * out.normal;
  out.antagonist_lever = ra * out.normal;
  return true;
}

bool disk_in_hollow_disk(const Vector2d& disk, double radius, const Vector2d& hollow, double outer,
                         PairContact2D& out) {
  const Vector2d d = disk - hollow;
  const double distance = d.norm();
  if (distance < 1e-18) return false;
  // The normal points from the wall into the cavity (towards the hollow disk's centre).
  out.normal = -d / distance;
  out.gap = outer - distance - radius;
  out.point = disk - radius * out.normal;
  out.candidate_lever = -radius * out.normal;
  out.antagonist_lever = -outer * out.normal;
  return true;
}

bool disk_joncx(const Vector2d& disk, double radius, const Joncx& wall, PairContact2D& out) {
  const Vector2d axis = wall.axis, side(-axis.y(), axis.x());
  const Vector2d d = disk - wall.centre;
  const double d1 = d.dot(axis), d2 = d.dot(side);
  const double a1 = wall.half_length, a2 = wall.half_width;
  Vector2d n_local, lever_local;
  double gap;
  if (d1 >= -a1 && d1 <= a1) {
    // Flat faces.
    n_local = d2 >= 0.0 ? Vector2d(0.0, 1.0) : Vector2d(0.0, -1.0);
    gap = std::fabs(d2) - (a2 + radius);
    lever_local = Vector2d(d1, d2 >= 0.0 ? a2 : -a2);
  } else {
    // Rounded ends centred at ±a1 on the axis.
    const double end = d1 > a1 ? a1 : -a1;
    const Vector2d e(d1 - end, d2);
    const double rho = e.norm();
    if (rho <= 0.0) return false;
    n_local = e / rho;
    gap = rho - (a2 + radius);
    lever_local = Vector2d(end + a2 * n_local.x(), a2 * n_local.y());
  }
  out.normal = n_local.x() * axis + n_local.y() * side;
  out.gap = gap;
  out.point = disk - radius * out.normal;
  out.candidate_lever = -radius * out.normal;
  out.antagonist_lever = lever_local.x() * axis + lever_local.y() * side;  // from the JONCx centre
  return true;
}

bool disk_polygon(const Vector2d& b, double r, const PolygonView& p, double alert, PairContact2D& out) {
  const std::size_t n = p.vertices.size();
  if (n < 3) return false;
  const Vector2d towards = b - p.centre;
  if (towards.norm() < 1e-18) return false;
  Vector2d s = towards.normalized();
  // 1. Overlap of the shadows along the centre line.
  double p_max = -std::numeric_limits<double>::infinity();
  for (const Vector2d& v : p.vertices) p_max = std::max(p_max, s.dot(v));
  Vector2d q = b - r * s;
  double over = p_max - s.dot(q);
  if (over + alert < 0.0) return false;
  // 2. The nearest vertex among those whose edge faces the disk.
  std::size_t k = n;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i)
    if (s.dot(p.normals[i]) > 0.1) {
      const double d = (p.vertices[i] - b).norm();
      if (d < nearest) {
        nearest = d;
        k = i;
      }
    }
  if (k == n || nearest <= 0.0) return false;
  // 3. Edge k, edge k-1, or the corner at vertex k.
  const Vector2d s0 = (p.vertices[k] - b) / nearest;
  if (cross_2d(p.normals[k], s0) > 0.0) {
    const std::size_t j = previous(k, n);
    if (cross_2d(p.normals[j], s0) > 0.0) {
      s = p.normals[j];
      k = j;
    } else {
      s = -s0;
    }
  } else {
    s = p.normals[k];
  }
  q = b - r * s;
  over = s.dot(p.vertices[k] - q);
  if (over + alert < 0.0) return false;
  out.normal = s;
  out.gap = -over;
  const Vector2d x = q + over * s;  // on the polygon's boundary
  out.point = x;
  out.candidate_lever = x - b;
  out.antagonist_lever = x - p.centre;
  out.antagonist_segment = static_cast<int>(k) + 1;
  return true;
}

int polygon_joncx(const PolygonView& p, const Joncx& wall, double alert, std::array<PairContact2D, 2>& out) {
  const Vector2d nj(-wall.axis.y(), wall.axis.x());
  const double sn = (wall.centre - p.centre).dot(nj);
  // Normal and reference point on the JONCx face that looks at the polygon centre.
  const Vector2d normal = sn >= 0.0 ? Vector2d(-nj) : nj;
  const Vector2d reference = p.centre + (sn >= 0.0 ? sn - wall.half_width : sn + wall.half_width) * nj;
  const Vector2d tangent(normal.y(), -normal.x());
  std::size_t i1 = 0, i2 = 0;
  double g1 = std::numeric_limits<double>::infinity(), g2 = g1;
  int found = 0;
  for (std::size_t j = 0; j < p.vertices.size(); ++j) {
    const Vector2d& v = p.vertices[j];
    if (normal.dot(v - p.centre) >= 0.0) continue;  // vertex turned away from the wall
    if (std::fabs(tangent.dot(v - wall.centre)) > wall.half_length) continue;  // beyond the flat part
    const double g = normal.dot(v - reference);
    if (!(g < alert)) continue;
    ++found;
    if (g < g1) {
      i2 = i1;
      g2 = g1;
      i1 = j;
      g1 = g;
    } else if (g < g2) {
      i2 = j;
      g2 = g;
    }
  }
  const int count = std::min(found, 2);
  for (int c = 0; c < count; ++c) {
    const std::size_t j = c == 0 ? i1 : i2;
    PairContact2D& o = out[static_cast<std::size_t>(c)];
    o.normal = normal;
    o.gap = c == 0 ? g1 : g2;
    o.point = p.vertices[j];
    o.candidate_lever = p.vertices[j] - p.centre;
    o.antagonist_lever = p.vertices[j] - wall.centre;
    o.candidate_vertex = static_cast<int>(j) + 1;
  }
  return count;
}

int polygon_polygon(const PolygonView& A, const PolygonView& B, double alert,
                    std::array<PairContact2D, 2>& out) {
  const std::size_t na = A.vertices.size(), nb = B.vertices.size();
  if (na < 3 || nb < 3) return 0;
  const Vector2d line = B.centre - A.centre;
  if (line.norm() < 1e-18) return 0;
  Vector2d s = line.normalized();
  // 1. Extreme vertices along the centre line and their shadow overlap.
  std::size_t a = 0, b = 0;
  for (std::size_t i = 1; i < na; ++i)
    if (s.dot(A.vertices[i]) > s.dot(A.vertices[a])) a = i;
  for (std::size_t j = 1; j < nb; ++j)
    if (s.dot(B.vertices[j]) < s.dot(B.vertices[b])) b = j;
  double over = s.dot(A.vertices[a]) - s.dot(B.vertices[b]);
  if (over + alert < 0.0) return 0;
  // 2-3. Turn the separating direction edge by edge until the vertex pair is on the right side.
  Vector2d del = A.vertices[a] - B.vertices[b];
  const int sens = cross_2d(s, del) > 0.0 ? 1 : -1;
  int obj = 0;
  const std::size_t limit = 2 * (na + nb) + 4;
  for (std::size_t guard = 0; guard < limit; ++guard) {
    if (sens > 0) {
      const std::size_t pa = previous(a, na), pb = previous(b, nb);
      const double sa = s.dot(A.normals[pa]), sb = s.dot(B.normals[pb]);
      if (sa > -sb) {
        s = A.normals[pa];
        a = pa;
        obj = 1;
      } else {
        s = -B.normals[pb];
        b = pb;
        obj = -1;
      }
    } else {
      const double sa = s.dot(A.normals[a]), sb = s.dot(B.normals[b]);
      if (sa > -sb) {
        s = A.normals[a];
        a = following(a, na);
        obj = 1;
      } else {
        s = -B.normals[b];
        b = following(b, nb);
        obj = -1;
      }
    }
    del = A.vertices[a] - B.vertices[b];
    over = s.dot(del);
    if ((sens > 0 && cross_2d(s, del) < 0.0) || (sens < 0 && cross_2d(s, del) > 0.0)) break;
  }
  // 4. Contact only when the overlap exceeds -alert.
  if (over + alert <= 0.0) return 0;
  const Vector2d centre = 0.5 * (A.vertices[a] + B.vertices[b]);
  const Vector2d tau(-s.y(), s.x());
  PairContact2D first;
  PairContact2D second;
  bool has_second = false;
  if (obj == -1) {
    // 5. A vertex of A on an edge of B: candidate A, antagonist B, n = -s.
    first.swapped = second.swapped = false;
    const std::size_t segment = sens > 0 ? b : previous(b, nb);
    first.candidate_vertex = static_cast<int>(a) + 1;
    first.antagonist_segment = static_cast<int>(segment) + 1;
    first.point = A.vertices[a] - 0.5 * over * s;
    first.gap = -over;
    const std::size_t pa = previous(a, na), nxt = following(a, na);
    double d1 = (A.vertices[pa] - centre).dot(s);
    std::size_t k = na;
    if (d1 + alert > 0.0) k = pa;
    const double d2 = (A.vertices[nxt] - centre).dot(s);
    if (d2 + alert > 0.0 && d2 > d1) {
      k = nxt;
      d1 = d2;
    }
    if (k != na) {
      has_second = true;
      Vector2d x2 = A.vertices[k] - d1 * s;
      const double ovlap2 = (A.vertices[k] - B.vertices[b]).dot(s);
      double alpha = (x2 - centre).dot(tau);
      const double beta1 =
          sens > 0 ? (B.vertices[following(b, nb)] - centre).dot(tau) : (B.vertices[b] - centre).dot(tau);
      const double beta2 =
          sens > 0 ? (B.vertices[b] - centre).dot(tau) : (B.vertices[previous(b, nb)] - centre).dot(tau);
      if (alpha > beta2) alpha = beta2;
      if (alpha < beta1) alpha = beta1;
      x2 = centre + alpha * tau;
      second.point = x2;
      second.gap = -ovlap2;
      second.candidate_vertex = static_cast<int>(k) + 1;
      second.antagonist_segment = first.antagonist_segment;
    }
    first.normal = second.normal = -s;
    first.candidate_lever = first.point - A.centre;
    first.antagonist_lever = first.point - B.centre;
    second.candidate_lever = second.point - A.centre;
    second.antagonist_lever = second.point - B.centre;
  } else {
    // 6. A vertex of B on an edge of A: candidate B, antagonist A, n = s.
    first.swapped = second.swapped = true;
    const std::size_t segment = sens > 0 ? a : previous(a, na);
    first.candidate_vertex = static_cast<int>(b) + 1;
    first.antagonist_segment = static_cast<int>(segment) + 1;
    first.point = B.vertices[b] + 0.5 * over * s;
    first.gap = -over;
    const std::size_t pb = previous(b, nb), nxt = following(b, nb);
    double d1 = (B.vertices[pb] - centre).dot(s);
    std::size_t k = nb;
    if (d1 - alert < 0.0) k = pb;
    const double d2 = (B.vertices[nxt] - centre).dot(s);
    if (d2 - alert < 0.0 && d2 < d1) {
      k = nxt;
      d1 = d2;
    }
    if (k != nb) {
      has_second = true;
      Vector2d x2 = B.vertices[k] - d1 * s;
      const double ovlap2 = -(B.vertices[k] - A.vertices[a]).dot(s);
      double alpha = (x2 - centre).dot(tau);
      const double beta1 =
          sens > 0 ? (A.vertices[a] - centre).dot(tau) : (A.vertices[previous(a, na)] - centre).dot(tau);
      const double beta2 =
          sens > 0 ? (A.vertices[following(a, na)] - centre).dot(tau) : (A.vertices[a] - centre).dot(tau);
      if (alpha > beta2) alpha = beta2;
      if (alpha < beta1) alpha = beta1;
      x2 = centre + alpha * tau;
      second.point = x2;
      second.gap = -ovlap2;
      second.candidate_vertex = static_cast<int>(k) + 1;
      second.antagonist_segment = first.antagonist_segment;
    }
    first.normal = second.normal = s;
    first.candidate_lever = first.point - B.centre;
    first.antagonist_lever = first.point - A.centre;
    second.candidate_lever = second.point - B.centre;
    second.antagonist_lever = second.point - A.centre;
  }
  out[0] = first;
  if (!has_second) return 1;
  // Each point of an edge-to-edge contact carries half the shared length.
  const double shared = (first.point - second.point).norm();
  out[0].length = 0.5 * shared;
  second.length = 0.5 * shared;
  out[1] = second;
  return 2;
}

bool point_point(const Vector2d& c, const Vector2d& a, PairContact2D& out) {
  const Vector2d d = c - a;
  const double distance = d.norm();
  out.normal = distance > 1e-18 ? Vector2d(d / distance) : Vector2d(0.0, 1.0);
  out.gap = distance;
  out.point = 0.5 * (c + a);
  out.candidate_lever.setZero();
  out.antagonist_lever.setZero();
  return true;
}

}  // namespace lmgc::solver
