// The numeric lexical grammar, written with Boost.Spirit X3. This is the only translation unit
// that instantiates these rules, which keeps X3's compile cost in one place. The hot path
// allocates nothing: fields are compacted into a stack buffer, the grammar records where each
// piece starts and ends, and std::from_chars converts the normalised text (correctly rounded).
#include "grammar/common/fortran_number.hpp"

#include <boost/spirit/home/x3.hpp>
#include <charconv>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace lmgc::grammar {
namespace {

namespace x3 = boost::spirit::x3;
using Range = boost::iterator_range<const char*>;

// Grammar of a real with blanks removed (docs/lmgc90-facts/datbox-inputs.md §0):
//   real     = [sign] mantissa [exponent]
//   mantissa = digit+ ['.' digit*] | '.' digit+
//   exponent = ('D'|'d'|'E'|'e') [sign] digit+ | sign digit+
// Each piece is captured as a range of the input (x3::raw), so no attribute allocates.
struct RealPieces {
  char sign = '+';
  Range integer_digits, fraction_digits, exponent_digits;
  bool has_point = false;
  bool has_exponent = false;
  char exponent_sign = '+';
};

struct RealTag;
struct IntegerTag;

// Semantic actions write into the RealPieces passed through the parse context (x3::with), so the
// parsers themselves are constant objects built once.
template <class Member>
auto store(Member member) {
  return [member](auto& ctx) { x3::get<RealTag>(ctx).get().*member = x3::_attr(ctx); };
}
auto const mark_point = [](auto& ctx) { x3::get<RealTag>(ctx).get().has_point = true; };
auto const mark_exponent = [](auto& ctx) { x3::get<RealTag>(ctx).get().has_exponent = true; };

// Digits as a range, not x3::digit: the standard encoding's classifier asserts on a byte >= 0x80
// (a negative char), and any byte may sit in a damaged file.
auto const digit = x3::char_('0', '9');
auto const sign_char = x3::char_("+-");
auto const exponent_letter = x3::char_("DdEe");
auto const fraction = x3::lit('.')[mark_point] >> x3::raw[*digit][store(&RealPieces::fraction_digits)];
auto const mantissa = (x3::raw[+digit][store(&RealPieces::integer_digits)] >> -fraction) |
                      (x3::lit('.')[mark_point] >> x3::raw[+digit][store(&RealPieces::fraction_digits)]);
auto const exponent_digits = x3::raw[+digit][store(&RealPieces::exponent_digits)];
auto const exponent =
    (exponent_letter[mark_exponent] >> -sign_char[store(&RealPieces::exponent_sign)] >> exponent_digits) |
    (sign_char[store(&RealPieces::exponent_sign)] >> x3::eps[mark_exponent] >> exponent_digits);
auto const real_grammar = -sign_char[store(&RealPieces::sign)] >> mantissa >> -exponent;

bool parse_real_pieces(const char* first, const char* last, RealPieces& out) {
  const char* it = first;
  return x3::parse(it, last, x3::with<RealTag>(std::ref(out))[real_grammar]) && it == last;
}

struct IntegerPieces {
  char sign = '+';
  Range digits;
};
auto const integer_grammar =
    -sign_char[([](auto& ctx) { x3::get<IntegerTag>(ctx).get().sign = x3::_attr(ctx); })] >>
    x3::raw[+digit][([](auto& ctx) { x3::get<IntegerTag>(ctx).get().digits = x3::_attr(ctx); })];

bool parse_integer_pieces(const char* first, const char* last, char& sign, Range& digits) {
  IntegerPieces pieces;
  const char* it = first;
  const bool ok = x3::parse(it, last, x3::with<IntegerTag>(std::ref(pieces))[integer_grammar]) && it == last;
  sign = pieces.sign;
  digits = pieces.digits;
  return ok;
}

// Fields longer than this (after removing blanks) are not numbers LMGC90 could have written.
constexpr std::size_t kMaxCompact = 120;

struct Compact {
  char text[kMaxCompact];
  std::size_t size = 0;
  bool too_long = false;
};

// Fortran BLANK='NULL': blanks (and tabs, which we read as blanks) inside a field are ignored.
void compact(std::string_view field, Compact& out) {
  for (char c : field) {
    if (c == ' ' || c == '\t') continue;
    if (out.size == kMaxCompact) {
      out.too_long = true;
      return;
    }
    out.text[out.size++] = c;
  }
}

RealResult real_from_compact(const char* first, const char* last, int implied_decimals) {
  RealResult result;
  if (first == last) {
    result.blank = true;
    return result;
  }
  RealPieces p;
  if (!parse_real_pieces(first, last, p)) {
    result.error = NumberError::malformed;
    return result;
  }
  long exponent = 0;
  if (p.has_exponent) {
    if (p.exponent_digits.size() > 6) {
      result.error = NumberError::out_of_range;
      return result;
    }
    std::from_chars(p.exponent_digits.begin(), p.exponent_digits.end(), exponent);
    if (p.exponent_sign == '-') exponent = -exponent;
  }
  if (!p.has_point) exponent -= implied_decimals;
  // Fast path (Clinger 1990): with at most 15 significant digits the digits form an integer
  // below 2^53, and one multiplication or division by an exact power of ten (<= 1e22) is
  // correctly rounded. This covers every D14.7 value LMGC90 writes.
  double value = 0.0;
  {
    std::int64_t digits = 0;
    int count = 0;
    bool fast = true;
    auto take = [&](Range r) {
      for (char c : r) {
        if (count == 0 && c == '0') continue;  // leading zeros carry no digit
        if (++count > 15) {
          fast = false;
          return;
        }
        digits = digits * 10 + (c - '0');
      }
    };
    take(p.integer_digits);
    if (fast) take(p.fraction_digits);
    const long scale = exponent - static_cast<long>(p.fraction_digits.size());
    static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                         1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                         1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    if (fast && scale >= -22 && scale <= 22) {
      const double m = static_cast<double>(digits);
      value = scale >= 0 ? m * kPowers[scale] : m / kPowers[-scale];
      result.value = p.sign == '-' ? -value : value;
      return result;
    }
  }
  // General case: normalised text "digits.digitsE<exponent>" for from_chars (sign applied after).
  char normal[2 * kMaxCompact + 32];
  std::size_t n = 0;
  if (p.integer_digits.empty()) normal[n++] = '0';
  for (char c : p.integer_digits) normal[n++] = c;
  normal[n++] = '.';
  for (char c : p.fraction_digits) normal[n++] = c;
  normal[n++] = 'e';
  const auto written = std::to_chars(normal + n, normal + sizeof normal, exponent);
  const auto parsed = std::from_chars(normal, written.ptr, value);
  if (parsed.ec == std::errc::result_out_of_range) {
    // Underflow reads as zero in Fortran; overflow is an error.
    if (exponent > 0) {
      result.error = NumberError::out_of_range;
      return result;
    }
    value = 0.0;
  } else if (parsed.ec != std::errc() || std::isinf(value)) {
    result.error = NumberError::out_of_range;
    return result;
  }
  result.value = p.sign == '-' ? -value : value;
  return result;
}

IntegerResult integer_from_compact(const char* first, const char* last) {
  IntegerResult result;
  if (first == last) {
    result.blank = true;
    return result;
  }
  char sign = '+';
  Range digits;
  if (!parse_integer_pieces(first, last, sign, digits)) {
    result.error = NumberError::malformed;
    return result;
  }
  std::int64_t magnitude = 0;
  const auto parsed = std::from_chars(digits.begin(), digits.end(), magnitude);
  const std::int64_t value = sign == '-' ? -magnitude : magnitude;
  // Fortran default integers are 32-bit: LMGC90 cannot hold more.
  if (parsed.ec != std::errc() || value > std::numeric_limits<std::int32_t>::max() ||
      value < std::numeric_limits<std::int32_t>::min()) {
    result.error = NumberError::out_of_range;
    return result;
  }
  result.value = value;
  return result;
}

// The first list-directed item of `text`: skips leading blanks/commas, ends at blank, ',' or '/'.
std::optional<std::string_view> first_list_item(std::string_view text) {
  std::size_t begin = 0;
  while (begin < text.size() && (text[begin] == ' ' || text[begin] == '\t' || text[begin] == ',')) ++begin;
  if (begin >= text.size() || text[begin] == '/') return std::nullopt;
  std::size_t end = begin;
  while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != ',' && text[end] != '/')
    ++end;
  return text.substr(begin, end - begin);
}

}  // namespace

RealResult read_fortran_real(std::string_view field, int implied_decimals) {
  Compact c;
  compact(field, c);
  if (c.too_long) return RealResult{0.0, NumberError::malformed, false};
  return real_from_compact(c.text, c.text + c.size, implied_decimals);
}

IntegerResult read_fortran_integer(std::string_view field) {
  Compact c;
  compact(field, c);
  if (c.too_long) return IntegerResult{0, NumberError::malformed, false};
  return integer_from_compact(c.text, c.text + c.size);
}

std::optional<IntegerResult> read_list_directed_integer(std::string_view text) {
  auto item = first_list_item(text);
  if (!item) return std::nullopt;
  if (item->size() > kMaxCompact) return IntegerResult{0, NumberError::malformed, false};
  return integer_from_compact(item->data(), item->data() + item->size());
}

std::optional<RealResult> read_list_directed_real(std::string_view text) {
  auto item = first_list_item(text);
  if (!item) return std::nullopt;
  if (item->size() > kMaxCompact) return RealResult{0.0, NumberError::malformed, false};
  // List-directed reals have no implied decimal point.
  return real_from_compact(item->data(), item->data() + item->size(), 0);
}

}  // namespace lmgc::grammar
