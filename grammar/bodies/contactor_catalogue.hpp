#pragma once
// The closed list of contactor kinds of BODIES.DAT: one row per keyword with the body types
// that accept it and its card layout. Parser and writer both read this table.
// docs/lmgc90-facts/datbox-inputs.md §1.4 (rigid), §1.5 (MAILx), §10 (guide vs source).
#include <array>
#include <span>
#include <string_view>

#include "grammar/bodies/ast.hpp"

namespace lmgc::grammar {

enum class ContactorLayout {
  values,                 // reals on the first line at 35-48, 56-69, 77-90 (DISKx, JONCx, SPHER, ...)
  values_offset,          // + next line: offset of the contactor centre (DISKb, SPHEb)
  values_frame,           // + optional 'localframe' block of 5 lines (CYLND, PLANx)
  polygon,                // 'nb_vertex=' count at 40-46, then one vertex per line (POLYG)
  polyhedron,             // counts at 40-47 / 60-67, vertex lines, face lines (POLYR)
  polyhedron_patches,     // patch count, then per patch counts, vertices, faces (POLYF)
  deformable_polyhedron,  // counts, then face lines of node ranks (POLYD)
  node_point,             // noda nodb apab [bdyr brpm] (CLxxx, PT2DL, PT2TL, DISKL)
  node_polyline,          // noda nodb, then '+ALpxx' lines with the next segments (ALpxx)
  node_patch,             // 3, 4, 6 or 8 node ranks, then '+' lines with further faces (CSpxx, ASpxx)
};

// Bit mask of the body types that accept a contactor.
inline constexpr unsigned kOnRbdy2 = 1u << static_cast<unsigned>(BodyType::rbdy2);
inline constexpr unsigned kOnRbdy3 = 1u << static_cast<unsigned>(BodyType::rbdy3);
inline constexpr unsigned kOnMailx = 1u << static_cast<unsigned>(BodyType::mailx);

struct ContactorKind {
  std::string_view keyword;
  unsigned bodies;  // kOnRbdy2 | kOnRbdy3 | kOnMailx
  ContactorLayout layout;
  std::array<std::string_view, 5> labels;  // labels of the first-line values, as LMGC90 writes them
  int value_count;                         // reals on the first line
  std::array<std::string_view, 3> offset_labels;
  int offset_count;             // reals on the offset line (values_offset)
  int patch_nodes;              // node_patch: nodes per face given by the name (0 = detected from labels)
  int dimension;                // 2 or 3 (vertex components, offsets)
  std::string_view guide_only;  // non-empty: a spelling LMGC90's reader rejects; the reason
};

std::span<const ContactorKind> contactor_catalogue();
const ContactorKind* find_contactor_kind(std::string_view keyword);

// Element types of MAILx bodies and their node counts (datbox-inputs.md §1.5).
struct ElementKind {
  std::string_view keyword;
  int node_count;
};
std::span<const ElementKind> element_catalogue();
const ElementKind* find_element_kind(std::string_view keyword);

}  // namespace lmgc::grammar
