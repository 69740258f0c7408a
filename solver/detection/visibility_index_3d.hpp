#pragma once
// Which '$seety' row applies to an ordered pair of 3D contactors, looked up in a table built once per
// scene: the contactors grouped by (type as '$seety' rows name it, colour), rows in a class × class
// table (string comparisons per pair and per step were a tenth of large steps).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

struct Scene3D;

struct VisibilityIndex3D {
  std::vector<std::int32_t> class_of;  // (contactors) class of each contactor
  std::size_t class_count = 0;
  // (class_count²) row for (candidate class, antagonist class), -1 when no row reads the pair.
  std::vector<std::int32_t> row;
  // What the index was built for (rebuilt when the scene's contactors or rows change in number).
  std::size_t contactors = 0, rows = 0;
  bool built = false;

  std::int32_t row_of(std::size_t candidate, std::size_t antagonist) const {
    return row[static_cast<std::size_t>(class_of[candidate]) * class_count +
               static_cast<std::size_t>(class_of[antagonist])];
  }
};

// Builds `index` for `scene` unless it was built for a scene of its size.
void update_visibility_index_3d(const Scene3D& scene, VisibilityIndex3D& index);

}  // namespace lmgc::solver
