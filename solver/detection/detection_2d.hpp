#pragma once
// Contact detection of a rigid 2D scene: rough detection on a uniform grid of bounding circles
// (linear in the number of contactors), then fine detection per pair family.
// docs/lmgc90-facts/numerics.md §5.1-5.3.
#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

#include "solver/model/large_array.hpp"
#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

// Per-scene lookup built once: which '$seety' row applies to a pair of contactors, and the
// contactors' fixed data in the layout detection reads.
struct VisibilityIndex2D {
  std::vector<std::int32_t> contactor_class;  // (contactors) class = distinct (type, colour)
  std::int32_t class_count = 0;
  // (class_count²) visibility row for (candidate class, antagonist class), -1 when not visible;
  // the roles are already resolved: entry (a, b) means a is the candidate.
  std::vector<std::int32_t> row;
  // (class_count²) pair family of (candidate class, antagonist class), -1 when LMGC90 has none.
  std::vector<std::int8_t> family;
  double max_alert = 0.0;
  // The contactors' fixed data that detection reads at every step, compact (by contactor), so that
  // detection does not stream the 136-byte Contactor2D records for these few fields.
  std::vector<std::int32_t> contactor_body;
  std::vector<ContactorShape2D> contactor_shape;
  std::vector<double> contactor_radius, contactor_bounding_radius;
  std::vector<Eigen::Vector2d> contactor_shift;
  // LMGC90's rough detection grid of each pair family (mod_XXXXx compute_box, fixed at the first
  // detection): 1 / Lbox with Lbox = 1.01 (2 maxray + maxalert); 0 for a family without one.
  std::array<double, kRigidPairFamily2DCount> box_inverse{};
  // (contactors) LMGC90's "big" contactors, kept out of the grid and tested against every other
  // one after the grid's pairs, as the candidate: DISKx of radius above 5 times the mean radius
  // (DKDKx), POLYG of outer radius above twice the mean (PLPLx).
  std::vector<std::uint8_t> big;
};

VisibilityIndex2D build_visibility_index(const Scene2D& scene);
// Its box_inverse and big (called by build_visibility_index).
void set_rough_grids(const Scene2D& scene, VisibilityIndex2D& index);

// The family of a (candidate type, antagonist type) pair, or false when LMGC90 has none.
bool pair_family_of(const std::string& candidate_type, const std::string& antagonist_type,
                    PairFamily2D& family);

// Detects the interactions at `coordinates` (per body: x, y, θ in the world frame), with their
// local relative velocity at the bodies' velocity_begin. The result is in LMGC90's order, the
// order of its NLGS sweep: family by family (PairFamily2D's order), in each family the pairs as
// its rough detection enumerates them on its box grid (grid pairs, then big contactors', then
// periodic ones; docs/lmgc90-facts/rigid-2d.md §3.2), the one or two points of a pair as its fine
// detection finds them.
void detect_contacts_2d(const Scene2D& scene, const VisibilityIndex2D& index,
                        std::span<const Eigen::Vector3d> coordinates, LargeArray<Interaction2D>& out);

}  // namespace lmgc::solver
