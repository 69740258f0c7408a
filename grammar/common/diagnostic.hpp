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

// Collects diagnostics in emission order. Limits the count so a hostile file cannot
// exhaust memory; the overflow is itself reported once.
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
  bool truncated() const { return dropped_ > 0; }
  void clear();

 private:
  std::vector<Diagnostic> items_;
  std::size_t limit_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t dropped_ = 0;
};

}  // namespace lmgc::grammar
