#pragma once
// The interaction modules of LMGC90 and how each writes its Vloc_Rloc block: title line, data-line
// format, the labelled vector lines in their order, the layout of internal variables.
// spec: state-and-outputs.md §1.4.1 (2D), §1.4.2 (3D); docs/lmgc90-facts/rigid-2d.md §3.4.
#include <span>
#include <string_view>

namespace lmgc::grammar {

enum class InternalLayout2D { per_line_6, per_line_5, one_line_with_comment };

struct VectorLineKind {
  std::string_view labels[3];
  int count;  // 1 or 3
};

struct InteractionKind {
  std::string_view type;    // '$icdan' module name
  int dimension;            // 2 or 3
  std::string_view title;   // title line as LMGC90 writes it
  // Fortran format of the data line, as items separated by blanks: "1X", "A5", "I5" (and "nX").
  std::string_view data_format;
  std::span<const VectorLineKind> vectors;  // in writing order
  InternalLayout2D internals;
};

std::span<const InteractionKind> interaction_catalogue();
const InteractionKind* find_interaction_kind(std::string_view type);

}  // namespace lmgc::grammar
