#include "grammar/common/output_file.hpp"

#include <fstream>
#include <system_error>
#include <vector>

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

std::size_t remove_stale_temporaries(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::size_t removed = 0;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code type_ec;
    if (name.size() > 5 && name.front() == '.' && name.ends_with(".tmp") && it->is_regular_file(type_ec))
      stale.push_back(it->path());
  }
  for (const fs::path& path : stale) removed += fs::remove(path, ec) ? 1 : 0;
  return removed;
}

}  // namespace lmgc::grammar
