#include "grammar/common/diagnostic.hpp"

#include "grammar/common/diagnostic_catalogue.hpp"

namespace lmgc::grammar {

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::note:
      return "note";
    case Severity::warning:
      return "warning";
    case Severity::error:
      return "error";
  }
  return "error";
}

void DiagnosticSink::report(std::string_view code, Location where, std::string message, std::string hint) {
  const DiagnosticKind* kind = find_diagnostic_kind(code);
  Diagnostic d;
  d.code = std::string(code);
  d.severity = kind ? kind->severity : Severity::error;
  d.where = std::move(where);
  d.message = std::move(message);
  d.hint = std::move(hint);
  report(std::move(d));
}

void DiagnosticSink::report(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::error) ++errors_;
  if (diagnostic.severity == Severity::warning) ++warnings_;
  if (items_.size() >= limit_) {
    ++dropped_;
    return;
  }
  items_.push_back(std::move(diagnostic));
}

void DiagnosticSink::clear() {
  items_.clear();
  errors_ = warnings_ = dropped_ = 0;
}

}  // namespace lmgc::grammar
