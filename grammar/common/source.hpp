#pragma once
// Source text of one input file, split into Fortran records (lines), and positions in it.
// docs/lmgc90-facts/datbox-inputs.md §0 (records of 180 characters, CRLF accepted, comments in column 1).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lmgc::grammar {

// Position of a value in its file: 1-based line, 1-based first and one-past-last byte column.
// Spans are metadata: two spans always compare equal, so ASTs compare by value only.
// Columns are 16-bit (LMGC90 reads 180 columns; longer lines are clamped), which keeps a span
// at 8 bytes: every value of an AST carries one.
struct SourceSpan {
  std::uint32_t line = 0;
  std::uint16_t column = 0;
  std::uint16_t end_column = 0;
  friend bool operator==(const SourceSpan&, const SourceSpan&) { return true; }
};

// Span of columns first..last (1-based, inclusive) of a line, clamped to 16-bit columns.
inline SourceSpan make_span(std::uint32_t line, std::size_t first, std::size_t last) {
  auto clamp = [](std::size_t c) { return static_cast<std::uint16_t>(c > 65535 ? 65535 : c); };
  return SourceSpan{line, clamp(first), clamp(last + 1)};
}

// One record of the file: the bytes of the line without its terminator ("\n" or "\r\n").
struct Line {
  std::string_view text;
  std::uint32_t number = 0;  // 1-based line number
};

// LMGC90 reads records as A180: columns past 180 are not seen.
inline constexpr std::size_t kRecordLength = 180;

class SourceText {
 public:
  SourceText() = default;
  SourceText(std::string path, std::string text);
  // Lines view the text: a copy or a move points them at its own text (a short text lives inside
  // the string object, so a moved-from buffer is not the moved-to one).
  SourceText(const SourceText& other);
  SourceText(SourceText&& other) noexcept;
  SourceText& operator=(const SourceText& other);
  SourceText& operator=(SourceText&& other) noexcept;
  ~SourceText() = default;

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  const std::vector<Line>& lines() const { return lines_; }
  // The line with this 1-based number (empty view when out of range).
  std::string_view line_text(std::uint32_t number) const;
  // True when the file ended without a final newline (kept so a writer can decide).
  bool has_final_newline() const { return final_newline_; }

 private:
  void rebase(const char* old_text);

  std::string path_;
  std::string text_;
  std::vector<Line> lines_;
  bool final_newline_ = true;
};

}  // namespace lmgc::grammar
