#include "grammar/common/card_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"

namespace lmgc::grammar {

std::string_view columns(std::string_view line, int first, int last) {
  const std::size_t limit = std::min(line.size(), kRecordLength);
  const std::size_t begin = static_cast<std::size_t>(first - 1);
  if (begin >= limit) return {};
  const std::size_t end = std::min(static_cast<std::size_t>(last), limit);
  return line.substr(begin, end - begin);
}

std::string_view keyword_of(std::string_view line) {
  return columns(line, 2, 6);
}

bool is_skipped_line(std::string_view line) {
  if (!line.empty() && (line[0] == '!' || line[0] == '#')) return true;
  for (char c : line)
    if (c != ' ' && c != '\t') return false;
  return true;
}

CardReader::CardReader(const SourceText& source, DiagnosticSink& sink) : source_(source), sink_(sink) {
  skip_insignificant();
}

bool CardReader::check_records(Empty empty) {
  bool any = false;
  for (const Line& line : source_.lines()) {
    const std::string_view text = line.text;
    // Eight bytes at a time: a byte with its high bit set is non-ASCII, one below 0x20 a control
    // character (NUL of a damaged or binary file, ...); tabs are the only ones let through.
    std::size_t start = 0;
    for (; start + 8 <= text.size(); start += 8) {
      std::uint64_t word;
      std::memcpy(&word, text.data() + start, 8);
      const std::uint64_t below_space = (word - 0x2020202020202020ull) & ~word & 0x8080808080808080ull;
      if ((word & 0x8080808080808080ull) || below_space) break;
    }
    for (std::size_t i = start; i < text.size(); ++i) {
      const auto byte = static_cast<unsigned char>(text[i]);
      if (byte < 0x20 && byte != '\t') {
        const int col = static_cast<int>(i) + 1;
        report("L1008", line, col, col,
               (byte == 0 ? std::string("NUL byte") : "control character " + std::to_string(byte)) +
                   " in column " + std::to_string(col) + ": a damaged or binary file",
               "LMGC90 input files are plain ASCII text");
        break;  // one report per line
      }
      if (byte > 127) {
        const int col = static_cast<int>(i) + 1;
        report(
            "L1008", line, col, col,
            "non-ASCII byte 0x" +
                [&] {
                  static const char* hex = "0123456789ABCDEF";
                  const auto b = static_cast<unsigned char>(text[i]);
                  return std::string{hex[b >> 4], hex[b & 15]};
                }() +
                " in column " + std::to_string(col),
            "LMGC90 input files are plain ASCII");
        break;  // one report per line
      }
    }
    if (text.size() > kRecordLength) {
      const std::string_view beyond = text.substr(kRecordLength);
      if (beyond.find_first_not_of(" \t") != std::string_view::npos) {
        const int col = static_cast<int>(kRecordLength) + 1;
        report("L1010", line, col, static_cast<int>(std::min<std::size_t>(text.size(), 100000)),
               "line " + std::to_string(line.number) + " is " + std::to_string(text.size()) +
                   " characters long; LMGC90 ignores everything past column 180");
      }
    }
    if (!any && !is_skipped_line(text)) any = true;
  }
  if (!any && empty == Empty::error) {
    sink_.report("L1009", Location{source_.path(), SourceSpan{}},
                 source_.lines().empty() ? "file is empty" : "file holds only comments and blank lines");
  }
  return any;
}

void CardReader::skip_insignificant() {
  const auto& lines = source_.lines();
  while (index_ < lines.size() && is_skipped_line(lines[index_].text)) ++index_;
}

bool CardReader::at_end() const {
  return index_ >= source_.lines().size();
}

const Line& CardReader::peek() const {
  return source_.lines()[index_];
}

const Line& CardReader::next() {
  const Line& line = source_.lines()[index_++];
  skip_insignificant();
  return line;
}

SourceSpan CardReader::span(const Line& line, int first, int last) const {
  return make_span(line.number, static_cast<std::size_t>(first), static_cast<std::size_t>(last));
}

Location CardReader::location(const Line& line, int first, int last) const {
  return Location{source_.path(), span(line, first, last)};
}

void CardReader::report(std::string_view code, const Line& line, int first, int last, std::string message,
                        std::string hint) {
  sink_.report(code, location(line, first, last), std::move(message), std::move(hint));
}

void CardReader::report_at_end(std::string_view code, std::string message) {
  const auto& lines = source_.lines();
  const std::uint32_t last_line = lines.empty() ? 0 : lines.back().number;
  const std::size_t col = lines.empty() ? 0 : lines.back().text.size() + 1;
  SourceSpan span = make_span(last_line, col, col);
  span.end_column = span.column;
  sink_.report(code, Location{source_.path(), span}, std::move(message));
}

void CardReader::check_tabs(const Line& line, int first, int last) {
  const std::string_view field = columns(line.text, first, last);
  const std::size_t tab = field.find('\t');
  if (tab != std::string_view::npos) {
    const int col = first + static_cast<int>(tab);
    report("L1007", line, col, col,
           "tab character in columns " + std::to_string(first) + "-" + std::to_string(last) +
               "; read as a blank",
           "replace tabs by spaces: LMGC90 reads fixed columns");
  }
}

namespace {
bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '.' || c == 'D' || c == 'd' || c == 'E' || c == 'e';
}
}  // namespace

void CardReader::check_spill(const Line& line, int first, int last) {
  const std::string_view text = line.text;
  const std::string_view field = columns(text, first, last);
  if (field.find_first_not_of(" \t") == std::string_view::npos) return;
  const std::size_t after = static_cast<std::size_t>(last);  // 0-based index of column last+1
  const bool spills_right =
      after < std::min(text.size(), kRecordLength) && is_number_char(text[after]) && field.back() != ' ';
  const std::size_t before = static_cast<std::size_t>(first - 2);  // 0-based index of column first-1
  const bool spills_left = first >= 2 && before < text.size() &&
                           ((text[before] >= '0' && text[before] <= '9') || text[before] == '.') &&
                           field.front() != ' ';
  if (spills_right || spills_left) {
    // The whole token as written, to show what LMGC90 cuts it to.
    std::size_t begin = static_cast<std::size_t>(first - 1),
                end = std::min(text.size(), static_cast<std::size_t>(last));
    while (begin > 0 && (is_number_char(text[begin - 1]) || text[begin - 1] == '-' || text[begin - 1] == '+'))
      --begin;
    const std::size_t record = std::min(text.size(), kRecordLength);  // not past what LMGC90 reads
    while (end < record && (is_number_char(text[end]) || text[end] == '-' || text[end] == '+')) ++end;
    report("L1011", line, first, last,
           "value '" + std::string(trim(text.substr(begin, end - begin))) + "' spills out of columns " +
               std::to_string(first) + "-" + std::to_string(last) + "; LMGC90 reads '" +
               std::string(trim(field)) + "'",
           "align the value on columns " + std::to_string(first) + "-" + std::to_string(last) +
               " (LMGC90 reads only those columns)");
  }
}

Real CardReader::real(const Line& line, int first, int last, int implied_decimals, bool spill) {
  check_tabs(line, first, last);
  const std::string_view field = columns(line.text, first, last);
  const RealResult r = read_fortran_real(field, implied_decimals);
  if (r.error == NumberError::malformed) {
    report("L1002", line, first, last,
           "'" + std::string(trim(field)) + "' in columns " + std::to_string(first) + "-" +
               std::to_string(last) + " is not a real number",
           "write reals like 0.1000000D+01 or 1.0E+00");
    return Real{0.0, span(line, first, last)};
  }
  if (r.error == NumberError::out_of_range) {
    report("L1003", line, first, last,
           "'" + std::string(trim(field)) + "' is out of the range of a double precision real");
    return Real{0.0, span(line, first, last)};
  }
  // No quantity of an LMGC90 case (lengths, densities, moduli, gravity, velocities, law parameters)
  // comes near this; past it, the products a run forms (masses, inertias, stiffnesses) overflow.
  if (std::abs(r.value) > kLargestMagnitude) {
    report("L1003", line, first, last,
           "'" + std::string(trim(field)) +
               "' is beyond any physical magnitude (|x| > 1e100): the masses, "
               "inertias and stiffnesses a run forms from it overflow");
    return Real{0.0, span(line, first, last)};
  }
  if (spill) check_spill(line, first, last);
  return Real{r.value, span(line, first, last)};
}

Integer CardReader::integer(const Line& line, int first, int last, bool spill) {
  check_tabs(line, first, last);
  const std::string_view field = columns(line.text, first, last);
  const IntegerResult r = read_fortran_integer(field);
  if (r.error == NumberError::malformed) {
    report("L1004", line, first, last,
           "'" + std::string(trim(field)) + "' in columns " + std::to_string(first) + "-" +
               std::to_string(last) + " is not an integer");
    return Integer{0, span(line, first, last)};
  }
  if (r.error == NumberError::out_of_range) {
    report("L1003", line, first, last, "'" + std::string(trim(field)) + "' does not fit a 32-bit integer");
    return Integer{0, span(line, first, last)};
  }
  if (spill) check_spill(line, first, last);
  return Integer{r.value, span(line, first, last)};
}

Word CardReader::word(const Line& line, int first, int last) {
  const std::string_view field = columns(line.text, first, last);
  return Word{std::string(trim_right(field)), span(line, first, last)};
}

std::optional<Integer> CardReader::list_integer(const Line& line, int first, int last,
                                                std::string_view what) {
  const std::string_view field = columns(line.text, first, last);
  auto r = read_list_directed_integer(field);
  if (!r) {
    report(
        "L1015", line, first, last,
        std::string(what) + " is missing in columns " + std::to_string(first) + "-" + std::to_string(last));
    return std::nullopt;
  }
  if (r->error != NumberError::none) {
    report(r->error == NumberError::malformed ? "L1004" : "L1003", line, first, last,
           std::string(what) + " '" + std::string(trim(field)) + "' is not a valid integer");
    return std::nullopt;
  }
  return Integer{r->value, span(line, first, last)};
}

}  // namespace lmgc::grammar
