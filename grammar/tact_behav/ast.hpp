#pragma once
// TACT_BEHAV.DAT: contact laws (`$behav` cards) and the visibility table (`$seety` blocks).
// docs/lmgc90-facts/contact-laws.md §1.1-1.2, datbox-inputs.md §3.
#include <optional>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One `$behav` card: nickname (columns 2-6 of the law line), keyword (columns 9-38) and the
// values in the catalogue's parameter order (law_catalogue.hpp), as LMGC90 reads them.
struct TactLaw {
  Word nickname;
  Word keyword;
  std::vector<Real> parameters;
  bool operator==(const TactLaw&) const = default;
};

// One `$seety` block: the data line (1X,A5,2X,A5,2X,A5,2X,A5,2X,A5,2X,A5,2X,A5,5X,1X,D14.7)
// and the optional `+` global alert line (value at columns 55-68).
struct SeeEntry {
  Word candidate_body;               // cols 2-6 (RBDY2, RBDY3, MAILx; obsolete files: DISKx ...)
  Word candidate_contactor;          // cols 9-13
  Word candidate_colour;             // cols 16-20
  Word law_nickname;                 // cols 23-27
  Word antagonist_body;              // cols 30-34
  Word antagonist_contactor;         // cols 37-41
  Word antagonist_colour;            // cols 44-48
  Real alert;                        // cols 55-68
  std::optional<Real> global_alert;  // `+` line, cols 55-68
  bool operator==(const SeeEntry&) const = default;
};

// Laws in reading order (the order of LMGC90's law numbers); see entries in file order
// (LMGC90's own order after merging and sorting is lmgc90_see_order(), see_table.hpp).
struct TactBehavFile {
  std::vector<TactLaw> laws;
  std::vector<SeeEntry> sees;
  bool operator==(const TactBehavFile&) const = default;
};

}  // namespace lmgc::grammar
