// Fuzz target: evolution (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "evolution", [](const SourceText& s, DiagnosticSink& d) { return parse_evolution(s, d); },
      [](const EvolutionFile& f) { return write_evolution(f); });
}
