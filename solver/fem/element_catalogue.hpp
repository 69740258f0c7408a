#pragma once
// The finite elements lmgc runs, in one table: LMGC90's name, the reference element, the Gauss rule
// of its stiffness and of its mass (element_catalogue.cpp). Adding an element is one struct in
// reference_element.hpp, one row here and its case in with_element.
#include <span>
#include <string_view>

#include "solver/fem/quadrature.hpp"
#include "solver/fem/reference_element.hpp"

namespace lmgc::solver::fem {

// Q4P0: LMGC90's Q4P0x, the bilinear quadrilateral whose mass takes the 2 × 2 rule; its own large-strain
// material gives it a pressure constant over the element (mean dilatation); with MatLib it is a Q4.
enum class ElementKind : std::uint8_t { T3, Q4, T6, Q8, TE4, H8, Q4P0 };

// MODELS.DAT 'mstrg lump_': the element mass on the diagonal by row sums (linear elements, T6) or
// by scaling the consistent diagonal to the element's mass (HRZ: Q8).
enum class MassLumping : std::uint8_t { row_sum, diagonal_scaling };

struct ElementEntry {
  std::string_view name;       // LMGC90's, as MODELS.DAT writes it
  std::string_view body_name;  // as BODIES.DAT and GPV files write the element (Q4P0x's is Q4xxx)
  ElementKind kind;
  int dimension;
  int nodes;
  Rule stiffness_rule;
  Rule mass_rule;
  MassLumping lumping;
};

std::span<const ElementEntry> element_catalogue();
const ElementEntry* find_element(std::string_view name);
const ElementEntry& element_entry(ElementKind kind);

// Calls f with a value of the element's struct (T3{}, Q4{}, ...).
template <class F>
decltype(auto) with_element(ElementKind kind, F&& f) {
  switch (kind) {
    case ElementKind::T3:
      return f(T3{});
    case ElementKind::Q4:
      return f(Q4{});
    case ElementKind::T6:
      return f(T6{});
    case ElementKind::Q8:
      return f(Q8{});
    case ElementKind::TE4:
      return f(TE4{});
    case ElementKind::H8:
      return f(H8{});
    case ElementKind::Q4P0:
      return f(Q4{});
  }
  return f(T3{});
}

}  // namespace lmgc::solver::fem
