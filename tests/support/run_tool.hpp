#pragma once
// Running a built command-line program from a test: exit code and standard output.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace lmgc::test {

struct ToolRun {
  int exit_code = -1;
  std::string output;  // standard output (standard error is discarded)
};

inline std::filesystem::path tool_path(const std::string& name) {
  return std::filesystem::path(LMGC_BINARY_DIR) / "tools" / name;
}

inline ToolRun run_tool(const std::string& name, const std::string& arguments) {
  ToolRun run;
  const std::string command = "'" + tool_path(name).string() + "' " + arguments + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// As run_tool, with standard error in `output` too (after standard output), and `prefix` before
// the tool's path (a `cd` to run it from another folder, a `ulimit`, ...).
inline ToolRun run_tool_both_streams(const std::string& name, const std::string& arguments,
                                     const std::string& prefix = "") {
  ToolRun run;
  const std::string command = prefix + "'" + tool_path(name).string() + "' " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// A fresh empty folder under the build tree, removed first if it exists.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(LMGC_BINARY_DIR) / "test_scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A scratch folder holding a copy of the shipped default case's DATBOX/ (never the original).
inline std::filesystem::path default_case_copy(const std::string& name) {
  const auto dir = scratch_dir(name);
  std::filesystem::copy(
      std::filesystem::path(LMGC_SOURCE_DIR) / "reference_cases" / "disk_bounce_rst" / "DATBOX",
      dir / "DATBOX", std::filesystem::copy_options::recursive);
  return dir;
}

}  // namespace lmgc::test
