#pragma once
// Rendering diagnostics for people (compiler style, with the source line and a caret) and for
// programs (one JSON array). spec of the JSON schema: docs/diagnostics.md.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/diagnostic.hpp"

namespace lmgc::validate {

// Returns the text of line `line` of `file`, or an empty view when unknown.
using LineLookup = std::function<std::string_view(const std::string& file, std::uint32_t line)>;

struct TextStyle {
  bool color = false;
};

// FILE:LINE:COL: severity[CODE]: message, then the source line and a caret under the span,
// then related positions ("note:") and the hint ("hint:").
std::string render_text(const grammar::Diagnostic& diagnostic, const LineLookup& lines, TextStyle style);

// "N errors, M warnings" (plus notes when any).
std::string render_summary(std::size_t errors, std::size_t warnings, std::size_t notes);

// The JSON array of all diagnostics (fields: file, line, column, end_column, severity, code,
// message, related[{file,line,column,message}], hint, url).
std::string render_json(const std::vector<grammar::Diagnostic>& diagnostics);

}  // namespace lmgc::validate
