// Fuzz target: DRV_DOF.DAT (fuzz/fuzz_target.hpp).
#include <optional>

#include "fuzz/fuzz_target.hpp"
#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lmgc::grammar;
  // LMGC90 writes the echo for the run's modules (the case's dimension and MAILx models), not for
  // what the echo itself holds: the echo of the echo is written with the first file's setup (a 3D
  // mesh that drives no dof echoes as a bare header, which alone would read as a 2D file).
  std::optional<DrvDofEchoSetup> setup;
  return lmgc::fuzz::read_and_round_trip(
      data, size, "DRV_DOF.DAT", [](const SourceText& s, DiagnosticSink& d) { return parse_drv_dof(s, d); },
      [&](const DrvDofFile& f) {
        if (!setup) setup = drv_dof_echo_setup_of(f);
        return write_drv_dof(f, *setup);
      });
}
