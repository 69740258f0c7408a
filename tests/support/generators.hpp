#pragma once
// RapidCheck generators shared by the round-trip properties: values that LMGC90's writers can
// represent exactly (7 significant digits for D14.7, 5-character words), so that
// parse(write(ast)) == ast is a fair claim.
#include <rapidcheck.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace lmgc::test {

// A real with 7 significant digits and a decimal exponent in [-30, 30], or zero.
inline rc::Gen<double> gen_d14_real() {
  return rc::gen::oneOf(rc::gen::just(0.0),
                        rc::gen::map(rc::gen::tuple(rc::gen::inRange(1000000, 10000000),
                                                    rc::gen::inRange(-30, 31), rc::gen::arbitrary<bool>()),
                                     [](const std::tuple<int, int, bool>& t) {
                                       char buffer[64];
                                       std::snprintf(buffer, sizeof buffer, "%s0.%dE%d",
                                                     std::get<2>(t) ? "-" : "", std::get<0>(t),
                                                     std::get<1>(t));
                                       return std::strtod(buffer, nullptr);
                                     }));
}

// A real drawn uniformly from [lo, hi] on a grid of 10⁶ steps (shrinks towards lo).
inline double in_range(double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(*rc::gen::inRange(0, 1000001)) / 1e6;
}

// A word of exactly `length` characters from [A-Za-z0-9_], no blanks (colours, nicknames).
inline rc::Gen<std::string> gen_word(int length = 5) {
  return rc::gen::container<std::string>(
      static_cast<std::size_t>(length),
      rc::gen::elementOf(std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_")));
}

// Canonical text damaged in 1 to 7 places: a byte overwritten by one that matters to the
// readers, up to 40 bytes cut, or a line broken in two (robustness properties).
inline std::string damaged_text(std::string text) {
  for (int k = 0, n = *rc::gen::inRange(1, 8); k < n && !text.empty(); ++k) {
    const std::size_t at = *rc::gen::inRange<std::size_t>(0, text.size());
    switch (*rc::gen::inRange(0, 3)) {
      case 0:
        text[at] = *rc::gen::elementOf(std::string("x0.-+D$! \n\t"));
        break;
      case 1:
        text.erase(at, *rc::gen::inRange<std::size_t>(1, 40));
        break;
      default:
        text.insert(at, "\n");
        break;
    }
  }
  return text;
}

}  // namespace lmgc::test
