#pragma once
// The closed list of bulk behaviour law types: each with the sub-blocks LMGC90's reader goes
// through, in order (datbox-inputs.md §2 table). Parser and writer walk the same list.
#include <span>
#include <string_view>

namespace lmgc::grammar {

enum class BulkFirstLine { umas, values3, joint3 };

struct BulkLawKind {
  std::string_view law_type;
  BulkFirstLine first_line;
  std::span<const std::string_view> blocks;  // "ELAS", "CPLT", "THERM", "VARIA", "PLAS", "VISCO",
                                             // "RIGID_THERM", "RIGID_ELEC", "WS", "UMAT", "BIOT",
                                             // "DISCRETE", "JOINT"
  int extra;  // JOINT_*: number of parameters after the first 3
};

std::span<const BulkLawKind> bulk_law_catalogue();
const BulkLawKind* find_bulk_law_kind(std::string_view law_type);

}  // namespace lmgc::grammar
