#include "validate/render.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace lmgc::validate {
namespace {

constexpr std::string_view kReset = "\033[0m";
constexpr std::string_view kBold = "\033[1m";

std::string_view severity_color(grammar::Severity s) {
  switch (s) {
    case grammar::Severity::error:
      return "\033[1;31m";
    case grammar::Severity::warning:
      return "\033[1;35m";
    case grammar::Severity::note:
      return "\033[1;36m";
  }
  return "";
}

std::string location_text(const grammar::Location& where) {
  if (where.span.line == 0) return where.file;
  return fmt::format("{}:{}:{}", where.file, where.span.line, where.span.column);
}

// Tabs become one blank so the caret lines up with the column count in bytes.
std::string displayable(std::string_view line) {
  std::string out;
  const std::size_t limit = std::min<std::size_t>(line.size(), 240);
  out.reserve(limit);
  for (std::size_t i = 0; i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(line[i]);
    out.push_back(c == '\t' || c == '\r' ? ' ' : (c > 127 ? '?' : static_cast<char>(c)));
  }
  if (line.size() > limit) out += " ...";
  return out;
}

}  // namespace

std::string render_text(const grammar::Diagnostic& d, const LineLookup& lines, TextStyle style) {
  std::string out;
  const std::string_view severity = grammar::severity_name(d.severity);
  if (style.color) {
    out += fmt::format("{}{}:{} {}{}[{}]:{} {}{}{}\n", kBold, location_text(d.where), kReset,
                       severity_color(d.severity), severity, d.code, kReset, kBold, d.message, kReset);
  } else {
    out += fmt::format("{}: {}[{}]: {}\n", location_text(d.where), severity, d.code, d.message);
  }
  if (d.where.span.line > 0 && lines) {
    const std::string_view text = lines(d.where.file, d.where.span.line);
    const std::string gutter = fmt::format("{:>5}", d.where.span.line);
    out += fmt::format("{} | {}\n", gutter, displayable(text));
    if (d.where.span.column > 0 && d.where.span.column <= 241) {
      const std::size_t first = d.where.span.column - 1;
      std::size_t width =
          d.where.span.end_column > d.where.span.column ? d.where.span.end_column - d.where.span.column : 1;
      width = std::min<std::size_t>(width, 60);
      std::string caret(first, ' ');
      caret += '^';
      if (width > 1) caret.append(width - 1, '~');
      out += fmt::format("{} | {}{}{}\n", std::string(gutter.size(), ' '),
                         style.color ? severity_color(d.severity) : "", caret, style.color ? kReset : "");
    }
  }
  for (const auto& r : d.related) out += fmt::format("   note: {}: {}\n", location_text(r.where), r.message);
  if (!d.hint.empty()) out += fmt::format("   hint: {}\n", d.hint);
  return out;
}

std::string render_summary(std::size_t errors, std::size_t warnings, std::size_t notes) {
  std::string s = fmt::format("{} error{}, {} warning{}", errors, errors == 1 ? "" : "s", warnings,
                              warnings == 1 ? "" : "s");
  if (notes > 0) s += fmt::format(", {} note{}", notes, notes == 1 ? "" : "s");
  return s;
}

std::string render_json(const std::vector<grammar::Diagnostic>& diagnostics) {
  nlohmann::json array = nlohmann::json::array();
  for (const auto& d : diagnostics) {
    nlohmann::json related = nlohmann::json::array();
    for (const auto& r : d.related)
      related.push_back({{"file", r.where.file},
                         {"line", r.where.span.line},
                         {"column", r.where.span.column},
                         {"message", r.message}});
    array.push_back({{"file", d.where.file},
                     {"line", d.where.span.line},
                     {"column", d.where.span.column},
                     {"end_column", d.where.span.end_column},
                     {"severity", std::string(grammar::severity_name(d.severity))},
                     {"code", d.code},
                     {"message", d.message},
                     {"related", related},
                     {"hint", d.hint},
                     {"url", "docs/diagnostics.md#" + d.code}});
  }
  // A message may quote bytes of a damaged file that are not UTF-8 (a Latin-1 accent in a colour):
  // replaced by U+FFFD rather than an exception.
  return array.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace lmgc::validate
