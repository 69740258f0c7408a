#pragma once
// Fortran list-directed input: the items of a record, as READ(*,*) splits them.
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

#include "grammar/common/source.hpp"

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

// The items of a record with their columns, for diagnostics: separated by blanks, tabs or
// commas, '/' ends the record, nothing past column 180 is read.
struct Token {
  std::string_view text;
  int first = 0;  // 1-based columns
  int last = 0;
};

inline std::vector<Token> list_tokens(std::string_view text) {
  std::vector<Token> tokens;
  const std::size_t size = text.size() < kRecordLength ? text.size() : kRecordLength;
  std::size_t i = 0;
  while (i < size) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == ',') {
      ++i;
      continue;
    }
    if (c == '/') break;
    const std::size_t begin = i;
    while (i < size && text[i] != ' ' && text[i] != '\t' && text[i] != ',' && text[i] != '/') ++i;
    tokens.push_back(Token{text.substr(begin, i - begin), static_cast<int>(begin) + 1, static_cast<int>(i)});
  }
  return tokens;
}

}  // namespace lmgc::grammar
