// Rigid contactors that overlap at the start (disks and spheres against each other, against
// JONCx walls and PLANx boxes), for the pairs a visibility row lets interact. With the IQS laws
// LMGC90 never pushes an initial overlap out; with GAP laws it removes it in one step, as a
// burst. Candidate pairs come from the solver's own spatial grid (spatial/multilevel_grid.hpp:
// uniform grids, one per power-of-two level of radius): linear in the number of contactors.
// docs/lmgc90-facts/contact-laws.md §3.1 (IQS and GAP forms), datbox-inputs.md §1.4.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "spatial/multilevel_grid.hpp"
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

  // Disks and spheres in the grid; walls and boxes query it with their boxes.
  std::vector<Eigen::Vector3d> centres(placed.size());
  std::vector<double> radii(placed.size(), 0.0);
  std::vector<std::uint8_t> in_grid(placed.size(), 0);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& p = placed[i];
    centres[i] = p.centre;
    if (is_round(p) && p.radius > 0.0 && finite(p.centre) && std::isfinite(p.radius)) {
      radii[i] = p.radius;
      in_grid[i] = 1;
    }
  }
  spatial::MultilevelGrid grid;
  grid.build(centres, radii, in_grid, 0.0);

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
  // Disks and spheres against each other (each pair once).
  grid.for_each_candidate_pair(centres, radii, 0.0, test);
  // Walls and boxes against every level.
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& p = placed[i];
    if ((p.shape != RigidShape::stadium && p.shape != RigidShape::box) || !finite(p.lo) || !finite(p.hi))
      continue;
    for (std::size_t level = 0; level < grid.level_count(); ++level)
      grid.for_each_near(level, p.lo, p.hi, [&](std::size_t j) { test(i, j); });
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
