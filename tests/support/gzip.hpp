#pragma once
// Reading a possibly gzip-compressed reference file (several LMGC90 outputs are stored .gz).
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "tests/support/shared_data.hpp"

namespace lmgc::test {

// The decompressed content of `path` (".gz" through `gzip -dc`), or the file itself.
inline std::string read_maybe_gzip(const std::filesystem::path& path) {
  if (path.extension() != ".gz") return read_file(path);
  std::string out;
  FILE* pipe = popen(("gzip -dc '" + path.string() + "'").c_str(), "r");
  if (!pipe) return out;
  std::array<char, 65536> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  pclose(pipe);
  return out;
}

}  // namespace lmgc::test
