// Fuzz target: DRV_DOF.DAT (fuzz/fuzz_target.hpp).
#include "fuzz/fuzz_target.hpp"
#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "DRV_DOF.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_drv_dof(s, d); },
      [](const DrvDofFile& f) { return write_drv_dof(f); });
}
