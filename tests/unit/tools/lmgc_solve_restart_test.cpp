// Restarts as LMGC90 users make them: DOF.LAST and Vloc_Rloc.LAST copied to DATBOX/DOF.INI and
// Vloc_Rloc.INI. The run continues from their step and time (drivers, write periods and headers use
// the absolute values; output numbers start again at 1, as LMGC90's counter does for record 0), a
// pair of files of different steps is refused, and with EXACT_STATE.LAST copied beside them to
// DATBOX/EXACT_STATE.INI the run continues bit for bit: N steps equal N/2 + N/2.
#include <gtest/gtest.h>

#include <fstream>

#include "grammar/dof/parser.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

grammar::DofFile dof_of(const fs::path& path) {
  grammar::DiagnosticSink sink;
  return grammar::parse_dof(grammar::SourceText(path.string(), read_file(path)), sink);
}

// A copy of a shipped case; the default case gets a wall that oscillates in x (AMP cos(OMEGA t)), so
// that a restart at the wrong time shows.
fs::path case_copy(const std::string& shipped, const std::string& name) {
  const fs::path dir = scratch_dir(name);
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / shipped / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  if (shipped == "disk_bounce_rst") {
    std::string drv = read_file(dir / "DATBOX" / "DRV_DOF.DAT");
    const std::string fixed_x =
        " vlocy      1  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  "
        "0.0000000D+00";
    drv.replace(drv.find(fixed_x), fixed_x.size(),
                " vlocy      1  0.0000000D+00  0.5000000D+00  0.3000000D+02  0.0000000D+00  0.1000000D+01  "
                "0.0000000D+00");
    std::ofstream(dir / "DATBOX" / "DRV_DOF.DAT", std::ios::binary) << drv;
  }
  return dir;
}

// Copies a run's .LAST files into its DATBOX as a user restarting does.
void restart_from_last(const fs::path& dir, bool exact) {
  fs::copy_file(dir / "OUTBOX" / "DOF.LAST", dir / "DATBOX" / "DOF.INI",
                fs::copy_options::overwrite_existing);
  fs::copy_file(dir / "OUTBOX" / "Vloc_Rloc.LAST", dir / "DATBOX" / "Vloc_Rloc.INI",
                fs::copy_options::overwrite_existing);
  if (exact)
    fs::copy_file(dir / "OUTBOX" / "EXACT_STATE.LAST", dir / "DATBOX" / "EXACT_STATE.INI",
                  fs::copy_options::overwrite_existing);
}

TEST(LmgcSolveRestart, ContinuesFromTheStepAndTimeOfDofIni) {
  const fs::path dir = case_copy("disk_bounce_rst", "restart_clock");
  const std::string args = "'" + dir.string() + "' --quiet --write-every 10";
  ASSERT_EQ(run_tool("lmgc-solve", args + " --steps 30").exit_code, 0);
  restart_from_last(dir, false);
  const ToolRun run = run_tool_both_streams("lmgc-solve", args + " --steps 20");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const grammar::DofFile last = dof_of(dir / "OUTBOX" / "DOF.LAST");
  EXPECT_EQ(last.step.value, 50);
  EXPECT_NEAR(last.time.value, 0.05, 1e-12);
  // LMGC90's counter starts again at 1 for a run read from DATBOX; the step is the absolute one.
  EXPECT_EQ(dof_of(dir / "OUTBOX" / "DOF.OUT.1").step.value, 40);
  EXPECT_EQ(dof_of(dir / "OUTBOX" / "DOF.OUT.2").step.value, 50);
  EXPECT_EQ(dof_of(dir / "OUTBOX" / "DOF.OUT.3").step.value,
            30);  // the first run's, left as LMGC90 leaves it
}

TEST(LmgcSolveRestart, StateFilesOfDifferentStepsAreRefused) {
  const fs::path dir = case_copy("disk_bounce_rst", "restart_mismatch");
  const std::string args = "'" + dir.string() + "' --quiet --write-every 10";
  ASSERT_EQ(run_tool("lmgc-solve", args + " --steps 20").exit_code, 0);
  fs::copy_file(dir / "OUTBOX" / "DOF.LAST", dir / "DATBOX" / "DOF.INI",
                fs::copy_options::overwrite_existing);
  fs::copy_file(dir / "OUTBOX" / "Vloc_Rloc.OUT.1", dir / "DATBOX" / "Vloc_Rloc.INI",
                fs::copy_options::overwrite_existing);
  const ToolRun run = run_tool_both_streams("lmgc-solve", args + " --steps 5");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("error[L1020]"), std::string::npos) << run.output;
}

// N steps and N/2 + N/2 from the exact state: the same files, byte for byte. Under the sanitizers
// (which check memory, not results, 10-50x slower) a tenth of the steps.
void expect_exact_restart(const std::string& shipped, long steps, const std::string& flags) {
#ifdef LMGC_SANITIZED_BUILD
  steps /= 10;
#endif
  SCOPED_TRACE(shipped);
  const fs::path whole = case_copy(shipped, "exact_whole_" + shipped);
  const fs::path halves = case_copy(shipped, "exact_halves_" + shipped);
  const std::string common = " --quiet --write-every 0 --no-command-dat " + flags;
  ASSERT_EQ(run_tool("lmgc-solve", "'" + whole.string() + "'" + common + " --steps " + std::to_string(steps))
                .exit_code,
            0);
  ASSERT_EQ(
      run_tool("lmgc-solve", "'" + halves.string() + "'" + common + " --steps " + std::to_string(steps / 2))
          .exit_code,
      0);
  restart_from_last(halves, true);
  const ToolRun second = run_tool_both_streams(
      "lmgc-solve", "'" + halves.string() + "'" + common + " --steps " + std::to_string(steps - steps / 2));
  ASSERT_EQ(second.exit_code, 0) << second.output;
  for (const char* file : {"DOF.LAST", "Vloc_Rloc.LAST", "EXACT_STATE.LAST"})
    EXPECT_TRUE(read_file(whole / "OUTBOX" / file) == read_file(halves / "OUTBOX" / file))
        << file << " differs";
}

TEST(LmgcSolveRestart, ExactStateContinuesBitForBit2D) {
  expect_exact_restart("disk_bounce_rst", 600, "--dt 1e-3");
  expect_exact_restart("disk_column_20", 400,
                       "--dt 1e-3 --quick-scramble --tol 1e-6 --gs-it1 10 --gs-it2 20");
}

TEST(LmgcSolveRestart, ExactStateContinuesBitForBit3D) {
  expect_exact_restart("cube_stack_10_3d", 200,
                       "--dt 1e-3 --quick-scramble --tol 1e-6 --gs-it1 10 --gs-it2 20");
  expect_exact_restart("sphere_column_10_3d", 200, "--dt 1e-3 --tol 1e-6");
}

// An exact state of another run than DOF.INI's is refused, by lmgc-check too.
TEST(LmgcSolveRestart, AnExactStateOfAnotherStepIsRefused) {
  const fs::path dir = case_copy("disk_bounce_rst", "exact_mismatch");
  const std::string args = "'" + dir.string() + "' --quiet --write-every 0 --no-command-dat";
  ASSERT_EQ(run_tool("lmgc-solve", args + " --steps 20").exit_code, 0);
  fs::copy_file(dir / "OUTBOX" / "EXACT_STATE.LAST", dir / "DATBOX" / "EXACT_STATE.INI");  // DOF.INI: step 0
  EXPECT_NE(run_tool("lmgc-check", "'" + dir.string() + "' --json").output.find("L1020"), std::string::npos);
  EXPECT_EQ(run_tool("lmgc-solve", args + " --steps 5").exit_code, 1);
}

}  // namespace
}  // namespace lmgc::test
