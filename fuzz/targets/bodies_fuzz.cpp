// Fuzz target: BODIES.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/bodies/parser.hpp"
#include "grammar/bodies/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "BODIES.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_bodies(s, d); },
      [](const BodiesFile& f) { return write_bodies(f); });
}
