// cmake --install puts lmgc where a user's project finds it: the programs run from the prefix and a
// program built with find_package(lmgc) against it links and runs (tests/install_consumer/).
#include <gtest/gtest.h>

#include <array>

#include "tests/support/run_tool.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// The command's exit code and output (standard error included).
ToolRun run_command(const std::string& command) {
  ToolRun run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

TEST(Install, AProjectBuildsAgainstTheInstalledPackage) {
#ifdef LMGC_SANITIZED_BUILD
  GTEST_SKIP() << "the sanitized libraries need the sanitizer runtime in the consumer";
#endif
  const fs::path prefix = scratch_dir("install_prefix");
  const fs::path consumer = scratch_dir("install_consumer");
  const ToolRun install = run_command("cmake --install '" + std::string(LMGC_BINARY_DIR) + "' --prefix '" +
                                      prefix.string() + "'");
  ASSERT_EQ(install.exit_code, 0) << install.output;
  for (const char* file : {"bin/lmgc-check", "bin/lmgc-solve", "include/lmgc/grammar/dof/parser.hpp",
                           "lib/cmake/lmgc/lmgcConfig.cmake", "share/doc/lmgc/LICENSE"})
    EXPECT_TRUE(fs::exists(prefix / file) || fs::exists(prefix / "lib64" / fs::path(file).filename()))
        << file;
  const ToolRun version = run_command("'" + (prefix / "bin" / "lmgc-solve").string() + "' --version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("lmgc-solve 0.1.0 (revision "), std::string::npos) << version.output;
  const ToolRun configure = run_command(
      "cmake -S '" + std::string(LMGC_SOURCE_DIR) + "/tests/install_consumer' -B '" + consumer.string() +
      "' -DCMAKE_PREFIX_PATH='" + prefix.string() + "' -DCMAKE_BUILD_TYPE=Release");
  ASSERT_EQ(configure.exit_code, 0) << configure.output;
  const ToolRun build = run_command("cmake --build '" + consumer.string() + "'");
  ASSERT_EQ(build.exit_code, 0) << build.output;
  const ToolRun run = run_command("'" + (consumer / "consumer").string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("step 12, pi_g 3.1415927410"), std::string::npos) << run.output;
}

// The installed lmgc-run runs a script with the installed module; the forwarding pylmgc90 package
// is installed off Python's default path, so that `import pylmgc90` outside lmgc-run still means a
// real LMGC90 (or nothing).
TEST(Install, LmgcRunRunsFromThePrefixAndPylmgc90IsNotShadowed) {
#ifdef LMGC_SANITIZED_BUILD
  GTEST_SKIP() << "a sanitized build has no Python module";
#endif
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path prefix = scratch_dir("install_prefix_python");
  const ToolRun install = run_command("cmake --install '" + std::string(LMGC_BINARY_DIR) + "' --prefix '" +
                                      prefix.string() + "'");
  ASSERT_EQ(install.exit_code, 0) << install.output;
  EXPECT_TRUE(fs::exists(prefix / "lib" / "python3" / "dist-packages" / "lmgc" / "chipy" / "__init__.py"));
  EXPECT_FALSE(fs::exists(prefix / "lib" / "python3" / "dist-packages" / "pylmgc90"));
  EXPECT_TRUE(fs::exists(prefix / "lib" / "lmgc" / "forward" / "pylmgc90" / "chipy" / "__init__.py"));
  const fs::path dir = scratch_dir("install_lmgc_run");
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "script_driven_pusher", dir,
           fs::copy_options::recursive);
  const ToolRun run = run_command("'" + (prefix / "bin" / "lmgc-run").string() + "' '" + dir.string() +
                                  "' --quiet --max-steps 20");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
  // With the installed packages' folder on the path, pylmgc90 is not lmgc's.
  const ToolRun plain = run_command(
      "PYTHONPATH='" + (prefix / "lib" / "python3" / "dist-packages").string() +
      "' /usr/bin/python3 -c \"import importlib.util, lmgc.chipy; s = importlib.util.find_spec('pylmgc90'); "
      "print('pylmgc90 at', s.origin if s else None)\"");
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_NE(plain.output.find("pylmgc90 at "), std::string::npos) << plain.output;
  EXPECT_EQ(plain.output.find(prefix.string()), std::string::npos) << plain.output;
}

}  // namespace
}  // namespace lmgc::test
