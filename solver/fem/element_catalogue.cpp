#include "solver/fem/element_catalogue.hpp"

#include <array>

namespace lmgc::solver::fem {

namespace {

// LMGC90's Gauss rules per element: the stiffness rule's points are the GPV points
// (docs/lmgc90-facts/mailx-2d.md §1.1).
constexpr std::array<ElementEntry, 7> kElements{{
    {"T3xxx", "T3xxx", ElementKind::T3, 2, 3, Rule::triangle_3, Rule::triangle_3, MassLumping::row_sum},
    {"Q4xxx", "Q4xxx", ElementKind::Q4, 2, 4, Rule::quad_2x2, Rule::quad_3x3, MassLumping::row_sum},
    {"T6xxx", "T6xxx", ElementKind::T6, 2, 6, Rule::triangle_3, Rule::triangle_6, MassLumping::row_sum},
    {"Q8xxx", "Q8xxx", ElementKind::Q8, 2, 8, Rule::quad_3x3, Rule::quad_3x3, MassLumping::diagonal_scaling},
    {"TE4xx", "TE4xx", ElementKind::TE4, 3, 4, Rule::tetrahedron_4, Rule::tetrahedron_4,
     MassLumping::row_sum},
    {"H8xxx", "H8xxx", ElementKind::H8, 3, 8, Rule::hexahedron_2x2x2, Rule::hexahedron_2x2x2,
     MassLumping::row_sum},
    {"Q4P0x", "Q4xxx", ElementKind::Q4P0, 2, 4, Rule::quad_2x2, Rule::quad_2x2, MassLumping::row_sum},
}};

}  // namespace

std::span<const ElementEntry> element_catalogue() {
  return kElements;
}

const ElementEntry* find_element(std::string_view name) {
  for (const ElementEntry& e : kElements)
    if (e.name == name) return &e;
  return nullptr;
}

const ElementEntry& element_entry(ElementKind kind) {
  return kElements[static_cast<std::size_t>(kind)];
}

}  // namespace lmgc::solver::fem
