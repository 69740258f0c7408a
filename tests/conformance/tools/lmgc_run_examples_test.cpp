// Every rigid example's own command.py, run unchanged by lmgc-run (lmgc's chipy module), ends its
// first steps with the same DOF.LAST and Vloc_Rloc.LAST, byte for byte, as lmgc-solve's own loop
// with the parameters the script passes (--read-script), and the same POSTPRO files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

fs::path case_copy(const fs::path& example, const std::string& tag) {
  const fs::path dir = scratch_dir("lmgc_run_" + tag + "_" + example.filename().string());
  for (const auto& entry : fs::directory_iterator(example))
    if (entry.path().filename() != "reference_lmgc90")
      fs::copy(entry.path(), dir / entry.path().filename(), fs::copy_options::recursive);
  return dir;
}

TEST(LmgcRunExamples, EveryRigidScriptGivesLmgcSolvesFilesByteForByte) {
  LMGC_REQUIRE_SHARED();
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  auto examples = rigid_examples("RIGID_2D");
  for (const auto& e : rigid_examples("RIGID_3D")) examples.push_back(e);
  ASSERT_GE(examples.size(), 12u);
  for (const fs::path& example : examples) {
    SCOPED_TRACE(case_name(example));
    const std::string steps = example.filename() == "500PL_PerioBoxJC" ? "5" : "20";
    const fs::path script = case_copy(example, "script"), read = case_copy(example, "read");
    const ToolRun a =
        run_tool_both_streams("lmgc-run", "'" + script.string() + "' --quiet --max-steps " + steps);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const ToolRun b =
        run_tool_both_streams("lmgc-solve", "'" + read.string() + "' --quiet --read-script --steps " + steps);
    ASSERT_EQ(b.exit_code, 0) << b.output;
    for (const char* file : {"DOF.LAST", "Vloc_Rloc.LAST"}) {
      const std::string ours = read_file(script / "OUTBOX" / file);
      EXPECT_FALSE(ours.empty()) << file;
      EXPECT_TRUE(ours == read_file(read / "OUTBOX" / file)) << file << " differs";
    }
    int postpro = 0;
    if (fs::exists(read / "POSTPRO"))
      for (const auto& entry : fs::directory_iterator(read / "POSTPRO")) {
        EXPECT_TRUE(read_file(entry.path()) == read_file(script / "POSTPRO" / entry.path().filename()))
            << entry.path().filename() << " differs";
        ++postpro;
      }
    std::printf("%s: DOF.LAST, Vloc_Rloc.LAST and %d POSTPRO files compared\n", case_name(example).c_str(),
                postpro);
  }
}

// lmgc-solve on a case with a command.py runs the script (as LMGC90 2025 does): --steps caps it.
TEST(LmgcRunExamples, LmgcSolveRunsTheScriptThroughTheModule) {
  LMGC_REQUIRE_SHARED();
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path example = examples_dir() / "RIGID_2D" / "BouncingBallsDK";
  const fs::path solved = case_copy(example, "solve"), run = case_copy(example, "run");
  const ToolRun a = run_tool_both_streams("lmgc-solve", "'" + solved.string() + "' --quiet --steps 30");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const ToolRun b = run_tool_both_streams("lmgc-run", "'" + run.string() + "' --quiet --max-steps 30");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_TRUE(read_file(solved / "OUTBOX" / "DOF.LAST") == read_file(run / "OUTBOX" / "DOF.LAST"));
  // The script's own run: no run_parameters.csv (lmgc-solve's own loop writes it).
  EXPECT_FALSE(fs::exists(solved / "OUTBOX" / "run_parameters.csv"));
  EXPECT_TRUE(fs::exists(solved / "OUTBOX" / "run_report.csv"));
}

}  // namespace
}  // namespace lmgc::test
