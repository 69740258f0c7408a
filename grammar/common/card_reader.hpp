#pragma once
// Reading fixed-column cards: the record rules shared by every LMGC90 reader
// (docs/lmgc90-facts/datbox-inputs.md §0): comment lines ('!' or '#' in column 1) and blank lines are
// skipped, keywords sit in columns 2-6, values are read from fixed column ranges.
#include <optional>
#include <string>
#include <string_view>

#include "grammar/common/diagnostic.hpp"
#include "grammar/common/field.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::grammar {

// The largest magnitude a real of a case file may have (L1003 above it).
inline constexpr double kLargestMagnitude = 1e100;

// Columns `first`..`last` (1-based, inclusive) of a record, blank where the line is shorter
// and never past column 180 (LMGC90's record length).
std::string_view columns(std::string_view line, int first, int last);

// The 5-character keyword of columns 2-6.
std::string_view keyword_of(std::string_view line);

// True for a comment line ('!' or '#' in column 1) or an all-blank line.
bool is_skipped_line(std::string_view line);

class CardReader {
 public:
  CardReader(const SourceText& source, DiagnosticSink& sink);

  const SourceText& source() const { return source_; }
  DiagnosticSink& sink() { return sink_; }

  // Record-level checks, once per file: non-ASCII bytes, text past column 180, empty file.
  // Returns false when the file holds no significant line (after reporting L1009, unless the
  // file kind may be empty: LMGC90 reads a DRV_DOF.DAT without any body as "nothing driven").
  enum class Empty { error, allowed };
  bool check_records(Empty empty = Empty::error);

  // Cursor over significant lines (comments and blanks skipped).
  bool at_end() const;
  const Line& peek() const;  // requires !at_end()
  const Line& next();        // requires !at_end()
  std::size_t position() const { return index_; }
  void rewind_to(std::size_t position) { index_ = position; }
  void skip_insignificant();

  // Field readers. They report malformed values (and values spilling out of their columns)
  // and return 0 / blank for them, so parsing can go on.
  Real real(const Line& line, int first, int last, int implied_decimals = 7, bool check_spill = true);
  Integer integer(const Line& line, int first, int last, bool check_spill = true);
  Word word(const Line& line, int first, int last);
  // List-directed integer from columns first..last; reports L1015 and returns nullopt when blank.
  std::optional<Integer> list_integer(const Line& line, int first, int last, std::string_view what);

  SourceSpan span(const Line& line, int first, int last) const;
  void report(std::string_view code, const Line& line, int first, int last, std::string message,
              std::string hint = {});
  void report_at_end(std::string_view code, std::string message);
  Location location(const Line& line, int first, int last) const;

 private:
  void check_tabs(const Line& line, int first, int last);
  void check_spill(const Line& line, int first, int last);

  const SourceText& source_;
  DiagnosticSink& sink_;
  std::size_t index_ = 0;  // index into source_.lines()
};

}  // namespace lmgc::grammar
