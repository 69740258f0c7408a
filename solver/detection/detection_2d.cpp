#include "solver/detection/detection_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "solver/detection/pair_geometry_2d.hpp"
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

// The contactor shapes of a family: candidate, antagonist.
constexpr std::array<std::pair<ContactorShape2D, ContactorShape2D>, kRigidPairFamily2DCount> kFamilyShapes = {
    {
        {ContactorShape2D::disk, ContactorShape2D::disk},         // DKDKx
        {ContactorShape2D::disk, ContactorShape2D::hollow_disk},  // DKKDx
        {ContactorShape2D::disk, ContactorShape2D::joncx},        // DKJCx
        {ContactorShape2D::disk, ContactorShape2D::polygon},      // DKPLx
        {ContactorShape2D::point, ContactorShape2D::point},       // PTPT2
        {ContactorShape2D::polygon, ContactorShape2D::polygon},   // PLPLx
        {ContactorShape2D::polygon, ContactorShape2D::joncx},     // PLJCx
    }};

bool of_family(PairFamily2D f, ContactorShape2D shape) {
  const auto& [cd, an] = kFamilyShapes[static_cast<std::size_t>(f)];
  return shape == cd || shape == an;
}

}  // namespace

// LMGC90's compute_box of each module (rigid-2d.md §3.2): maxray over the module's contactors
// (a JONCx counts ax1 + ax2, a polygon its outer radius; big disks and polygons left out of their
// own module's), maxalert over the '$seety' rows of exactly that (candidate, antagonist) pair.
void set_rough_grids(const Scene2D& scene, VisibilityIndex2D& index) {
  const std::size_t n = scene.contactors.size();
  index.big.assign(n, 0);
  double disk_max = 0.0, polygon_max = 0.0, joncx_max = 0.0, hollow_max = 0.0;
  double disk_sum = 0.0, polygon_sum = 0.0;
  std::size_t disks = 0, polygons = 0;
  for (const Contactor2D& c : scene.contactors) switch (c.shape) {
      case ContactorShape2D::disk:
        disk_max = std::max(disk_max, c.radius);
        disk_sum += c.radius;
        ++disks;
        break;
      case ContactorShape2D::polygon:
        polygon_max = std::max(polygon_max, c.bounding_radius);
        polygon_sum += c.bounding_radius;
        ++polygons;
        break;
      case ContactorShape2D::joncx:
        joncx_max = std::max(joncx_max, c.half_length + c.half_width);
        break;
      case ContactorShape2D::hollow_disk:
        hollow_max = std::max(hollow_max, c.radius);
        break;
      case ContactorShape2D::point:
        break;
    }
  // Big contactors (mod_DKDKx big_ratio 5, mod_PLPLx 2 times the mean); the module's maxray is then
  // that of the others.
  double disk_max_small = disk_max, polygon_max_small = polygon_max;
  const auto mark_big = [&](ContactorShape2D shape, double sum, std::size_t count, double ratio,
                            double& max_small) {
    if (count == 0) return;
    const double mean = sum / static_cast<double>(count);
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) {
      const Contactor2D& c = scene.contactors[k];
      if (c.shape != shape) continue;
      const double r = shape == ContactorShape2D::disk ? c.radius : c.bounding_radius;
      if (r > ratio * mean) index.big[k] = 1, any = true;
    }
    if (!any) return;
    max_small = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (scene.contactors[k].shape == shape && !index.big[k])
        max_small =
            std::max(max_small, shape == ContactorShape2D::disk ? scene.contactors[k].radius
                                                                : scene.contactors[k].bounding_radius);
  };
  mark_big(ContactorShape2D::disk, disk_sum, disks, 5.0, disk_max_small);
  mark_big(ContactorShape2D::polygon, polygon_sum, polygons, 2.0, polygon_max_small);
  std::array<double, kRigidPairFamily2DCount> alert{};
  for (const Visibility2D& v : scene.visibility) {
    PairFamily2D f;
    if (pair_family_of(v.candidate_type, v.antagonist_type, f))
      alert[static_cast<std::size_t>(f)] = std::max(alert[static_cast<std::size_t>(f)], v.alert);
  }
  std::array<double, kRigidPairFamily2DCount> ray{};
  ray[static_cast<std::size_t>(PairFamily2D::DKDKx)] = disk_max_small;
  ray[static_cast<std::size_t>(PairFamily2D::DKKDx)] = std::max(disk_max, hollow_max);
  ray[static_cast<std::size_t>(PairFamily2D::DKJCx)] = std::max(disk_max, joncx_max);
  ray[static_cast<std::size_t>(PairFamily2D::DKPLx)] = std::max(polygon_max, disk_max);
  ray[static_cast<std::size_t>(PairFamily2D::PLPLx)] = polygon_max_small;
  ray[static_cast<std::size_t>(PairFamily2D::PLJCx)] = std::max(polygon_max, joncx_max);
  for (int f = 0; f < kRigidPairFamily2DCount; ++f) {
    if (static_cast<PairFamily2D>(f) == PairFamily2D::PTPT2) continue;  // no grid: pairs in index order
    const double box = 1.01 * (2.0 * ray[static_cast<std::size_t>(f)] + alert[static_cast<std::size_t>(f)]);
    index.box_inverse[static_cast<std::size_t>(f)] = box > 0.0 ? 1.0 / box : 0.0;
  }
}

bool pair_family_of(const std::string& cd, const std::string& an, PairFamily2D& family) {
  const grammar::ContactorPair* pair =
      grammar::find_contactor_pair(grammar::see_name(cd), grammar::see_name(an));
  if (!pair) return false;
  for (int f = 0; f < kRigidPairFamily2DCount; ++f)
    if (pair_family_name(static_cast<PairFamily2D>(f)) == pair->interaction) {
      family = static_cast<PairFamily2D>(f);
      return true;
    }
  return false;  // a pair of LMGC90's that the rigid 2D solver does not detect
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
  set_rough_grids(scene, index);
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
  // pair, and reading each antagonist's radius from its 136-byte record would go beyond the caches
  // at every pair of a large scene.
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
  // Kept from step to step (one per thread), so that a large list is not grown again, through many
  // reallocations, at every step.
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
  // Edge normals as LMGC90 has them (mod_POLYG): computed once in the body frame, d = v_i - v_(i+1),
  // n = (-d2, d1) times 1/|d|, then turned with the body; not from the turned vertices. On two
  // parallel faces the shadow-overlap detection compares normals that are opposite up to round-off:
  // only the same round-off chooses the same candidate and the same critical vertex.
  auto polygon_view = [&](std::size_t k, std::vector<Vector2d>& vertices, std::vector<Vector2d>& normals) {
    world_polygon(k, vertices);
    const Contactor2D& c = scene.contactors[k];
    const std::size_t m = vertices.size();
    normals.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Vector2d& a = scene.vertices[static_cast<std::size_t>(c.first_vertex) + i];
      const Vector2d& b = scene.vertices[static_cast<std::size_t>(c.first_vertex) + (i + 1) % m];
      const double d1 = a.x() - b.x(), d2 = a.y() - b.y();
      const double inverse = 1.0 / std::sqrt(d1 * d1 + d2 * d2);
      normals[i] = orientation[k] * Vector2d(-d2 * inverse, d1 * inverse);
    }
    return PolygonView{vertices, normals, centre[k]};
  };
  // The roles of a pair: the visibility's, except that LMGC90 pairs a big contactor as the
  // candidate of every other one (a big polygon against a big one: the lower index).
  const auto roles_of = [&](std::size_t i, std::size_t j) {
    PairRoles roles = pair_roles(index, i, j);
    if (roles.seen && index.big[roles.antagonist] && !index.big[roles.candidate]) {
      const auto family = static_cast<PairFamily2D>(index.family[roles.pair]);
      if (family == PairFamily2D::DKDKx || family == PairFamily2D::PLPLx) {
        const PairRoles turned = pair_roles(index, roles.antagonist, roles.candidate);
        if (turned.seen && turned.candidate == roles.antagonist) roles = turned;
      }
    }
    return roles;
  };

  // LMGC90's enumeration of each family's rough pairs (rigid-2d.md §3.2): on the family's box grid
  // (its origin at this configuration's lowest contactor centres, x at 0 when periodic), boxes
  // column by column (i1 outer; PLPLx row by row), a box's candidates by index, for each the 3 x 3
  // neighbouring boxes in the same nesting and their antagonists by index; then the big
  // contactors' pairs; then the periodic ones. `order` lists the rough pairs that way; the fine
  // detection below keeps it, and so does the interaction list.
  struct FamilyGrid {
    double left = 0.0, down = 0.0, inverse = 0.0;
    bool rows_first = false;  // PLPLx: i2 outer
  };
  std::array<FamilyGrid, kRigidPairFamily2DCount> grids{};
  for (int f = 0; f < kRigidPairFamily2DCount; ++f) {
    const auto family = static_cast<PairFamily2D>(f);
    if (!scene.plan.families[static_cast<std::size_t>(f)] || family == PairFamily2D::PTPT2) continue;
    FamilyGrid& g = grids[static_cast<std::size_t>(f)];
    g.inverse = index.box_inverse[static_cast<std::size_t>(f)];
    g.rows_first = family == PairFamily2D::PLPLx;
    // DKKDx reads every contactor, visible or not; the others the visible ones, big ones left out.
    const bool all = family == PairFamily2D::DKKDx;
    const bool skip_big = family == PairFamily2D::DKDKx || family == PairFamily2D::PLPLx;
    g.left = g.down = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
      if (!of_family(family, shape_of[k]) || (!all && !in_grid[k]) || (skip_big && index.big[k])) continue;
      g.left = std::min(g.left, centre[k].x());
      g.down = std::min(g.down, centre[k].y());
    }
    if (scene.x_period > 0.0 &&
        (family == PairFamily2D::DKDKx || family == PairFamily2D::DKPLx || family == PairFamily2D::PLPLx))
      g.left = 0.0;
  }
  // Box indices as LMGC90 computes them: 1 + int((x - Bleft) / Lbox), by the inverse.
  const auto box_of = [&](const FamilyGrid& g, std::size_t k) {
    return std::pair<std::int64_t, std::int64_t>{
        1 + static_cast<std::int64_t>((centre[k].x() - g.left) * g.inverse),
        1 + static_cast<std::int64_t>((centre[k].y() - g.down) * g.inverse)};
  };
  // The rank of each candidate in its family's enumeration (boxes in the family's nesting, then
  // index), by a counting sort on the box when the grid is not much larger than its contactors.
  thread_local std::array<std::vector<std::uint32_t>, kRigidPairFamily2DCount> candidate_rank;
  for (int f = 0; f < kRigidPairFamily2DCount; ++f) {
    const auto family = static_cast<PairFamily2D>(f);
    std::vector<std::uint32_t>& rank = candidate_rank[static_cast<std::size_t>(f)];
    if (!scene.plan.families[static_cast<std::size_t>(f)]) {
      rank.clear();
      continue;
    }
    rank.assign(n, std::numeric_limits<std::uint32_t>::max());
    const ContactorShape2D shape = kFamilyShapes[static_cast<std::size_t>(f)].first;
    if (family == PairFamily2D::PTPT2) {
      std::uint32_t next = 0;
      for (std::size_t k = 0; k < n; ++k)
        if (shape_of[k] == shape) rank[k] = next++;
      continue;
    }
    const FamilyGrid& g = grids[static_cast<std::size_t>(f)];
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    std::int64_t columns = 1, rows = 1;
    for (std::size_t k = 0; k < n; ++k) {
      if (shape_of[k] != shape || index.big[k]) continue;
      const auto [b1, b2] = box_of(g, k);
      columns = std::max(columns, b1);
      rows = std::max(rows, b2);
      keys.push_back({0, static_cast<std::uint32_t>(k)});
    }
    const auto linear = [&](std::size_t k) {
      const auto [b1, b2] = box_of(g, k);
      const std::int64_t c = std::clamp<std::int64_t>(b1, 0, columns),
                         r = std::clamp<std::int64_t>(b2, 0, rows);
      return static_cast<std::uint64_t>(g.rows_first ? r * (columns + 1) + c : c * (rows + 1) + r);
    };
    for (auto& key : keys) key.first = linear(key.second);
    const std::uint64_t boxes = static_cast<std::uint64_t>((columns + 1) * (rows + 1));
    if (boxes <= 4 * keys.size() + 1024) {
      thread_local std::vector<std::uint32_t> start;
      start.assign(boxes + 1, 0);
      for (const auto& key : keys) ++start[key.first + 1];
      for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
      for (const auto& key : keys) rank[key.second] = start[key.first]++;  // keys come by index: stable
    } else {
      std::sort(keys.begin(), keys.end());
      for (std::size_t p = 0; p < keys.size(); ++p) rank[keys[p].second] = static_cast<std::uint32_t>(p);
    }
  }
  thread_local std::vector<std::uint32_t> order;
  {
    // Grid pairs: counted into (family, candidate rank) buckets, then each bucket's few pairs by
    // (neighbouring box, antagonist). Big contactors' and periodic pairs (few) follow their family's
    // grid pairs, sorted on their own keys.
    const std::size_t family_slots = kRigidPairFamily2DCount + 1;  // the last: pairs no row sees
    thread_local std::vector<std::size_t> bucket;
    thread_local std::vector<std::uint64_t> secondary;
    thread_local std::vector<std::uint32_t> start;
    struct Extra {
      std::array<std::int64_t, 7> key;
      std::uint32_t pair;
      bool operator<(const Extra& o) const { return std::tie(key, pair) < std::tie(o.key, o.pair); }
    };
    std::array<std::vector<Extra>, kRigidPairFamily2DCount + 1> extra;
    bucket.resize(rough.size());
    secondary.resize(rough.size());
    constexpr std::size_t kNoBucket = static_cast<std::size_t>(-1);
    for (std::size_t k = 0; k < rough.size(); ++k) {
      const RoughPair& rp = rough[k];
      const PairRoles roles = roles_of(rp.i, rp.j);
      const std::size_t cd = roles.candidate, an = roles.antagonist;
      if (!roles.seen) {
        bucket[k] = kNoBucket;
        extra[kRigidPairFamily2DCount].push_back(
            {{0, 0, 0, 0, 0, static_cast<std::int64_t>(rp.i), rp.j}, static_cast<std::uint32_t>(k)});
        continue;
      }
      const std::size_t f = static_cast<std::size_t>(index.family[roles.pair]);
      const auto family = static_cast<PairFamily2D>(f);
      const FamilyGrid& g = grids[f];
      if (rp.shift != 0) {
        // Periodic: the contactor in the last box columns against one in the first columns, moved
        // by a period (the one whose image the pair holds); DKPLx: disks there first, then polygons.
        const std::size_t right = rp.shift > 0 ? rp.i : rp.j, left = rp.shift > 0 ? rp.j : rp.i;
        const auto [r1, r2] = box_of(g, right);
        const auto [l1, l2] = box_of(g, left);
        const std::int64_t part = family == PairFamily2D::DKPLx && shape_of[right] != ContactorShape2D::disk;
        bucket[k] = kNoBucket;
        extra[f].push_back(
            {{2 + part, r1, r2, static_cast<std::int64_t>(right), l1, l2, static_cast<std::int64_t>(left)},
             static_cast<std::uint32_t>(k)});
        continue;
      }
      if (index.big[cd] || index.big[an] || family == PairFamily2D::PTPT2) {
        bucket[k] = kNoBucket;
        extra[f].push_back({{family == PairFamily2D::PTPT2 ? 0 : 1, static_cast<std::int64_t>(cd),
                             static_cast<std::int64_t>(an), 0, 0, 0, 0},
                            static_cast<std::uint32_t>(k)});
        continue;
      }
      const auto [c1, c2] = box_of(g, cd);
      const auto [a1, a2] = box_of(g, an);
      const std::int64_t d1 = a1 - c1 + 1, d2 = a2 - c2 + 1;
      // A pair outside the 3 x 3 boxes is one LMGC90's grid does not enumerate: its fine test
      // rejects it too; it comes last.
      const std::uint64_t neighbour =
          d1 < 0 || d1 > 2 || d2 < 0 || d2 > 2
              ? 9
              : static_cast<std::uint64_t>(g.rows_first ? d2 * 3 + d1 : d1 * 3 + d2);
      bucket[k] = f * n + candidate_rank[f][cd];
      secondary[k] = (neighbour << 32) | static_cast<std::uint64_t>(an);
    }
    start.assign(kRigidPairFamily2DCount * n + 1, 0);
    std::size_t grid_pairs = 0;
    for (std::size_t k = 0; k < rough.size(); ++k)
      if (bucket[k] != kNoBucket) ++start[bucket[k] + 1], ++grid_pairs;
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    thread_local std::vector<std::uint32_t> grid_order;
    grid_order.resize(grid_pairs);
    for (std::size_t k = 0; k < rough.size(); ++k)
      if (bucket[k] != kNoBucket) grid_order[start[bucket[k]]++] = static_cast<std::uint32_t>(k);
    // Insertion into the run of the same bucket.
    for (std::size_t p = 1; p < grid_order.size(); ++p)
      for (std::size_t q = p; q > 0 && bucket[grid_order[q - 1]] == bucket[grid_order[q]] &&
                              secondary[grid_order[q]] < secondary[grid_order[q - 1]];
           --q)
        std::swap(grid_order[q - 1], grid_order[q]);
    order.clear();
    order.reserve(rough.size());
    std::size_t p = 0;
    for (std::size_t f = 0; f < family_slots; ++f) {
      for (; p < grid_order.size() && bucket[grid_order[p]] / n == f; ++p) order.push_back(grid_order[p]);
      std::sort(extra[f].begin(), extra[f].end());
      for (const Extra& e : extra[f]) order.push_back(e.pair);
    }
  }

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
    const PairRoles roles = roles_of(i, j);
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
        // mod_PLPLx compute_contact's pre-test on the outer radii, with the pair's alert distance.
        if ((centre[cd] - centre[an]).squaredNorm() >=
            (radii[cd] + radii[an] + see.alert) * (radii[cd] + radii[an] + see.alert))
          break;
        count = polygon_polygon(polygon_view(cd, vertices_cd, normals_cd),
                                polygon_view(an, vertices_an, normals_an), see.alert, found);
        break;
      case PairFamily2D::PLJCx:
        count = polygon_joncx(polygon_view(cd, vertices_cd, normals_cd), joncx_of(an), see.alert, found);
        break;
      case PairFamily2D::CLALp:
      case PairFamily2D::CLJCx:
      case PairFamily2D::P2P2L:
      case PairFamily2D::PLALp:
      case PairFamily2D::DKALp:
      case PairFamily2D::DKDKL:
        break;  // a side on a mesh: mesh_detection_2d.hpp
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
    }
  }
}

}  // namespace lmgc::solver
