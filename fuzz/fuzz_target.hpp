#pragma once
// One fuzz target per file grammar: the bytes are read as that file; reading never crashes, hangs
// or leaks, and when a text reads without any diagnostic, its echo (what the writer makes of it, in
// LMGC90's layout: reals to 7 digits) reads without error and is a fixed point: the echo of the echo
// is the echo. Built two ways (fuzz/CMakeLists.txt): with
// libFuzzer (clang, scripts/fuzz.sh) and with fuzz/replay_main.cpp, a corpus replay and a seeded
// mutation loop that CI runs in the sanitized build.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::fuzz {

// Stops the process with a message naming the broken promise (libFuzzer then saves the input).
[[noreturn]] inline void broken(const char* what) {
  std::fprintf(stderr, "lmgc fuzz: %s\n", what);
  std::abort();
}

// The same lines, in any order: TACT_BEHAV.OUT's '$seety' rows come in the order of LMGC90's
// sort_see_ll, which depends on the order it reads them in (its echo of its own echo may differ).
inline bool same_lines(const std::string& a, const std::string& b) {
  const auto lines = [](const std::string& text) {
    std::vector<std::string> out;
    std::size_t begin = 0;
    for (std::size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
      out.push_back(text.substr(begin, end - begin));
    out.push_back(text.substr(begin));
    std::sort(out.begin(), out.end());
    return out;
  };
  return lines(a) == lines(b);
}

template <class Parse, class Write>
int read_and_round_trip(const std::uint8_t* data, std::size_t size, const char* name, Parse parse,
                        Write write, bool any_line_order = false) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  grammar::DiagnosticSink sink;
  const auto file = parse(grammar::SourceText(name, text), sink);
  if (!sink.items().empty() || sink.truncated()) return 0;
  const std::string echo = write(file);
  grammar::DiagnosticSink again_sink;
  const auto again = parse(grammar::SourceText(name, echo), again_sink);
  if (again_sink.has_errors()) broken("the echo of a clean file does not read without error");
  const std::string echo_of_echo = write(again);
  if (any_line_order ? !same_lines(echo_of_echo, echo) : echo_of_echo != echo)
    broken("write(parse(echo)) differs from the echo");
  return 0;
}

}  // namespace lmgc::fuzz
