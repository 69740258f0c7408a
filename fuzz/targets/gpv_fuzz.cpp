// Fuzz target: GPV.INI (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/gpv/parser.hpp"
#include "grammar/gpv/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "GPV.INI", [](const SourceText& s, DiagnosticSink& d) { return parse_gpv(s, d); },
      [](const GpvFile& f) { return write_gpv(f); });
}
