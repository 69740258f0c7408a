#include "grammar/common/output_file.hpp"

#include <fstream>
#include <system_error>

namespace lmgc::grammar {

bool write_file_whole(const std::filesystem::path& path, const std::string& content, std::string& error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path(), ec);
  const fs::path temporary = path.parent_path() / ("." + path.filename().string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = "cannot write '" + temporary.string() + "'";
      return false;
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      error = "cannot write '" + temporary.string() + "' (disk full?)";
      fs::remove(temporary, ec);
      return false;
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    error = "cannot rename '" + temporary.string() + "' to '" + path.string() + "': " + ec.message();
    fs::remove(temporary, ec);
    return false;
  }
  return true;
}

}  // namespace lmgc::grammar
