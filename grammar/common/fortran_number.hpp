#pragma once
// Fortran formatted input of numbers (gfortran, BLANK='NULL'): the lexical grammar of every
// numeric field of every LMGC90 file. docs/lmgc90-facts/datbox-inputs.md §0 "Semantics of a numeric field".
#include <cstdint>
#include <optional>
#include <string_view>

namespace lmgc::grammar {

enum class NumberError { none, malformed, out_of_range };

struct RealResult {
  double value = 0.0;
  NumberError error = NumberError::none;
  bool blank = false;  // the field held only blanks (reads as 0)
};

struct IntegerResult {
  std::int64_t value = 0;
  NumberError error = NumberError::none;
  bool blank = false;
};

// Reads a `Dw.d` / `Ew.d` / `Fw.d` field. Blanks anywhere are ignored; an all-blank field is 0;
// exponent letters D d E e, or a bare signed exponent ("1.0+05"); a mantissa without a
// decimal point is scaled by 10^-implied_decimals (Fortran's implied decimal point).
RealResult read_fortran_real(std::string_view field, int implied_decimals);

// Reads an `Iw` field: blanks ignored, optional sign, digits.
IntegerResult read_fortran_integer(std::string_view field);

// List-directed input of one value: leading/trailing blanks, stops at a blank, ',' or '/'.
// Returns nullopt when the range holds no value (Fortran raises an end-of-record error).
std::optional<IntegerResult> read_list_directed_integer(std::string_view text);
std::optional<RealResult> read_list_directed_real(std::string_view text);

}  // namespace lmgc::grammar
