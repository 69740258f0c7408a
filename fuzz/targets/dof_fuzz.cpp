// Fuzz target: DOF.INI (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/dof/parser.hpp"
#include "grammar/dof/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "DOF.INI", [](const SourceText& s, DiagnosticSink& d) { return parse_dof(s, d); },
      [](const DofFile& f) { return write_dof(f); });
}
