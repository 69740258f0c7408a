#pragma once
// Fortran formatted output, as gfortran prints it: the only way numbers reach LMGC90 files.
// docs/lmgc90-facts/state-and-outputs.md (notation), datbox-inputs.md §0 "Writers".
#include <cstdint>
#include <string>
#include <string_view>

namespace lmgc::grammar {

// `Dw.d`: ±0.ddddddd D±ee, right-justified in w columns (w=14, d=7 gives ' 0.1000000D-02').
// For |exponent| > 99 the letter is dropped to make room for three digits (' 0.1000000+100').
void append_fortran_d(std::string& out, double value, int width = 14, int digits = 7);
std::string fortran_d(double value, int width = 14, int digits = 7);

// `ESw.d`: scientific with one non-zero digit before the point (' 1.00000000E-03').
void append_fortran_es(std::string& out, double value, int width, int digits);

// `Iw`: right-justified; all '*' when it does not fit.
void append_fortran_i(std::string& out, std::int64_t value, int width);

// `Aw`: the text padded with blanks on the right or truncated to w characters.
void append_fortran_a(std::string& out, std::string_view text, int width);

// `nX`: n blanks.
inline void append_blanks(std::string& out, int count) {
  out.append(static_cast<std::size_t>(count), ' ');
}

// Removes trailing blanks (used where LMGC90 writes a value with A-format trimming).
std::string_view trim_right(std::string_view text);
std::string_view trim(std::string_view text);

}  // namespace lmgc::grammar
