// Fuzz target: MODELS.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "MODELS.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_models(s, d); },
      [](const ModelsFile& f) { return write_models(f); });
}
