#include "grammar/common/exact_state_header.hpp"

#include <cstdio>
#include <cstdlib>

namespace lmgc::grammar {

std::string exact_state_header_line(const ExactStateHeader& h) {
  char line[256];
  std::snprintf(line, sizeof line, "%.*s dimension %d step %ld time %a bodies %zu\n",
                static_cast<int>(kExactStateMagic.size()), kExactStateMagic.data(), h.dimension, h.step,
                h.time, h.bodies);
  return line;
}

std::optional<ExactStateHeader> read_exact_state_header(std::string_view bytes) {
  const std::size_t end = bytes.find('\n');
  if (end == std::string_view::npos || end > 250 ||
      bytes.substr(0, kExactStateMagic.size()) != kExactStateMagic)
    return std::nullopt;
  const std::string line(bytes.substr(kExactStateMagic.size(), end - kExactStateMagic.size()));
  ExactStateHeader h;
  char time_text[64] = {};
  if (std::sscanf(line.c_str(), " dimension %d step %ld time %63s bodies %zu", &h.dimension, &h.step,
                  time_text, &h.bodies) != 4)
    return std::nullopt;
  char* stop = nullptr;
  h.time = std::strtod(time_text, &stop);
  if (stop == time_text || *stop != '\0' || (h.dimension != 2 && h.dimension != 3)) return std::nullopt;
  return h;
}

}  // namespace lmgc::grammar
