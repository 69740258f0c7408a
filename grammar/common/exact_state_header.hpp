#pragma once
// The first line of lmgc's exact restart state (OUTBOX/EXACT_STATE.LAST, DATBOX/EXACT_STATE.INI):
// "lmgc exact state 1 dimension D step N time T bodies B", T a hexadecimal float (exact). The rest
// of the file is binary (solver/io/exact_state.hpp); the checks read only this line.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace lmgc::grammar {

inline constexpr std::string_view kExactStateMagic = "lmgc exact state 1";

struct ExactStateHeader {
  int dimension = 0;
  long step = 0;
  double time = 0.0;
  std::size_t bodies = 0;
};

std::string exact_state_header_line(const ExactStateHeader& header);
// nullopt when the bytes do not start with such a line.
std::optional<ExactStateHeader> read_exact_state_header(std::string_view bytes);

}  // namespace lmgc::grammar
