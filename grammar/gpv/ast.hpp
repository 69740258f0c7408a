#pragma once
// GPV.INI / .LAST / .OUT.n: Gauss-point values of MAILx bodies. docs/lmgc90-facts/state-and-outputs.md §1.5,
// datbox-inputs.md §7. Each vector of a Gauss point is written with '(9D14.7)': consecutive
// 14-column fields, wrapping after 9 values, an empty line for an empty vector. Per Gauss point:
//   MECAx: stress, strain, [internal variables]   THERM: T, [grad, flux], [internal variables]
// The lengths depend on the element, the model and the law (examples: Q4xxx 2D 4+4+6 or 5+5+1,
// T3xxx 4+4+1, H8xxx/TE4xx 6+6+1, THERM Q4xxx 1+3+3), which the GPV file does not say; a line
// of exactly 9 values may or may not continue on the next. So the values are kept line by line,
// exactly as written, which makes the echo exact without knowing the models.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

struct GpvModelBlock {
  Word model;                            // MECAx, THERM, POROx, THMCx (line after '$model')
  std::vector<std::vector<Real>> lines;  // value lines, in order
  friend bool operator==(const GpvModelBlock&, const GpvModelBlock&) = default;
};

struct GpvElement {
  Word type;       // element type (Q4xxx ...), columns 2-6
  Integer number;  // element rank, columns 7-13
  std::vector<GpvModelBlock> models;
  friend bool operator==(const GpvElement&, const GpvElement&) = default;
};

struct GpvBody {
  Integer number;  // MAILx rank, columns 7-13
  std::vector<GpvElement> elements;
  friend bool operator==(const GpvBody&, const GpvBody&) = default;
};

struct GpvFile {
  Integer step;
  Real time;
  std::vector<GpvBody> bodies;
  friend bool operator==(const GpvFile&, const GpvFile&) = default;
};

}  // namespace lmgc::grammar
