#pragma once
// BULK_BEHAV.DAT: gravity and bulk behaviour laws. spec: datbox-inputs.md §2.
#include <array>
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One line of a bulk law's sub-blocks. Labels are the ones LMGC90 writes (its internal names),
// fixed by the sub-block, so two laws read from different spellings compare equal.
struct BulkLine {
  enum class Kind { option, values, field, marker };
  Kind kind = Kind::values;
  std::string label;               // option/field/marker: "elas:", "cplt:"; values: unused
  Word word;                       // option value, columns 47-59
  std::vector<std::string> labels; // values: labels of each value ("EYng=", "EPss=")
  std::vector<Real> values;        // values: at 46-59, 67-80, 88-101
  friend bool operator==(const BulkLine&, const BulkLine&) = default;
};

// A sub-block (ELAS, CPLT, THERM, PLAS, ...): its lines in file order.
struct BulkBlock {
  std::string kind;  // "ELAS", "CPLT", "THERM", "VARIA", "PLAS", "VISCO", ...
  std::vector<BulkLine> lines;
  friend bool operator==(const BulkBlock&, const BulkBlock&) = default;
};

struct BulkLaw {
  Word nickname;  // columns 2-6
  Word law_type;  // columns 9-38: RIGID, ELAS, ...
  bool density_field = false;  // 'field' instead of a value: density per Gauss point
  Real density;                // Umas, columns 46-59 [kg/m³, or kg/m² in 2D rigid runs]
  std::vector<Real> first_line_values;  // DISCRETE masses, JOINT_* first parameters (instead of Umas)
  std::vector<BulkBlock> blocks;
  friend bool operator==(const BulkLaw&, const BulkLaw&) = default;
};

struct BulkBehavFile {
  std::array<Real, 3> gravity{};  // '$gravy' values at 25-38, 46-59, 67-80
  bool has_gravity = false;
  std::vector<BulkLaw> laws;
  friend bool operator==(const BulkBehavFile&, const BulkBehavFile&) = default;
};

// Density of the law with this nickname; false when there is none (or it is a 'field').
bool bulk_density(const BulkBehavFile& file, const std::string& nickname, double& density);

}  // namespace lmgc::grammar
