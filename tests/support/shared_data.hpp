#pragma once
// Access to ../shared (LMGC90's example cases and reference outputs). The folder is beside the
// project in the developers' and CI's checkouts, and absent in a user's clone: tests that need
// it call LMGC_REQUIRE_SHARED() and are skipped with the path they looked for.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lmgc::test {

inline std::filesystem::path shared_dir() {
  if (const char* env = std::getenv("LMGC_SHARED_DIR")) return env;
  return std::filesystem::path(LMGC_SOURCE_DIR).parent_path() / "shared";
}

inline std::filesystem::path examples_dir() {
  return shared_dir() / "lmgc90-examples";
}

inline bool shared_available() {
  return std::filesystem::is_directory(examples_dir());
}

#define LMGC_REQUIRE_SHARED()                                                            \
  do {                                                                                   \
    if (!::lmgc::test::shared_available())                                               \
      GTEST_SKIP() << "LMGC90 example set not found at " << ::lmgc::test::examples_dir() \
                   << " (set LMGC_SHARED_DIR or place shared/ beside the project)";      \
  } while (0)

// Every example case folder (the parent of a DATBOX/), sorted.
inline std::vector<std::filesystem::path> example_cases() {
  std::vector<std::filesystem::path> cases;
  if (!shared_available()) return cases;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(examples_dir()))
    if (entry.is_directory() && entry.path().filename() == "DATBOX")
      cases.push_back(entry.path().parent_path());
  std::sort(cases.begin(), cases.end());
  return cases;
}

// Example DATBOX files with this exact name, sorted.
inline std::vector<std::filesystem::path> example_files(const std::string& name) {
  std::vector<std::filesystem::path> files;
  for (const auto& c : example_cases())
    if (std::filesystem::is_regular_file(c / "DATBOX" / name)) files.push_back(c / "DATBOX" / name);
  return files;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// "RIGID_2D/1024DK_BoxJC" for a case folder.
inline std::string case_name(const std::filesystem::path& case_dir) {
  return case_dir.parent_path().filename().string() + "/" + case_dir.filename().string();
}

}  // namespace lmgc::test
