#pragma once
// A value read from a fixed-column field, with the place it was read from.
#include <cstdint>
#include <string>

#include "grammar/common/source.hpp"

namespace lmgc::grammar {

template <class T>
struct Field {
  T value{};
  SourceSpan span;  // compares equal always: equality of fields is equality of values

  Field() = default;
  Field(T v) : value(std::move(v)) {}  // NOLINT: implicit, so ASTs can be built from plain values
  Field(T v, SourceSpan s) : value(std::move(v)), span(s) {}
  friend bool operator==(const Field& a, const Field& b) { return a.value == b.value; }
};

using Real = Field<double>;
using Integer = Field<std::int64_t>;
using Word = Field<std::string>;  // fixed-width word, trailing blanks removed

}  // namespace lmgc::grammar
