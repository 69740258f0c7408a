// Fuzz target: PTPT3_NETWORK.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/ptpt3_network/parser.hpp"
#include "grammar/ptpt3_network/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "PTPT3_NETWORK.DAT",
      [](const SourceText& s, DiagnosticSink& d) { return parse_ptpt3_network(s, d); },
      [](const Ptpt3NetworkFile& f) { return write_ptpt3_network(f); });
}
