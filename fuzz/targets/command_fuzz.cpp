// Fuzz target: COMMAND.DAT (fuzz/fuzz_target.hpp), then CHIC's compilation and a bounded run of it.
#include "fuzz/fuzz_target.hpp"
#include "grammar/command/expand.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/command/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  lmgc::fuzz::read_and_round_trip(
      data, size, "COMMAND.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_command(s, d); },
      [](const CommandFile& f) { return write_command(f); });
  DiagnosticSink sink;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const CommandFile file = parse_command(SourceText("COMMAND.DAT", text), sink);
  expand_command_program(file, 20000, sink);
  return 0;
}
