// Fuzz target: an FCLIB problem file (HDF5). The bytes are written to a file and read; a refusal is
// an FclibError, anything else (a crash, a leak, a hang) is a finding. Errors inside the HDF5
// library itself are HDF5's: scripts/fuzz.sh reports them apart.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "solver/io/fclib/fclib_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("lmgc_fclib_fuzz_" + std::to_string(::getpid()) + ".hdf5"))
          .string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    lmgc::solver::read_fclib_local(path);
  } catch (const lmgc::solver::FclibError&) {
  }
  return 0;
}
