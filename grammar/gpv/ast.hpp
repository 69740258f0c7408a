#pragma once
// GPV.INI / .LAST / .OUT.n: Gauss-point values of MAILx bodies. spec: state-and-outputs.md §1.5,
// datbox-inputs.md §7. A Gauss point's vectors are written on consecutive lines of up to 9
// D14.7 values with no separator; their lengths are known only from the model, so the values
// are kept line by line, exactly as written.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

struct GpvModelBlock {
  Word model;                             // MECAx, THERM, POROx, THMCx (line after '$model')
  std::vector<std::vector<Real>> lines;   // value lines, in order
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
