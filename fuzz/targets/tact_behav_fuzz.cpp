// Fuzz target: TACT_BEHAV.DAT (fuzz/fuzz_target.hpp); its echo sorts the rows as LMGC90 does.
#include "fuzz/fuzz_target.hpp"
#include "grammar/tact_behav/parser.hpp"
#include "grammar/tact_behav/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "TACT_BEHAV.DAT",
      [](const SourceText& s, DiagnosticSink& d) { return parse_tact_behav(s, d); },
      [](const TactBehavFile& f) { return write_tact_behav(f); }, /*any_line_order=*/true);
}
