#pragma once
// Output files are written whole: to a temporary name in the same folder, then renamed, so an
// interrupted run leaves the previous complete file.
#include <filesystem>
#include <string>

namespace lmgc::grammar {

bool write_file_whole(const std::filesystem::path& path, const std::string& content, std::string& error);

}  // namespace lmgc::grammar
