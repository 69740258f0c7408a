// Rigid contactors that overlap at the start (disks and spheres against each other, against
// JONCx walls and PLANx boxes), for the pairs a visibility row lets interact. With the IQS laws
// LMGC90 never pushes an initial overlap out; with GAP laws it removes it in one step, as a
// burst. Candidate pairs come from uniform grids, one per power-of-two level of radius (so a few
// large disks among small ones do not make the cells large): linear in the number of contactors.
// spec: contact-laws.md §3.1 (IQS and GAP forms), datbox-inputs.md §1.4.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "validate/case_index.hpp"
#include "validate/checks.hpp"
#include "validate/rigid_layout.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

// An overlap smaller than this fraction of the smaller contactor is rounding of a generated
// packing, not an error.
constexpr double kRelativeTolerance = 1e-3;
// Pairs reported one by one; the rest are counted in one last diagnostic.
constexpr std::size_t kReportedPairs = 20;

struct Cell {
  std::int64_t x, y, z;
  friend bool operator==(const Cell&, const Cell&) = default;
};
struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

// One level of the grid: contactors whose radius is in [2^L, 2^(L+1)) times the smallest.
struct Level {
  double largest_radius = 0.0;
  double cell = 0.0;
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells;
  Cell cell_of(const Eigen::Vector3d& p) const {
    return {grid_index(p.x(), cell), grid_index(p.y(), cell), grid_index(p.z(), cell)};
  }
  // Calls f(j) for every contactor j of the level in cells meeting the box [lo, hi] (grown by
  // the level's largest radius); walks the occupied cells instead when the box covers more.
  template <class F>
  void for_each_near(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, F f) const {
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(largest_radius);
    const Cell a = cell_of(lo - grow), b = cell_of(hi + grow);
    const double span = double(b.x - a.x + 1) * double(b.y - a.y + 1) * double(b.z - a.z + 1);
    if (span > double(cells.size())) {
      for (const auto& [c, members] : cells)
        if (c.x >= a.x && c.x <= b.x && c.y >= a.y && c.y <= b.y && c.z >= a.z && c.z <= b.z)
          for (std::size_t j : members) f(j);
      return;
    }
    for (std::int64_t x = a.x; x <= b.x; ++x)
      for (std::int64_t y = a.y; y <= b.y; ++y)
        for (std::int64_t z = a.z; z <= b.z; ++z) {
          auto it = cells.find({x, y, z});
          if (it != cells.end())
            for (std::size_t j : it->second) f(j);
        }
  }
};

bool is_round(const PlacedContactor& p) {
  return p.shape == RigidShape::disk || p.shape == RigidShape::sphere;
}

bool finite(const Eigen::Vector3d& v) {
  return v.allFinite();
}

// The size a tolerance is relative to: radius, wall thickness, box thickness.
double contactor_size(const PlacedContactor& p) {
  switch (p.shape) {
    case RigidShape::disk:
    case RigidShape::sphere:
      return p.radius;
    case RigidShape::stadium:
      return p.half.y();
    case RigidShape::box:
      return p.half.minCoeff();
    case RigidShape::polygon:
      break;
  }
  return 0.0;
}

struct Overlap {
  std::size_t a, b;
  double depth;
};

}  // namespace

void check_interpenetration(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.bodies || !files.tact_behav) return;
  const RigidLayout layout = place_rigid_contactors(files);
  const auto& placed = layout.contactors;
  const SeeTable see(*files.tact_behav);

  // Levels by radius.
  double smallest = 0.0;
  for (const auto& p : placed)
    if (is_round(p) && p.radius > 0.0 && finite(p.centre) && std::isfinite(p.radius))
      smallest = smallest == 0.0 ? p.radius : std::min(smallest, p.radius);
  if (smallest == 0.0) return;
  std::vector<int> level_of(placed.size(), -1);
  std::vector<Level> levels;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& p = placed[i];
    if (!is_round(p) || !(p.radius > 0.0) || !finite(p.centre) || !std::isfinite(p.radius)) continue;
    const int level = static_cast<int>(std::min(60.0, std::floor(std::log2(p.radius / smallest))));
    level_of[i] = level;
    if (static_cast<int>(levels.size()) <= level) levels.resize(static_cast<std::size_t>(level) + 1);
    levels[static_cast<std::size_t>(level)].largest_radius =
        std::max(levels[static_cast<std::size_t>(level)].largest_radius, p.radius);
  }
  for (auto& level : levels) level.cell = 2.0 * level.largest_radius;
  for (std::size_t i = 0; i < placed.size(); ++i)
    if (level_of[i] >= 0) {
      Level& level = levels[static_cast<std::size_t>(level_of[i])];
      level.cells[level.cell_of(placed[i].centre)].push_back(i);
    }

  std::vector<Overlap> overlaps;
  auto test = [&](std::size_t i, std::size_t j) {
    const PlacedContactor& a = placed[i];
    const PlacedContactor& b = placed[j];
    if (a.body_index == b.body_index || (a.translation_driven && b.translation_driven)) return;
    if (!see.find(a.see_class, b.see_class)) return;  // never in contact
    const double depth = penetration(a, b);
    const double size = std::min(contactor_size(a), contactor_size(b));
    if (std::isfinite(depth) && depth > kRelativeTolerance * size)
      overlaps.push_back({std::min(i, j), std::max(i, j), depth});
  };
  // Disks and spheres against those of their own level (each pair once) and of larger levels.
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (level_of[i] < 0) continue;
    for (std::size_t l = static_cast<std::size_t>(level_of[i]); l < levels.size(); ++l)
      levels[l].for_each_near(placed[i].lo, placed[i].hi, [&](std::size_t j) {
        if (level_of[j] > level_of[i] || j > i) test(i, j);
      });
  }
  // Walls and boxes against every level.
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& p = placed[i];
    if ((p.shape != RigidShape::stadium && p.shape != RigidShape::box) || !finite(p.lo) || !finite(p.hi))
      continue;
    for (const Level& level : levels) level.for_each_near(p.lo, p.hi, [&](std::size_t j) { test(i, j); });
  }

  std::sort(overlaps.begin(), overlaps.end(),
            [](const Overlap& x, const Overlap& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  const std::string path = datbox_path(files, "BODIES.DAT");
  auto name = [](const PlacedContactor& p) {
    return fmt::format("{} of {} {}", p.contactor->type.value, grammar::body_type_keyword(p.body->type),
                       p.rank);
  };
  for (std::size_t k = 0; k < overlaps.size() && k < kReportedPairs; ++k) {
    const PlacedContactor& a = placed[overlaps[k].a];
    const PlacedContactor& b = placed[overlaps[k].b];
    report_related(sink, "L3012", grammar::Location{path, a.contactor->type.span},
                   fmt::format("{} and {} overlap by {:.3g} at the start ({:.3g} % of the smaller one)",
                               name(a), name(b), overlaps[k].depth,
                               100.0 * overlaps[k].depth / std::min(contactor_size(a), contactor_size(b))),
                   {{grammar::Location{path, b.contactor->type.span}, "the other contactor is defined here"}},
                   "with IQS laws LMGC90 keeps the overlap, with GAP laws it pushes the bodies apart in one "
                   "step; check the "
                   "coordinates (and DOF.INI)");
  }
  if (overlaps.size() > kReportedPairs)
    sink.report(
        "L3012", grammar::Location{path, {}},
        fmt::format("{} more pairs of contactors overlap at the start", overlaps.size() - kReportedPairs));
}

}  // namespace lmgc::validate
