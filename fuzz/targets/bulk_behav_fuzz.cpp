// Fuzz target: BULK_BEHAV.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "BULK_BEHAV.DAT",
      [](const SourceText& s, DiagnosticSink& d) { return parse_bulk_behav(s, d); },
      [](const BulkBehavFile& f) { return write_bulk_behav(f); });
}
