#include "grammar/common/fortran_number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

TEST(FortranReal, ReadsDExponent) {
  auto r = read_fortran_real(" 0.1600000D-02", 7);
  EXPECT_EQ(r.error, NumberError::none);
  EXPECT_DOUBLE_EQ(r.value, 0.0016);
}

TEST(FortranReal, ReadsLowerCaseAndEExponents) {
  EXPECT_DOUBLE_EQ(read_fortran_real("1.6000000E-03", 7).value, 0.0016);
  EXPECT_DOUBLE_EQ(read_fortran_real("0.0000000e+00", 7).value, 0.0);
  EXPECT_DOUBLE_EQ(read_fortran_real("3.0788939d-01", 7).value, 0.30788939);
}

TEST(FortranReal, ReadsBareSignedExponent) {
  EXPECT_DOUBLE_EQ(read_fortran_real("1.0+05", 7).value, 1.0e5);
}

TEST(FortranReal, BlankFieldIsZeroAndFlagged) {
  auto r = read_fortran_real("              ", 7);
  EXPECT_TRUE(r.blank);
  EXPECT_EQ(r.value, 0.0);
}

TEST(FortranReal, EmbeddedBlanksAreIgnored) {
  EXPECT_DOUBLE_EQ(read_fortran_real(" 1. 5 D+0 1", 7).value, 15.0);
}

TEST(FortranReal, MantissaWithoutPointUsesImpliedDecimal) {
  EXPECT_DOUBLE_EQ(read_fortran_real("           100", 7).value, 1.0e-5);
}

TEST(FortranReal, RejectsGarbage) {
  EXPECT_EQ(read_fortran_real("abc", 7).error, NumberError::malformed);
  EXPECT_EQ(read_fortran_real("1.2.3", 7).error, NumberError::malformed);
  EXPECT_EQ(read_fortran_real("1.0D", 7).error, NumberError::malformed);
  EXPECT_EQ(read_fortran_real("--1", 7).error, NumberError::malformed);
}

TEST(FortranReal, OverflowIsOutOfRange) {
  EXPECT_EQ(read_fortran_real("0.1D+999", 7).error, NumberError::out_of_range);
}

TEST(FortranInteger, ReadsLeftJustifiedAndSplitDigits) {
  EXPECT_EQ(read_fortran_integer("1025   ").value, 1025);
  EXPECT_EQ(read_fortran_integer(" 1 0").value, 10);
  EXPECT_EQ(read_fortran_integer("  -7").value, -7);
}

TEST(FortranInteger, RejectsRealAndOverflow) {
  EXPECT_EQ(read_fortran_integer("1.5").error, NumberError::malformed);
  EXPECT_EQ(read_fortran_integer("99999999999").error, NumberError::out_of_range);
}

TEST(ListDirected, StopsAtBlankCommaSlash) {
  EXPECT_EQ(read_list_directed_integer("   12  ")->value, 12);
  EXPECT_EQ(read_list_directed_integer(" 7,8")->value, 7);
  EXPECT_FALSE(read_list_directed_integer("   ").has_value());
  EXPECT_FALSE(read_list_directed_integer(" / 3").has_value());
}

// Every byte may sit in a damaged file: a byte >= 0x80 (a negative char) is malformed, never an
// assertion of the parser's character classes (found by fuzzing POSTPRO.DAT's STEP line).
TEST(FortranNumbers, BytesAbove127AreMalformedNotAsserted) {
  for (int byte = 0x80; byte <= 0xFF; ++byte) {
    const std::string high(1, static_cast<char>(byte));
    EXPECT_EQ(read_fortran_integer("1" + high).error, NumberError::malformed);
    EXPECT_EQ(read_fortran_integer(high).error, NumberError::malformed);
    EXPECT_EQ(read_fortran_real("1.0" + high, 7).error, NumberError::malformed);
    EXPECT_EQ(read_fortran_real("1.0D" + high, 7).error, NumberError::malformed);
    const auto listed = read_list_directed_integer(" 7" + high + " ");
    ASSERT_TRUE(listed.has_value());
    EXPECT_EQ(listed->error, NumberError::malformed);
    const auto real = read_list_directed_real(high);
    ASSERT_TRUE(real.has_value());
    EXPECT_EQ(real->error, NumberError::malformed);
  }
}

TEST(FortranD, WritesLmgc90Layout) {
  EXPECT_EQ(fortran_d(0.0016), " 0.1600000D-02");
  EXPECT_EQ(fortran_d(-0.5175621), "-0.5175621D+00");
  EXPECT_EQ(fortran_d(0.0), " 0.0000000D+00");
  EXPECT_EQ(fortran_d(1.0), " 0.1000000D+01");
  EXPECT_EQ(fortran_d(0.1e-100), " 0.1000000-100");
  EXPECT_EQ(fortran_d(-0.0), "-0.0000000D+00");
}

TEST(FortranD, RoundsToSevenSignificantDigits) {
  EXPECT_EQ(fortran_d(0.99999999), " 0.1000000D+01");
  EXPECT_EQ(fortran_d(1.23456789e-3), " 0.1234568D-02");
}

TEST(FortranI, RightJustifiesAndOverflowsToStars) {
  std::string s;
  append_fortran_i(s, 42, 7);
  EXPECT_EQ(s, "     42");
  s.clear();
  append_fortran_i(s, 123456, 5);
  EXPECT_EQ(s, "*****");
}

TEST(FortranEs, WritesScientific) {
  std::string s;
  append_fortran_es(s, 1.0e-3, 15, 8);
  EXPECT_EQ(s, " 1.00000000E-03");
}

// The writers format with std::to_chars; printf is the reference they must equal digit for digit.
std::string printf_es(double value, int width, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*E", digits, value);
  const std::string field(buffer);
  if (static_cast<int>(field.size()) > width) return std::string(static_cast<std::size_t>(width), '*');
  return std::string(static_cast<std::size_t>(width) - field.size(), ' ') + field;
}

std::string printf_d(double value, int width, int digits) {
  if (std::isnan(value) || std::isinf(value)) return fortran_d(value, width, digits);
  std::string mantissa(static_cast<std::size_t>(digits), '0');
  long exponent = 0;
  if (value != 0.0) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, std::fabs(value));
    const std::string text(buffer);
    const std::size_t e = text.find('e');
    mantissa.clear();
    for (std::size_t i = 0; i < e; ++i)
      if (text[i] != '.') mantissa.push_back(text[i]);
    exponent = std::strtol(text.c_str() + e + 1, nullptr, 10) + 1;
  }
  std::string field = std::signbit(value) ? "-0." : " 0.";
  field += mantissa;
  char exponent_text[32];
  const long magnitude = std::labs(exponent);
  if (magnitude <= 99)
    std::snprintf(exponent_text, sizeof exponent_text, "D%c%02ld", exponent < 0 ? '-' : '+', magnitude);
  else
    std::snprintf(exponent_text, sizeof exponent_text, "%c%03ld", exponent < 0 ? '-' : '+', magnitude);
  field += exponent_text;
  if (static_cast<int>(field.size()) > width && field[0] == ' ') field.erase(0, 1);
  if (static_cast<int>(field.size()) > width) return std::string(static_cast<std::size_t>(width), '*');
  return std::string(static_cast<std::size_t>(width) - field.size(), ' ') + field;
}

TEST(FortranWriters, EqualPrintfOnRandomAndSpecialValues) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                0.99999999,
                                9.9999999950e99,
                                1e-100,
                                -2.5e-308,
                                4.9e-324,
                                1.7976931348623157e308,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-320, 300);
  for (int i = 0; i < 20000; ++i) values.push_back(mantissa(random) * std::pow(10.0, exponent(random)));
  for (const double v : values) {
    std::string es;
    append_fortran_es(es, v, 15, 8);
    ASSERT_EQ(es, printf_es(v, 15, 8)) << v;
    es.clear();
    append_fortran_es(es, v, 14, 7);
    ASSERT_EQ(es, printf_es(v, 14, 7)) << v;
    ASSERT_EQ(fortran_d(v), printf_d(v, 14, 7)) << v;
  }
}

}  // namespace
}  // namespace lmgc::grammar

namespace lmgc::grammar {
namespace {

// The fast path and the general path must agree with a correctly rounded conversion.
TEST(FortranReal, FastPathIsCorrectlyRounded) {
  EXPECT_EQ(read_fortran_real(" 0.1234567D-02", 7).value, 0.1234567e-2);
  EXPECT_EQ(read_fortran_real("-0.9999999D+22", 7).value, -0.9999999e22);
  EXPECT_EQ(read_fortran_real(" 0.1000000D-30", 7).value, 1e-31);
  EXPECT_EQ(read_fortran_real("1.2345678901234567890", 7).value, 1.2345678901234567890);
  EXPECT_EQ(read_fortran_real("0.5D-320", 7).value, 0.5e-320);  // subnormal, general path
  EXPECT_EQ(read_fortran_real("0.1D-400", 7).value, 0.0);       // underflow reads as zero
}

}  // namespace
}  // namespace lmgc::grammar
