#pragma once
// Output files are written whole: to a temporary name in the same folder, then renamed, so an
// interrupted run leaves the previous complete file.
#include <filesystem>
#include <string>

namespace lmgc::grammar {

bool write_file_whole(const std::filesystem::path& path, const std::string& content, std::string& error);

// Removes the temporaries a killed run may have left in `folder` ('.NAME.tmp', never a final name):
// called before a run writes there. Returns how many were removed.
std::size_t remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace lmgc::grammar
