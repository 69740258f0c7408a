#include "solver/detection/detection_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "solver/detection/pair_geometry_2d.hpp"
#include "solver/detection/sort_interactions.hpp"
#include "spatial/multilevel_grid.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

bool is_disk(const std::string& t) {
  return t == "DISKx" || t == "DISKb";
}

}  // namespace

bool pair_family_of(const std::string& cd, const std::string& an, PairFamily2D& family) {
  if (is_disk(cd) && is_disk(an))
    family = PairFamily2D::DKDKx;
  else if (is_disk(cd) && an == "xKSID")
    family = PairFamily2D::DKKDx;
  else if (is_disk(cd) && an == "JONCx")
    family = PairFamily2D::DKJCx;
  else if (is_disk(cd) && an == "POLYG")
    family = PairFamily2D::DKPLx;
  else if (cd == "PT2Dx" && an == "PT2Dx")
    family = PairFamily2D::PTPT2;
  else if (cd == "POLYG" && an == "POLYG")
    family = PairFamily2D::PLPLx;
  else if (cd == "POLYG" && an == "JONCx")
    family = PairFamily2D::PLJCx;
  else
    return false;
  return true;
}

VisibilityIndex2D build_visibility_index(const Scene2D& scene) {
  VisibilityIndex2D index;
  std::map<std::pair<std::string, std::string>, std::int32_t> classes;
  std::vector<std::pair<std::string, std::string>> class_keys;
  index.contactor_class.reserve(scene.contactors.size());
  for (const Contactor2D& c : scene.contactors) {
    auto key = std::make_pair(c.type, c.color);
    auto [it, inserted] = classes.emplace(key, static_cast<std::int32_t>(class_keys.size()));
    if (inserted) class_keys.push_back(key);
    index.contactor_class.push_back(it->second);
    index.contactor_body.push_back(c.body);
    index.contactor_shape.push_back(c.shape);
    index.contactor_radius.push_back(c.radius);
    index.contactor_bounding_radius.push_back(c.bounding_radius);
    index.contactor_shift.push_back(c.shift);
  }
  index.class_count = static_cast<std::int32_t>(class_keys.size());
  index.row.assign(static_cast<std::size_t>(index.class_count * index.class_count), -1);
  index.family.assign(static_cast<std::size_t>(index.class_count * index.class_count), -1);
  // First matching row wins, looked up in either order; the pair family fixes the roles
  // (contact-laws.md §1.2).
  for (std::int32_t a = 0; a < index.class_count; ++a)
    for (std::int32_t b = 0; b < index.class_count; ++b) {
      const auto& [ta, ca] = class_keys[static_cast<std::size_t>(a)];
      const auto& [tb, cb] = class_keys[static_cast<std::size_t>(b)];
      PairFamily2D family;
      if (!pair_family_of(ta, tb, family)) continue;
      index.family[static_cast<std::size_t>(a * index.class_count + b)] = static_cast<std::int8_t>(family);
      for (std::size_t v = 0; v < scene.visibility.size(); ++v) {
        const Visibility2D& s = scene.visibility[v];
        const bool direct = s.candidate_type == ta && s.candidate_color == ca && s.antagonist_type == tb &&
                            s.antagonist_color == cb;
        const bool swapped = s.candidate_type == tb && s.candidate_color == cb && s.antagonist_type == ta &&
                             s.antagonist_color == ca;
        if (direct || swapped) {
          index.row[static_cast<std::size_t>(a * index.class_count + b)] = static_cast<std::int32_t>(v);
          index.max_alert = std::max(index.max_alert, s.alert);
          break;
        }
      }
    }
  return index;
}

namespace {

// The roles of a pair of contactors: i is the candidate when a visibility row with a pair family
// reads (i, j) that way, else j; `seen` false when neither way has one.
struct PairRoles {
  std::size_t candidate, antagonist, pair;  // pair: index into the class × class tables
  bool seen;
};

PairRoles pair_roles(const VisibilityIndex2D& index, std::size_t i, std::size_t j) {
  const auto read = [&](std::size_t a, std::size_t b) {
    const auto pair =
        static_cast<std::size_t>(index.contactor_class[a] * index.class_count + index.contactor_class[b]);
    return PairRoles{a, b, pair, index.row[pair] >= 0 && index.family[pair] >= 0};
  };
  const PairRoles forward = read(i, j);
  return forward.seen ? forward : read(j, i);
}

}  // namespace

void detect_contacts_2d(const Scene2D& scene, const VisibilityIndex2D& index,
                        std::span<const Vector3d> coordinates, LargeArray<Interaction2D>& out) {
  out.clear();
  const std::size_t n = scene.contactors.size();
  if (n == 0) return;
  // The contactors' fixed data, compact (VisibilityIndex2D): the pair loops read them at every
  // pair, and reading each antagonist's radius from its 136-byte record went beyond the caches at
  // every pair of a 64k-disk layer (a sampled profile: 7% of detect_contacts_2d's time, 2% at 1k).
  const std::vector<std::int32_t>& body_of = index.contactor_body;
  const std::vector<double>& radius_of = index.contactor_radius;
  const std::vector<double>& radii = index.contactor_bounding_radius;
  const std::vector<ContactorShape2D>& shape_of = index.contactor_shape;
  // World placement of every contactor at this configuration. Kept from step to step (one set per
  // thread), as the rough pairs below.
  thread_local std::vector<Vector2d> centre;
  thread_local std::vector<Eigen::Matrix2d> orientation;
  thread_local std::vector<Vector3d> grid_centres;
  thread_local std::vector<std::uint8_t> in_grid;
  centre.resize(n);
  orientation.resize(n);
  grid_centres.resize(n);
  in_grid.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3d& q = coordinates[static_cast<std::size_t>(body_of[i])];
    orientation[i] = rotation(q.z());
    centre[i] = q.head<2>() + orientation[i] * index.contactor_shift[i];
    grid_centres[i] = Vector3d(centre[i].x(), centre[i].y(), 0.0);
    in_grid[i] = scene.bodies.visible[static_cast<std::size_t>(body_of[i])];
  }
  // Periodic images: a contactor taken one period to the right (+1) or left (-1) for one pair.
  thread_local std::vector<double> image_shift;
  image_shift.assign(n, 0.0);
  auto body_position = [&](std::size_t k) {
    const Vector3d& q = coordinates[static_cast<std::size_t>(body_of[k])];
    return Vector2d(q.x() + image_shift[k], q.y());
  };
  auto world_polygon = [&](std::size_t i, std::vector<Vector2d>& vertices) {
    const Contactor2D& c = scene.contactors[i];
    const Vector2d q = body_position(i);
    vertices.resize(static_cast<std::size_t>(c.vertex_count));
    for (std::int32_t k = 0; k < c.vertex_count; ++k)
      vertices[static_cast<std::size_t>(k)] =
          q + orientation[i] * scene.vertices[static_cast<std::size_t>(c.first_vertex + k)];
  };

  // Rough detection on the spatial grid shared with lmgc-check (spatial/multilevel_grid.hpp):
  // every pair whose bounding circles, grown by the largest alert distance, may meet.
  // Rough pairs (i < j); `shift` moves j by that many periods (periodic pairs only).
  // 12 bytes: a 64k-disk layer's list (about 190k pairs) is written and read again at every step.
  struct RoughPair {
    std::uint32_t i, j;  // contactor indices: a scene holds far fewer than 2^32 (each takes over 100 bytes)
    std::int32_t shift;
    bool operator<(const RoughPair& o) const { return std::tie(i, j, shift) < std::tie(o.i, o.j, o.shift); }
    bool operator==(const RoughPair& o) const { return i == o.i && j == o.j && shift == o.shift; }
  };
  // Kept from step to step (one per thread): grown again at every step, a 64k-disk layer's 4.6 MB
  // list was reallocated about twenty times (pairs 15.6-17.4 -> 13.9-14.5 ms per step).
  thread_local std::vector<RoughPair> rough;
  rough.clear();
  // Called by the grid, which holds only contactors of visible bodies.
  auto consider = [&](std::size_t i, std::size_t j) {
    if (body_of[i] == body_of[j]) return;
    const std::int32_t ci = index.contactor_class[i], cj = index.contactor_class[j];
    const bool ij = index.row[static_cast<std::size_t>(ci * index.class_count + cj)] >= 0;
    const bool ji = index.row[static_cast<std::size_t>(cj * index.class_count + ci)] >= 0;
    if (!ij && !ji) return;
    const double reach = radii[i] + radii[j] + index.max_alert;
    if ((centre[i] - centre[j]).squaredNorm() > reach * reach) return;
    rough.push_back(
        {static_cast<std::uint32_t>(std::min(i, j)), static_cast<std::uint32_t>(std::max(i, j)), 0});
  };
  // Kept from step to step, as `rough`: its levels keep their storage (spatial/multilevel_grid.hpp).
  thread_local spatial::MultilevelGrid grid;
  grid.build(grid_centres, radii, in_grid, index.max_alert);
  grid.for_each_candidate_pair(grid_centres, radii, index.max_alert, [&](std::size_t i, std::size_t j) {
    consider(std::min(i, j), std::max(i, j));
  });
  // Periodic in x: contactors near the right edge against images of those near the left edge
  // (docs/lmgc90-facts/rigid-2d.md §6). JONCx and points have no periodic pairs in LMGC90.
  if (scene.x_period > 0.0) {
    double widest = 0.0;
    for (double r : radii) widest = std::max(widest, r);
    const double band = 2.0 * widest + index.max_alert;
    std::vector<std::size_t> left, right;
    for (std::size_t k = 0; k < n; ++k) {
      if (!in_grid[k]) continue;  // invisible bodies have no pairs, periodic ones included
      const ContactorShape2D shape = shape_of[k];
      if (shape != ContactorShape2D::disk && shape != ContactorShape2D::polygon) continue;
      if (centre[k].x() < band) left.push_back(k);
      if (centre[k].x() > scene.x_period - band) right.push_back(k);
    }
    for (std::size_t a : right)
      for (std::size_t b : left) {
        if (a == b || body_of[a] == body_of[b]) continue;
        const std::int32_t ca = index.contactor_class[a], cb = index.contactor_class[b];
        if (index.row[static_cast<std::size_t>(ca * index.class_count + cb)] < 0 &&
            index.row[static_cast<std::size_t>(cb * index.class_count + ca)] < 0)
          continue;
        const double reach = radii[a] + radii[b] + index.max_alert;
        if ((centre[b] + Vector2d(scene.x_period, 0.0) - centre[a]).squaredNorm() > reach * reach) continue;
        // The lower index keeps its place; the other one is the image.
        if (a < b)
          rough.push_back({static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b), +1});
        else
          rough.push_back({static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(a), -1});
      }
  }
  if (scene.x_period > 0.0) {
    // The grid gives each pair once; only periodic images can repeat one.
    std::sort(rough.begin(), rough.end());
    rough.erase(std::unique(rough.begin(), rough.end()), rough.end());
  }

  // Fine detection, with the roles of the pair family.
  std::vector<Vector2d> vertices_cd, normals_cd, vertices_an, normals_an;
  auto polygon_view = [&](std::size_t k, std::vector<Vector2d>& vertices, std::vector<Vector2d>& normals) {
    world_polygon(k, vertices);
    const std::size_t m = vertices.size();
    normals.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Vector2d e = vertices[(i + 1) % m] - vertices[i];
      normals[i] = Vector2d(e.y(), -e.x()).normalized();
    }
    return PolygonView{vertices, normals, centre[k]};
  };
  // Rough pairs in the order the interactions are kept (family, candidate, antagonist; periodic
  // images of one pair by shift): fine detection then reads contactors in sequence and writes the
  // list in order, where a 64k-disk step sorted its 53 MB of interactions by permuting them at
  // random. Roles as the fine loop takes them; a pair no row sees sorts last. `order` lists the
  // pairs in that order: sorted on (family, candidate), then each candidate's few pairs by
  // (antagonist, shift) in place (std::sort of the keys was a twentieth of a 64k-disk step).
  // The grid gives the pairs by candidate (it visits the contactors in order, and a pair's
  // candidate is mostly the one it visits), so a counting sort on the family alone mostly does:
  // the one on (family, candidate) zeroed and summed a table of nine entries per contactor, 2 MB
  // at 64k disks. The pairs themselves are not moved: gathering them into a sorted copy went to
  // memory at every pair of a 64k-disk layer.
  thread_local std::vector<std::uint32_t> order;
  {
    const std::size_t family_slots = kPairFamily2DCount + 1;  // the last: pairs no row sees
    // Kept from step to step, as `rough`.
    thread_local std::vector<std::size_t> bucket;
    thread_local std::vector<std::uint32_t> antagonist, start;
    thread_local std::vector<std::uint8_t> family_of;
    bucket.resize(rough.size());
    antagonist.resize(rough.size());
    family_of.resize(rough.size());
    std::array<std::size_t, family_slots + 1> family_start{};
    for (std::size_t k = 0; k < rough.size(); ++k) {
      const PairRoles roles = pair_roles(index, rough[k].i, rough[k].j);
      const std::size_t cd = roles.candidate, an = roles.antagonist;
      const std::size_t family =
          roles.seen ? static_cast<std::size_t>(index.family[roles.pair]) : family_slots - 1;
      bucket[k] = family * n + cd;
      antagonist[k] = static_cast<std::uint32_t>(an);
      family_of[k] = static_cast<std::uint8_t>(family);
      ++family_start[family + 1];
    }
    order.resize(rough.size());
    for (std::size_t f = 1; f < family_start.size(); ++f) family_start[f] += family_start[f - 1];
    for (std::size_t k = 0; k < rough.size(); ++k)
      order[family_start[family_of[k]]++] = static_cast<std::uint32_t>(k);
    // Sorted on the family, stably: sorted on (family, candidate) too when no candidate comes
    // after a larger one of its family.
    bool by_candidate = true;
    for (std::size_t p = 1; p < order.size(); ++p) by_candidate &= bucket[order[p - 1]] <= bucket[order[p]];
    if (!by_candidate) {
      start.assign(family_slots * n + 1, 0);
      for (std::size_t k = 0; k < rough.size(); ++k) ++start[bucket[k] + 1];
      for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
      for (std::size_t k = 0; k < rough.size(); ++k)
        order[start[bucket[k]]++] = static_cast<std::uint32_t>(k);
    }
    const auto before = [&](std::uint32_t x, std::uint32_t y) {
      return std::tie(antagonist[x], rough[x].shift) < std::tie(antagonist[y], rough[y].shift);
    };
    // Insertion into the run of the same bucket (stable: grid order among equal keys).
    for (std::size_t p = 1; p < order.size(); ++p)
      for (std::size_t q = p;
           q > 0 && bucket[order[q - 1]] == bucket[order[q]] && before(order[q], order[q - 1]); --q)
        std::swap(order[q - 1], order[q]);
  }

  const auto key_of = [](const Interaction2D& c) {
    return std::pair{(std::uint64_t(c.family) << 32) | std::uint32_t(c.candidate),
                     (std::uint64_t(std::uint32_t(c.antagonist)) << 32) | std::uint32_t(c.candidate_vertex)};
  };
  bool in_order = true;
  const std::vector<Vector3d>& velocity_begin = scene.bodies.velocity_begin;
  // LMGC90's PLJCx detection (mod_PLJCx compute_contacts) leaves its contactor indices at 1 inside
  // the loop: every PLJCx interaction takes its begin velocities from the body of the first POLYG
  // and the body of the first JONCx of the case (docs/lmgc90-facts/rigid-2d.md §4.6). Only the
  // restitution laws and DISSIPATED ENERGY read them; reproduced so that both follow LMGC90.
  std::int32_t first_polygon_body = -1, first_joncx_body = -1;
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::PLJCx)])
    for (std::size_t k = 0; k < shape_of.size(); ++k) {
      if (first_polygon_body < 0 && shape_of[k] == ContactorShape2D::polygon) first_polygon_body = body_of[k];
      if (first_joncx_body < 0 && shape_of[k] == ContactorShape2D::joncx) first_joncx_body = body_of[k];
    }
  for (const std::uint32_t pair_index : order) {
    const RoughPair& rp = rough[pair_index];
    const std::size_t i = rp.i, j = rp.j;
    if (rp.shift != 0) {
      const ContactorShape2D si = shape_of[i], sj = shape_of[j];
      const bool periodic_family = (si == ContactorShape2D::disk || si == ContactorShape2D::polygon) &&
                                   (sj == ContactorShape2D::disk || sj == ContactorShape2D::polygon);
      if (!periodic_family) continue;
    }
    // Place j's periodic image for this pair, and put j back exactly afterwards: x + P - P is not
    // always x, and the next pairs of j would then see it moved by an ulp, pairs in another order
    // differently.
    struct Restore {
      std::vector<Vector2d>& centre;
      std::vector<double>& shift;
      std::size_t j;
      double x;
      ~Restore() {
        centre[j].x() = x;
        shift[j] = 0.0;
      }
    } restore{centre, image_shift, j, centre[j].x()};
    image_shift[j] = rp.shift * scene.x_period;
    centre[j].x() += image_shift[j];
    const PairRoles roles = pair_roles(index, i, j);
    if (!roles.seen) continue;
    const std::size_t pair = roles.pair, cd = roles.candidate, an = roles.antagonist;
    const std::int32_t v = index.row[pair];
    const auto family = static_cast<PairFamily2D>(index.family[pair]);
    const Visibility2D& see = scene.visibility[static_cast<std::size_t>(v)];
    std::array<PairContact2D, 2> found;
    int count = 0;
    auto joncx_of = [&](std::size_t k) {
      return Joncx{centre[k], orientation[k].col(0), scene.contactors[k].half_length,
                   scene.contactors[k].half_width};
    };
    switch (family) {
      case PairFamily2D::DKDKx:
        count = disk_disk(centre[cd], radius_of[cd], centre[an], radius_of[an], found[0]);
        break;
      case PairFamily2D::DKKDx:
        count = disk_in_hollow_disk(centre[cd], radius_of[cd], centre[an], radius_of[an], found[0]);
        break;
      case PairFamily2D::DKJCx:
        count = disk_joncx(centre[cd], radius_of[cd], joncx_of(an), found[0]);
        break;
      case PairFamily2D::DKPLx:
        count = disk_polygon(centre[cd], radius_of[cd], polygon_view(an, vertices_an, normals_an), see.alert,
                             found[0]);
        break;
      case PairFamily2D::PTPT2:
        count = point_point(centre[cd], centre[an], found[0]);
        break;
      case PairFamily2D::PLPLx:
        count = polygon_polygon(polygon_view(cd, vertices_cd, normals_cd),
                                polygon_view(an, vertices_an, normals_an), see.alert, found);
        break;
      case PairFamily2D::PLJCx:
        count = polygon_joncx(polygon_view(cd, vertices_cd, normals_cd), joncx_of(an), see.alert, found);
        break;
    }
    // Fine tests that keep a contact (docs/lmgc90-facts/rigid-2d.md §3.3).
    const bool keep_at_alert =
        family == PairFamily2D::DKDKx || family == PairFamily2D::DKKDx || family == PairFamily2D::DKJCx;
    for (int k = 0; k < count; ++k) {
      const PairContact2D& f = found[static_cast<std::size_t>(k)];
      if (keep_at_alert && f.gap > see.alert) continue;
      const std::size_t ccd = f.swapped ? an : cd, can = f.swapped ? cd : an;
      Interaction2D& c = out.emplace_back();
      c.family = family;
      c.candidate = static_cast<std::int32_t>(ccd);
      c.antagonist = static_cast<std::int32_t>(can);
      c.candidate_body = body_of[ccd];
      c.antagonist_body = body_of[can];
      c.candidate_vertex = f.candidate_vertex;
      c.antagonist_segment = f.antagonist_segment;
      c.law = see.law;
      c.visibility = v;
      c.normal = f.normal;
      const Vector2d tangent = c.tangent();
      c.point = f.point;
      c.gap_begin = f.gap;
      c.length = f.length;
      // The antagonist's image offset, in periods (negative when the candidate was the image).
      c.periodic_shift = rp.shift == 0 ? 0 : (can == j ? rp.shift : -rp.shift);
      // Levers from the body centres: add the contactor's offset on its body, except for JONCx and
      // xKSID antagonists, measured from the contactor itself in LMGC90.
      const Vector2d offset_cd = centre[ccd] - body_position(ccd);
      const bool antagonist_from_contactor =
          shape_of[can] == ContactorShape2D::joncx || shape_of[can] == ContactorShape2D::hollow_disk;
      const Vector2d offset_an =
          antagonist_from_contactor ? Vector2d::Zero() : Vector2d(centre[can] - body_position(can));
      const Vector2d lever_cd = f.candidate_lever + offset_cd;
      const Vector2d lever_an = f.antagonist_lever + offset_an;
      c.lever_candidate = Vector2d(cross_2d(lever_cd, tangent), cross_2d(lever_cd, c.normal));
      c.lever_antagonist = Vector2d(cross_2d(lever_an, tangent), cross_2d(lever_an, c.normal));
      // Local relative velocity at the beginning of the step (restitution laws), while the record is
      // at hand: a pass of its own over a large list went to memory again.
      const bool pljcx = family == PairFamily2D::PLJCx;
      const Vector3d& vc =
          velocity_begin[static_cast<std::size_t>(pljcx ? first_polygon_body : c.candidate_body)];
      const Vector3d& va =
          velocity_begin[static_cast<std::size_t>(pljcx ? first_joncx_body : c.antagonist_body)];
      const Vector3d tc(tangent.x(), tangent.y(), c.lever_candidate(0)),
          nc(c.normal.x(), c.normal.y(), c.lever_candidate(1));
      const Vector3d ta(tangent.x(), tangent.y(), c.lever_antagonist(0)),
          na(c.normal.x(), c.normal.y(), c.lever_antagonist(1));
      c.velocity_begin = Vector2d(tc.dot(vc) - ta.dot(va), nc.dot(vc) - na.dot(va));
      if (out.size() > 1 && in_order && key_of(c) < key_of(out[out.size() - 2])) in_order = false;
    }
  }
  // Written in order unless a pair's roles turned over in the fine test: sorted only then.
  if (!in_order) sort_interactions(out, key_of);
}

}  // namespace lmgc::solver
