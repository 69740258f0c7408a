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
  const bool error = diagnostic.severity == Severity::error;
  if (error) ++errors_;
  if (diagnostic.severity == Severity::warning) ++warnings_;
  const auto count_dropped = [this](Severity severity) {
    ++(severity == Severity::error     ? dropped_errors_
       : severity == Severity::warning ? dropped_warnings_
                                       : dropped_notes_);
  };
  if (items_.size() >= limit_) {
    if (!error || stored_errors_ == items_.size()) {
      count_dropped(diagnostic.severity);
      return;
    }
    // Make room by the latest warning or note.
    auto it = items_.end();
    do --it;
    while (it->severity == Severity::error);
    count_dropped(it->severity);
    items_.erase(it);
  }
  if (error) ++stored_errors_;
  items_.push_back(std::move(diagnostic));
}

std::vector<Diagnostic> DiagnosticSink::overflow_diagnostic() const {
  if (!truncated()) return {};
  Diagnostic d;
  d.code = "L9004";
  d.severity = dropped_errors_ > 0 ? Severity::error : Severity::warning;
  d.message = std::to_string(dropped_errors_) + " error(s), " + std::to_string(dropped_warnings_) +
              " warning(s) and " + std::to_string(dropped_notes_) + " note(s) not shown: only the first " +
              std::to_string(limit_) + " diagnostics are kept, errors before warnings and notes";
  d.hint = "fix the errors shown and check again";
  return {d};
}

void DiagnosticSink::clear() {
  items_.clear();
  errors_ = warnings_ = stored_errors_ = 0;
  dropped_errors_ = dropped_warnings_ = dropped_notes_ = 0;
}

}  // namespace lmgc::grammar
