#pragma once
// The interaction modules of LMGC90 and how each writes its Vloc_Rloc block: title line, data-line
// format, the labelled vector lines in their order, the layout of internal variables. One table,
// used by the parser, the writer and the solver's state writer.
// docs/lmgc90-facts/state-and-outputs.md §1.4.1 (2D), §1.4.2 (3D); docs/lmgc90-facts/rigid-2d.md §3.4.
#include <span>
#include <string_view>
#include <vector>

namespace lmgc::grammar {

// How a module writes the internal variables of a law that has some (state-and-outputs.md §1.4.4):
// DKDKx and DKJCx (normal mode) wrap them 6 or 5 per line without a '#' comment line; every
// other module (and DKDKx/DKJCx in "xxl" mode) writes the '#' line of names, then all values on
// one line.
enum class InternalLayout2D { per_line_6, per_line_5, one_line_with_comment };

struct VectorLineKind {
  std::string_view labels[3];
  int count;  // 1 or 3
};

struct InteractionKind {
  std::string_view type;   // '$icdan' module name (columns 9-13)
  int dimension;           // 2 or 3
  std::string_view title;  // title line exactly as LMGC90 writes it (A-format width applied)
  // Fortran format of the data line, as items separated by blanks: "1X", "A5", "I5", "I10", "9X".
  std::string_view data_format;
  std::span<const VectorLineKind> vectors;  // in writing order
  InternalLayout2D internals;
  bool xxl;         // the "xxl" variant (more than 99999 verlet contacts): wider number fields
  int icdan_width;  // width of the interaction number on the '$icdan' line (I7, I10 in 2D xxl)
};

// One item of a data-line format.
struct DataItem {
  char kind;  // 'X' (blanks), 'A' (word) or 'I' (integer)
  int width;
};

std::span<const InteractionKind> interaction_catalogue();

// The normal (not xxl) layout of a module, or nullptr for an unknown module name.
const InteractionKind* find_interaction_kind(std::string_view type);
// The layout of a module in the given mode; falls back to the normal layout when the module has
// no xxl variant.
const InteractionKind* find_interaction_kind(std::string_view type, bool xxl);

// The items of a data-line format, in order.
std::vector<DataItem> data_items(std::string_view data_format);

}  // namespace lmgc::grammar
