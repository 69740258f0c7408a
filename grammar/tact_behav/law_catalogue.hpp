#pragma once
// The catalogue of contact-law keywords of TACT_BEHAV.DAT: one row per LMGC90 law id, with the
// parameter names LMGC90 prints, where the reader takes each value from, where the writer puts
// it, and the law's internal variables (written later in Vloc_Rloc files).
// docs/lmgc90-facts/contact-laws.md §0 (catalogue), §1.1 (cards); state-and-outputs.md §1.4.4 (internals).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lmgc::grammar {

// One value field of a law card: `line` = 0 for the law line itself, 1.. for the following
// significant lines; `count` = 1 (value at columns 46-59: LMGC90's read_single / write_single)
// or 2 (values at 46-59 and 67-80: read_double / write_double); `first` = 0-based index of the
// first parameter stored from (or printed into) the field(s).
struct LawField {
  std::uint8_t line = 0;
  std::uint8_t count = 1;
  std::uint8_t first = 0;
};

// One internal-variable name as LMGC90 places it in its internal comment line: `column` is
// the 1-based column of the comment line where `text` starts (text kept with its blanks).
struct InternalSlot {
  std::uint16_t column = 0;
  std::string_view text;
};

// Internal variables of a law for one dimension. count = -1: LMGC90 stops for this law in that
// dimension ("Unsupported nbDIME"). count may exceed slots.size() (unnamed internals).
struct InternalLayout {
  int count = 0;
  std::span<const InternalSlot> slots;
};

// The '#' line of a Vloc_Rloc file naming a law's internal variables: each name at its column,
// 285 characters (empty when the law has none).
std::string internal_variables_comment(const InternalLayout& layout);

struct LawKind {
  int id = 0;                                    // LMGC90's integer law id (mod_parameters order, 1..94)
  std::string_view keyword;                      // as read from columns 9-38, case-sensitive
  std::span<const std::string_view> parameters;  // 5-character names LMGC90 prints, in storage order
  std::span<const LawField> reads;               // how the reader takes the values (quirks included)
  std::span<const LawField> writes;              // how the TACT_BEHAV.OUT writer prints them
  InternalLayout internals_2d;
  InternalLayout internals_3d;
  bool readable = true;    // false: an integer id whose keyword the reader rejects
  std::string_view quirk;  // non-empty where LMGC90's reader/writer does something surprising

  // Number of physical lines the reader consumes for this law (law line included).
  int read_line_count() const;
  // Values the reader takes from physical line `line` (0 = law line): 1, 2, or more for the
  // quirks that read the same field twice.
  int values_on_read_line(int line) const;
};

// The values the reader gets back when it reads a card printed by the writer from `values`:
// equal to `values` except for the quirk laws whose reader takes some fields twice (PERIO_DOF,
// ELASTIC_WET_NT, LJ_POTENTIAL). A value the writer did not print reads as 0.
std::vector<double> values_read_back_from_echo(const LawKind& kind, std::span<const double> values);

// All 94 rows, ordered by LMGC90 id.
std::span<const LawKind> law_catalogue();

// The row for a keyword as read from columns 9-38 (trailing blanks removed); nullptr when
// LMGC90 has no such law id. Rows with readable == false are returned too: the caller decides.
const LawKind* find_law_kind(std::string_view keyword);

// Keywords of LMGC90's 2012 user's guide that the current reader rejects, with the keyword
// that replaced them (empty when there is none). docs/lmgc90-facts/contact-laws.md §0 "Guide-only names".
struct GuideOnlyLawName {
  std::string_view guide_name;
  std::string_view current_keyword;
};
std::span<const GuideOnlyLawName> guide_only_law_names();

// The hint for an unknown law keyword: the guide replacement, the readable keyword that differs
// only by case, or the single readable keyword within edit distance 2; empty when none applies.
std::string law_keyword_hint(std::string_view keyword);

}  // namespace lmgc::grammar
