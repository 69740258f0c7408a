// lmgc-check on every LMGC90 example case: no error (the examples run in LMGC90).
#include <gtest/gtest.h>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

TEST(LmgcCheckExamples, EveryExampleCaseChecksWithoutError) {
  LMGC_REQUIRE_SHARED();
  const auto cases = example_cases();
  ASSERT_GE(cases.size(), 20u);
  for (const auto& dir : cases) {
    SCOPED_TRACE(case_name(dir));
    const ToolRun run = run_tool("lmgc-check", "'" + dir.string() + "' --quiet --no-color");
    EXPECT_EQ(run.exit_code, 0) << run.output;
  }
}

// `lmgc-check --echo` writes LMGC90's echo files byte for byte: every echo file LMGC90 wrote for an
// example (reference_lmgc90/OUTBOX/*.OUT but the state files and TIMER.OUT) is compared with the
// tool's, on a copy of the example. BODIES.OUT of the rigid cases carries LMGC90's pre-computations
// (avrd, gyrd, centre and principal frame of inertia), DRV_DOF.OUT the modules of BODIES.DAT.
TEST(LmgcCheckExamples, EchoFilesAreLmgc90sByteForByte) {
  LMGC_REQUIRE_SHARED();
  namespace fs = std::filesystem;
  int compared = 0;
  for (const auto& example : example_cases()) {
    const fs::path reference = example / "reference_lmgc90" / "OUTBOX";
    if (!fs::is_directory(reference)) continue;
    SCOPED_TRACE(case_name(example));
    const fs::path dir = scratch_dir("echo_" + example.filename().string());
    fs::copy(example / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
    ASSERT_EQ(run_tool("lmgc-check", "'" + dir.string() + "' --quiet --echo").exit_code, 0);
    for (const auto& entry : fs::directory_iterator(reference)) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".OUT" || name == "TIMER.OUT" || name.rfind("DOF.", 0) == 0 ||
          name.rfind("Vloc_Rloc.", 0) == 0 || name.rfind("GPV.", 0) == 0)
        continue;
      const fs::path ours = dir / "OUTBOX" / name;
      ASSERT_TRUE(fs::exists(ours)) << name << " not written";
      EXPECT_TRUE(read_file(ours) == read_file(entry.path())) << name << " differs from LMGC90's";
      ++compared;
    }
  }
  EXPECT_GE(compared, 60);
}

}  // namespace
}  // namespace lmgc::test
