#pragma once
// BULK_BEHAV.DAT: gravity and bulk behaviour laws. docs/lmgc90-facts/datbox-inputs.md §2.
// The AST holds what LMGC90 reads (values and option words); the labels LMGC90 writes come from
// the catalogue (grammar/bulk_behav/catalogue.hpp), so the AST never repeats them.
#include <array>
#include <string>
#include <vector>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One value line of a sub-block: values at 46-59, 67-80, 88-101, or the word 'field' at 46-50
// (the value is given per Gauss point by the model).
struct BulkValues {
  bool field = false;
  std::vector<Real> values;  // empty when `field`
  friend bool operator==(const BulkValues&, const BulkValues&) = default;
};

// A sub-block (ELAS, CPLT, PLAS, ...), walked by its catalogue steps.
struct BulkBlock {
  BulkBlockKind kind = BulkBlockKind::elas;
  std::vector<Word> options;      // option words in step order ('standard', 'isotropic', 'Swift', ...)
  std::vector<BulkValues> lines;  // value lines in file order
  Word file_name;                 // UMAT: user material file, relative to DATBOX/
  friend bool operator==(const BulkBlock&, const BulkBlock&) = default;
};

struct BulkLaw {
  Word nickname;                        // columns 2-6 (blank for an unknown law type, as LMGC90 keeps it)
  Word law_type;                        // columns 9-38: RIGID, ELAS, ... or 'unknown'
  bool density_field = false;           // 'field' instead of a value: density per Gauss point
  Real density;                         // Umas, columns 46-59 [kg/m³, or kg/m² in 2D rigid runs]
  std::vector<Real> first_line_values;  // DISCRETE masses (2 in 2D, 3 in 3D), JOINT_* kt knc knt
  std::vector<BulkBlock> blocks;        // in catalogue order
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
