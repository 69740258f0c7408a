#pragma once
// The closed list of bulk behaviour law types and of their sub-blocks: ONE table, walked by
// both the parser and the writer. docs/lmgc90-facts/datbox-inputs.md §2 (table of law types, sub-blocks,
// echo formats).
//
// A law is its first line (Umas, or values for DISCRETE / JOINT_*) and an ordered list of
// sub-blocks; a sub-block is an ordered list of steps (marker line, option line, value lines),
// where an option's value chooses the value lines that follow it.
#include <array>
#include <span>
#include <string_view>

namespace lmgc::grammar {

enum class BulkBlockKind {
  elas,
  cplt,
  therm,
  varia,
  plas,
  visco,
  rigid_therm,
  rigid_elec,
  ws,
  umat,
  biot,
  discrete,
  joint_mc,
  joint_fczm
};

// One line of up to 3 values at 46-59, 67-80, 88-101 (read as (k(7X,D14.7)) from column 39).
struct BulkValueLayout {
  std::array<std::string_view, 3> labels{};  // the labels LMGC90 writes (its internal names)
  int count = 0;                             // values on the line
  bool field_allowed = false;                // 'field' at 46-50 instead of the values
  bool by_dimension = false;                 // DISCRETE: 2 values in 2D, 3 in 3D
};

// One accepted value of an option line, with the value lines that follow it.
struct BulkOptionCase {
  std::string_view value;                    // as read, trailing blanks removed
  std::span<const BulkValueLayout> lines{};  // value lines after the option line
  bool ends_block = false;                   // PLAS 'crit: none': the rest of the block is absent
  bool supported = true;                     // false: LMGC90 reads the name, then stops (not implemented)
};

// How an option line is written (datbox-inputs.md §2 "Echo").
enum class BulkOptionStyle {
  labelled13,  // (38X,2X,A5,1x,A13): '                                        ani_: isotropic    '
  labelled5,   // (38X,2X,A5,1X,A5):  '                                        WSlw= LMM05'
  colon3,      // (40X,A3,A1):        '                                        iso:'
};

enum class BulkStepKind {
  marker,             // a checked word at 41-44 ('cplt', 'ther', 'varf', 'cpl_'); written 'cplt:'
  option,             // an option word; its case chooses the value lines that follow
  values,             // fixed value lines
  anisotropy_values,  // value lines chosen by the anisotropy of the law's ELAS block (CPLT)
  file_name,          // UMAT: a file name read list-directed from the whole line
};

struct BulkStep {
  BulkStepKind kind = BulkStepKind::values;
  std::string_view label{};    // marker/option: label LMGC90 writes ('cplt:', 'ani_:', 'WSlw=')
  std::string_view checked{};  // text LMGC90 checks from column 41 (fatal otherwise); empty: none
  int first = 0;               // option: columns of the value
  int last = 0;
  BulkOptionStyle style = BulkOptionStyle::labelled13;
  std::span<const BulkOptionCase> cases{};   // option, anisotropy_values
  std::span<const BulkValueLayout> lines{};  // values
};

struct BulkBlockInfo {
  BulkBlockKind kind;
  std::string_view name;  // ELAS, CPLT, ... (as datbox-inputs.md §2 names them)
  std::span<const BulkStep> steps;
  bool own_blank_line;  // the sub-block writer ends with its own ' ' line (blank-line quirk)
};

enum class BulkFirstLine { umas, values };

struct BulkLawKind {
  std::string_view law_type;  // columns 9-38
  BulkFirstLine first_line;
  BulkValueLayout first_values;  // BulkFirstLine::values: the values after the law type
  std::span<const BulkBlockKind> blocks;
};

std::span<const BulkLawKind> bulk_law_catalogue();
const BulkLawKind* find_bulk_law_kind(std::string_view law_type);
const BulkBlockInfo& bulk_block_info(BulkBlockKind kind);

// The law type LMGC90 gives a law whose type it does not know (its echo is '$behav  lawty' and a
// blank line).
inline constexpr std::string_view kUnknownBulkLawType = "unknown";

}  // namespace lmgc::grammar
