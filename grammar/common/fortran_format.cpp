#include "grammar/common/fortran_format.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace lmgc::grammar {

namespace {

// printf's "%.*e" of `value` into `buffer` (std::to_chars writes the same digits, several times
// faster, and POSTPRO writes its lines at every step); returns the length.
std::size_t scientific(char (&buffer)[64], double value, int digits_after_point) {
  const auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific, digits_after_point);
  return error == std::errc() ? static_cast<std::size_t>(end - buffer) : 0;
}

// Two or three exponent digits, as printf's "%02ld" / "%03ld".
void append_exponent_digits(std::string& out, long magnitude, int at_least) {
  char digits[24];
  const auto [end, error] = std::to_chars(digits, digits + sizeof digits, magnitude);
  const auto length = error == std::errc() ? static_cast<int>(end - digits) : 0;
  if (length < at_least) out.append(static_cast<std::size_t>(at_least - length), '0');
  out.append(digits, static_cast<std::size_t>(length));
}

}  // namespace

void append_fortran_d(std::string& out, double value, int width, int digits) {
  std::string field;
  if (std::isnan(value) || std::isinf(value)) {
    field = std::isnan(value) ? "NaN" : (value > 0 ? "Infinity" : "-Infinity");
  } else {
    // gfortran prints the sign of a negative zero ('-0.0000000D+00'), and LMGC90's files hold them.
    const bool negative = std::signbit(value);
    std::string mantissa(static_cast<std::size_t>(digits), '0');
    long exponent = 0;
    if (value != 0.0) {
      // printf rounds to `digits` significant digits: d.dddddde±x → 0.ddddddd × 10^(x+1).
      char buffer[64];
      const std::string_view text(buffer, scientific(buffer, std::fabs(value), digits - 1));
      const std::size_t e = text.find('e');
      mantissa.clear();
      for (std::size_t i = 0; i < e; ++i)
        if (text[i] != '.') mantissa.push_back(text[i]);
      long written = 0;
      const char* first = text.data() + e + 1;
      if (*first == '+') ++first;  // from_chars takes '-' but not '+'
      std::from_chars(first, text.data() + text.size(), written);
      exponent = written + 1;
    }
    field.push_back(negative ? '-' : ' ');
    field += "0.";
    field += mantissa;
    const long magnitude = std::labs(exponent);
    if (magnitude <= 99) field.push_back('D');
    field.push_back(exponent < 0 ? '-' : '+');
    append_exponent_digits(field, magnitude, magnitude <= 99 ? 2 : 3);
    // A positive value's leading blank is the optional sign position: drop it if too wide.
    if (static_cast<int>(field.size()) > width && field[0] == ' ') field.erase(0, 1);
  }
  if (static_cast<int>(field.size()) > width) {
    out.append(static_cast<std::size_t>(width), '*');
    return;
  }
  out.append(static_cast<std::size_t>(width) - field.size(), ' ');
  out += field;
}

std::string fortran_d(double value, int width, int digits) {
  std::string out;
  append_fortran_d(out, value, width, digits);
  return out;
}

void append_fortran_es(std::string& out, double value, int width, int digits) {
  char buffer[64];
  std::string field(buffer, scientific(buffer, value, digits));
  for (char& c : field) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));  // printf's %E
  // C prints at least two exponent digits, as Fortran does for |e| <= 99.
  if (static_cast<int>(field.size()) > width) {
    out.append(static_cast<std::size_t>(width), '*');
    return;
  }
  out.append(static_cast<std::size_t>(width) - field.size(), ' ');
  out += field;
}

void append_fortran_i(std::string& out, std::int64_t value, int width) {
  const std::string text = std::to_string(value);
  if (static_cast<int>(text.size()) > width) {
    out.append(static_cast<std::size_t>(width), '*');
    return;
  }
  out.append(static_cast<std::size_t>(width) - text.size(), ' ');
  out += text;
}

void append_fortran_a(std::string& out, std::string_view text, int width) {
  const std::size_t w = static_cast<std::size_t>(width);
  if (text.size() >= w) {
    out.append(text.substr(0, w));
  } else {
    out.append(text);
    out.append(w - text.size(), ' ');
  }
}

std::string_view trim_right(std::string_view text) {
  std::size_t end = text.size();
  while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  return text.substr(0, end);
}

std::string_view trim(std::string_view text) {
  text = trim_right(text);
  std::size_t begin = 0;
  while (begin < text.size() && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
  return text.substr(begin);
}

}  // namespace lmgc::grammar
