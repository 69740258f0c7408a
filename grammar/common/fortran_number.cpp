// The numeric lexical grammar, written with Boost.Spirit X3. This is the only translation unit
// that instantiates these rules, which keeps X3's compile cost in one place.
#include "grammar/common/fortran_number.hpp"

#include <boost/spirit/home/x3.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace lmgc::grammar {
namespace {

namespace x3 = boost::spirit::x3;

// Pieces of a Fortran real, captured as raw text: [sign] digits [. digits] [exponent].
struct RealPieces {
  char sign = '+';
  std::string integer_digits;
  bool has_point = false;
  std::string fraction_digits;
  bool has_exponent = false;
  char exponent_sign = '+';
  std::string exponent_digits;
};

// Grammar of a real with blanks already removed (spec: datbox-inputs.md §0):
//   real     = [sign] mantissa [exponent]
//   mantissa = digit+ ['.' digit*] | '.' digit+
//   exponent = ('D'|'d'|'E'|'e') [sign] digit+ | sign digit+
bool parse_real_pieces(std::string_view text, RealPieces& out) {
  using x3::char_;
  using x3::digit;
  using x3::lit;
  auto set_sign = [&](auto& ctx) { out.sign = x3::_attr(ctx); };
  auto add_integer = [&](auto& ctx) { out.integer_digits.push_back(x3::_attr(ctx)); };
  auto add_fraction = [&](auto& ctx) { out.fraction_digits.push_back(x3::_attr(ctx)); };
  auto set_point = [&](auto&) { out.has_point = true; };
  auto set_exponent = [&](auto&) { out.has_exponent = true; };
  auto set_exponent_sign = [&](auto& ctx) { out.exponent_sign = x3::_attr(ctx); };
  auto add_exponent = [&](auto& ctx) { out.exponent_digits.push_back(x3::_attr(ctx)); };

  auto const sign = char_("+-");
  auto const fraction = lit('.')[set_point] >> *digit[add_fraction];
  auto const mantissa = (+digit[add_integer] >> -fraction) | (lit('.')[set_point] >> +digit[add_fraction]);
  auto const exponent_digits = +digit[add_exponent];
  auto const exponent =
      (char_("DdEe")[set_exponent] >> -sign[set_exponent_sign] >> exponent_digits) |
      (sign[set_exponent_sign] >> x3::eps[set_exponent] >> exponent_digits);
  auto const real = -sign[set_sign] >> mantissa >> -exponent;

  auto first = text.begin();
  const bool ok = x3::parse(first, text.end(), real);
  return ok && first == text.end();
}

bool parse_integer_pieces(std::string_view text, char& sign, std::string& digits) {
  using x3::char_;
  using x3::digit;
  auto set_sign = [&](auto& ctx) { sign = x3::_attr(ctx); };
  auto add_digit = [&](auto& ctx) { digits.push_back(x3::_attr(ctx)); };
  auto const integer = -char_("+-")[set_sign] >> +digit[add_digit];
  auto first = text.begin();
  const bool ok = x3::parse(first, text.end(), integer);
  return ok && first == text.end();
}

std::string without_blanks(std::string_view field) {
  std::string s;
  s.reserve(field.size());
  for (char c : field)
    if (c != ' ' && c != '\t') s.push_back(c);
  return s;
}

RealResult real_from_compact(const std::string& compact, int implied_decimals) {
  RealResult result;
  if (compact.empty()) {
    result.blank = true;
    return result;
  }
  RealPieces p;
  if (!parse_real_pieces(compact, p)) {
    result.error = NumberError::malformed;
    return result;
  }
  // Exponent as an integer, guarded against absurd lengths.
  long exponent = 0;
  if (p.has_exponent) {
    if (p.exponent_digits.size() > 6) {
      result.error = NumberError::out_of_range;
      return result;
    }
    exponent = std::stol(p.exponent_digits);
    if (p.exponent_sign == '-') exponent = -exponent;
  }
  if (!p.has_point) exponent -= implied_decimals;
  // Normalised decimal text that strtod rounds correctly: sign digits '.' digits 'e' exponent.
  std::string normal;
  normal.reserve(p.integer_digits.size() + p.fraction_digits.size() + 16);
  normal.push_back(p.sign);
  normal += p.integer_digits.empty() ? "0" : p.integer_digits;
  normal.push_back('.');
  normal += p.fraction_digits;
  normal.push_back('e');
  normal += std::to_string(exponent);
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(normal.c_str(), &end);
  if (std::isinf(value) || (errno == ERANGE && value != 0.0)) {
    result.error = NumberError::out_of_range;
    return result;
  }
  result.value = value;
  return result;
}

IntegerResult integer_from_compact(const std::string& compact) {
  IntegerResult result;
  if (compact.empty()) {
    result.blank = true;
    return result;
  }
  char sign = '+';
  std::string digits;
  if (!parse_integer_pieces(compact, sign, digits)) {
    result.error = NumberError::malformed;
    return result;
  }
  // Fortran default integers are 32-bit: LMGC90 cannot hold more.
  std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos) return result;  // zero
  if (digits.size() - first > 10) {
    result.error = NumberError::out_of_range;
    return result;
  }
  const long long magnitude = std::stoll(digits.substr(first));
  const long long value = sign == '-' ? -magnitude : magnitude;
  if (value > std::numeric_limits<std::int32_t>::max() ||
      value < std::numeric_limits<std::int32_t>::min()) {
    result.error = NumberError::out_of_range;
    return result;
  }
  result.value = value;
  return result;
}

// The first list-directed item of `text`: skips leading blanks, ends at blank, ',' or '/'.
std::optional<std::string> first_list_item(std::string_view text) {
  std::size_t begin = 0;
  while (begin < text.size() && (text[begin] == ' ' || text[begin] == '\t' || text[begin] == ','))
    ++begin;
  if (begin >= text.size() || text[begin] == '/') return std::nullopt;
  std::size_t end = begin;
  while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != ',' &&
         text[end] != '/')
    ++end;
  return std::string(text.substr(begin, end - begin));
}

}  // namespace

RealResult read_fortran_real(std::string_view field, int implied_decimals) {
  return real_from_compact(without_blanks(field), implied_decimals);
}

IntegerResult read_fortran_integer(std::string_view field) {
  return integer_from_compact(without_blanks(field));
}

std::optional<IntegerResult> read_list_directed_integer(std::string_view text) {
  auto item = first_list_item(text);
  if (!item) return std::nullopt;
  return integer_from_compact(*item);
}

std::optional<RealResult> read_list_directed_real(std::string_view text) {
  auto item = first_list_item(text);
  if (!item) return std::nullopt;
  // List-directed reals have no implied decimal point.
  return real_from_compact(*item, 0);
}

}  // namespace lmgc::grammar
