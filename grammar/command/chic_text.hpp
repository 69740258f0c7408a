#pragma once
// Small text helpers shared by the COMMAND.DAT parser and its interpreter (internal).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/fortran_number.hpp"
#include "grammar/common/list_directed.hpp"

namespace lmgc::grammar::chic {

using grammar::list_items;

inline bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

// Characters first.. (0-based) of a significant text, as CHIC cuts CHZZZ(k:30).
inline std::string_view from(std::string_view text, std::size_t first) {
  return first < text.size() ? text.substr(first) : std::string_view();
}

inline std::string_view trim_blanks(std::string_view text) {
  const auto b = text.find_first_not_of(' ');
  if (b == std::string_view::npos) return {};
  const auto e = text.find_last_not_of(' ');
  return text.substr(b, e - b + 1);
}

// READ(text,*) of one integer: nullopt when missing or malformed.
inline std::optional<std::int64_t> list_integer(std::string_view text) {
  const auto items = list_items(text);
  if (items.empty()) return std::nullopt;
  const auto value = read_list_directed_integer(items[0]);
  if (!value || value->error != NumberError::none) return std::nullopt;
  return value->value;
}

// 'REPETE n FOIS': the count, read from columns 7-30 with the first 'FOIS' blanked.
inline std::optional<std::int64_t> repete_count(std::string_view text) {
  std::string rest(from(text, 6));
  const auto fois = rest.find("FOIS");
  if (fois == std::string::npos) return std::nullopt;
  rest.replace(fois, 4, "    ");
  return list_integer(rest);
}

// 'FLAG f = IOK' / 'DRAP f = ROK': f, read from columns 5-30 with the first '= IOK' blanked.
inline std::optional<std::int64_t> flag_number(std::string_view text, std::string_view marker) {
  std::string rest(from(text, 4));
  const auto at = rest.find(marker);
  if (at == std::string::npos) return std::nullopt;
  rest.replace(at, marker.size(), std::string(marker.size(), ' '));
  return list_integer(rest);
}

}  // namespace lmgc::grammar::chic
