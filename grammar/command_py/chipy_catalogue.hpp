#pragma once
// The chipy functions LMGC90's command.py scripts call, in one table: what lmgc-solve does with
// each when it stands for the script (its parameters compared and recorded, an output written, a
// feature not run yet). Exact names first, then families by prefix or by part of the name.
#include <span>
#include <string_view>

#include "grammar/command/catalogue.hpp"

namespace lmgc::grammar {

enum class ChipyMatch : std::uint8_t { exact, prefix, contains };

struct ChipyFunction {
  std::string_view name;
  ChipyMatch match;
  CommandSupport support;
  std::string_view what;  // for the diagnostic: what the call does that lmgc-solve does not
};

std::span<const ChipyFunction> chipy_catalogue();
// The entry for a call name (an exact entry before a family); nullptr when lmgc does not know it.
const ChipyFunction* find_chipy_function(std::string_view name);

}  // namespace lmgc::grammar
