// Fuzz target: Vloc_Rloc.INI (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "Vloc_Rloc.INI",
      [](const SourceText& s, DiagnosticSink& d) { return parse_vloc_rloc(s, d); },
      [](const VlocRlocFile& f) { return write_vloc_rloc(f); });
}
