// Fuzz target: POSTPRO.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/postpro/parser.hpp"
#include "grammar/postpro/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "POSTPRO.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_postpro(s, d); },
      [](const PostproFile& f) { return write_postpro(f); });
}
