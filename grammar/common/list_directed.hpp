#pragma once
// Fortran list-directed input: the items of a record, as READ(*,*) splits them.
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

namespace lmgc::grammar {

// The first `wanted` items of a list-directed record: separated by blanks or one comma, the
// record ended by '/'.
inline std::vector<std::string_view> list_items(
    std::string_view text, std::size_t wanted = std::numeric_limits<std::size_t>::max()) {
  std::vector<std::string_view> items;
  std::size_t p = 0;
  while (items.size() < wanted && p < text.size()) {
    while (p < text.size() && (text[p] == ' ' || text[p] == '\t')) ++p;
    if (p >= text.size() || text[p] == '/') break;
    if (text[p] == ',') {
      ++p;
      continue;
    }
    const std::size_t begin = p;
    while (p < text.size() && text[p] != ' ' && text[p] != '\t' && text[p] != ',' && text[p] != '/') ++p;
    items.push_back(text.substr(begin, p - begin));
  }
  return items;
}

}  // namespace lmgc::grammar
