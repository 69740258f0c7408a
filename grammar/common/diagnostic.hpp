#pragma once
// A diagnostic is data: checks emit into a DiagnosticSink, only the command-line tools render.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/source.hpp"

namespace lmgc::grammar {

enum class Severity { note, warning, error };

std::string_view severity_name(Severity severity);

struct Location {
  std::string file;  // path as given to the tool
  SourceSpan span;   // line 0 = the whole file
};

struct RelatedLocation {
  Location where;
  std::string message;
};

struct Diagnostic {
  std::string code;  // stable code, e.g. "L1002" (see diagnostic_catalogue.hpp)
  Severity severity = Severity::error;
  Location where;
  std::string message;  // no leading capital, no final period
  std::vector<RelatedLocation> related;
  std::string hint;
};

// Collects diagnostics in emission order. Limits the count so a hostile file cannot exhaust
// memory. When the limit is reached, an error still takes the place of the latest stored warning
// or note, so no error is lost while a warning is kept; what could not be kept is counted by
// severity and stated by overflow_diagnostic() (L9004).
class DiagnosticSink {
 public:
  explicit DiagnosticSink(std::size_t limit = 1000) : limit_(limit) {}

  // Reports with the catalogue's default severity for `code`.
  void report(std::string_view code, Location where, std::string message, std::string hint = {});
  void report(Diagnostic diagnostic);

  const std::vector<Diagnostic>& items() const { return items_; }
  std::size_t error_count() const { return errors_; }
  std::size_t warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ > 0; }
  bool truncated() const { return dropped_errors_ + dropped_warnings_ + dropped_notes_ > 0; }
  std::size_t dropped_errors() const { return dropped_errors_; }
  // L9004 "diagnostics not shown", with the counts left out by severity; empty when none was.
  std::vector<Diagnostic> overflow_diagnostic() const;
  void clear();

 private:
  std::vector<Diagnostic> items_;
  std::size_t limit_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t stored_errors_ = 0;
  std::size_t dropped_errors_ = 0, dropped_warnings_ = 0, dropped_notes_ = 0;
};

}  // namespace lmgc::grammar
