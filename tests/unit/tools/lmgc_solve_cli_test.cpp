// lmgc-solve as a user runs it: exit codes, outputs written whole, DATBOX never written to,
// COMMAND.DAT parameters and flags that override them.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "grammar/dof/parser.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> folder_contents(const fs::path& dir) {
  std::map<std::string, std::string> contents;
  for (const auto& e : fs::directory_iterator(dir))
    contents[e.path().filename().string()] = read_file(e.path());
  return contents;
}

long last_step(const fs::path& dir) {
  grammar::DiagnosticSink sink;
  const fs::path path = dir / "OUTBOX" / "DOF.LAST";
  return grammar::parse_dof(grammar::SourceText(path.string(), read_file(path)), sink).step.value;
}

TEST(LmgcSolve, DefaultCaseRunsItsCommandDatAndLeavesDatboxUntouched) {
  const fs::path dir = default_case_copy("solve_ok");
  const auto before = folder_contents(dir / "DATBOX");
  const ToolRun run = run_tool("lmgc-solve", "'" + dir.string() + "' --quiet");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(folder_contents(dir / "DATBOX"), before);
  EXPECT_EQ(last_step(dir), 3000);  // REPETE 2999 FOIS: 3000 passes of the step loop
  for (const char* name :
       {"BODIES.OUT", "TACT_BEHAV.OUT", "DOF.OUT.30", "Vloc_Rloc.OUT.30", "Vloc_Rloc.LAST", "run_report.csv"})
    EXPECT_TRUE(fs::is_regular_file(dir / "OUTBOX" / name)) << name;
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.OUT.31"));
  for (const auto& e : fs::directory_iterator(dir / "OUTBOX"))
    EXPECT_NE(e.path().filename().string().front(), '.') << "temporary file left: " << e.path();
}

TEST(LmgcSolve, FlagsOverrideTheCommandDatParameters) {
  const fs::path dir = default_case_copy("solve_flags");
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 7 --write-every 0").exit_code, 0);
  EXPECT_EQ(last_step(dir), 7);
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.OUT.1"));
}

// The run report's timing columns nest: the sweeps are part of the solve, the solve of the step.
TEST(LmgcSolve, RunReportSweepTimeIsPartOfTheSolveTimeWhichIsPartOfTheStepTime) {
  const fs::path dir = default_case_copy("solve_report");
  ASSERT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 20 --write-every 0").exit_code, 0);
  std::istringstream report(read_file(dir / "OUTBOX" / "run_report.csv"));
  std::string line;
  std::getline(report, line);
  ASSERT_NE(line.find(",step_seconds,nlgs_seconds,sweep_seconds"), std::string::npos) << line;
  int rows = 0;
  while (std::getline(report, line)) {
    std::vector<double> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(std::stod(field));
    ASSERT_GE(fields.size(), 3u);
    const double step = fields[fields.size() - 3], solve = fields[fields.size() - 2], sweeps = fields.back();
    EXPECT_LE(sweeps, solve) << line;
    EXPECT_LE(solve, step) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 20);
}

TEST(LmgcSolve, InvalidDataExitsOneAndWritesNothing) {
  const fs::path dir = default_case_copy("solve_invalid");
  std::string tact = read_file(dir / "DATBOX" / "TACT_BEHAV.DAT");
  tact.replace(tact.find("RBDY2  DISKx  BLEUx  rst08"), 26, "RBDY2  DISKx  BLEUx  rst09");
  std::ofstream(dir / "DATBOX" / "TACT_BEHAV.DAT", std::ios::binary) << tact;
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet").exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
}

// PTPT3_NETWORK.DAT is read only when the run asks for it (--ptpt3-network), as LMGC90 reads it
// only under PTPT3_LoadNetwork: a network naming a point the case lacks stops that run (exit 1,
// L2021) and not a run without the flag.
TEST(LmgcSolve, APtpt3NetworkIsReadOnlyWithItsFlag) {
  const fs::path dir = scratch_dir("solve_network");
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "wire_periodic_network_3d" / "DATBOX",
           dir / "DATBOX", fs::copy_options::recursive);
  std::ofstream(dir / "DATBOX" / "PTPT3_NETWORK.DAT") << " 1 9 1 0 0 1.0\n";
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 2").exit_code, 0);
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 2 --ptpt3-network").exit_code, 1);
  EXPECT_NE(run_tool("lmgc-check", "'" + dir.string() + "' --json").output.find("L2021"), std::string::npos);
}

TEST(LmgcSolve, UsageErrorsExitTwo) {
  EXPECT_EQ(run_tool("lmgc-solve", "").exit_code, 2);
  EXPECT_EQ(run_tool("lmgc-solve", "--no-such-flag x").exit_code, 2);
  EXPECT_EQ(run_tool("lmgc-solve", "'" + scratch_dir("solve_not_a_case").string() + "'").exit_code, 2);
  const fs::path dir = default_case_copy("solve_bad_norm");
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --norm Nope").exit_code, 2);
}

// Every real flag refuses NaN and infinities, every count its range (exit 2, nothing written).
TEST(LmgcSolve, NonFiniteOrOutOfRangeFlagsAreUsageErrors) {
  const fs::path dir = default_case_copy("solve_bad_flags");
  const std::string c = "'" + dir.string() + "' --quiet --steps 2 ";
  for (const char* flag :
       {"--dt nan", "--dt inf", "--theta nan", "--tol nan", "--relax nan", "--relax 5", "--relax 0",
        "--xperiod nan", "--xperiod -1", "--ymin-boundary nan", "--residual-target nan", "--steps -1",
        "--steps 99999999999999999999", "--write-every -1", "--display-every -2", "--gs-it1 0",
        "--cundall-iterations 0", "--source-point 1,nan,0,0,0", "--rloc-tol 0.01"}) {
    EXPECT_EQ(run_tool("lmgc-solve", c + flag).exit_code, 2) << flag;
  }
  EXPECT_FALSE(fs::exists(dir / "OUTBOX"));
}

// A case folder whose name starts with '-' is given after '--'.
TEST(LmgcSolve, ACasePathStartingWithADashIsGivenAfterTwoDashes) {
  const fs::path parent = scratch_dir("solve_dash");
  fs::create_directories(parent / "-case");
  fs::copy(default_case_copy("solve_dash_source") / "DATBOX", parent / "-case" / "DATBOX",
           fs::copy_options::recursive);
  const ToolRun run =
      run_tool_both_streams("lmgc-solve", "--quiet --steps 2 -- -case", "cd '" + parent.string() + "' && ");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(parent / "-case" / "OUTBOX" / "DOF.LAST"));
}

// A COMMAND.DAT command that changes the run and that lmgc-solve does not do: the case is refused
// (exit 5, L4005, nothing written); without COMMAND.DAT it runs.
TEST(LmgcSolve, ACommandItDoesNotRunRefusesTheCaseUnlessCommandDatIsLeftOut) {
  const fs::path dir = default_case_copy("solve_refused");
  std::string command = read_file(dir / "DATBOX" / "COMMAND.DAT");
  command.replace(command.find("COMPUTE MASS"), 12, "COMPUTE MASS                  :\nGHOST TO INVISIBLE");
  std::ofstream(dir / "DATBOX" / "COMMAND.DAT", std::ios::binary) << command;
  const ToolRun refused = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --quiet --steps 2");
  EXPECT_EQ(refused.exit_code, 5);
  EXPECT_NE(refused.output.find("warning[L4005]"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(dir / "OUTBOX"));
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 2 --no-command-dat").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
}

// OUTBOX/run_parameters.csv: each parameter's value and the layer it came from.
TEST(LmgcSolve, RunParametersRecordWhereEachValueCameFrom) {
  const fs::path dir = default_case_copy("solve_sources");
  ASSERT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --steps 4 --tol 1e-5").exit_code, 0);
  const std::string csv = read_file(dir / "OUTBOX" / "run_parameters.csv");
  EXPECT_NE(csv.find("\ndt,\"0.001\",COMMAND.DAT,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nnb_steps,\"4\",flag,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ntol,\"1e-05\",flag,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nscramble_seed,\"1\",default,"), std::string::npos) << csv;
}

// A case with a command.py: lmgc-solve says that it does not run it, and names each parameter whose
// value differs from the script's literal, with the script's line and the flag that would match it.
const char* const kScript =
    "from pylmgc90 import chipy\n"
    "dt = 5e-4\n"
    "theta = 0.5\n"
    "chipy.TimeEvolution_SetTimeStep(dt)\n"
    "chipy.Integrator_InitTheta(theta)\n"
    "chipy.ExSolver('Stored_Delassus_Loops', 'Quad ', 1e-4, 1., 20, 30)\n"
    "for k in range(30):\n"
    "  chipy.IncrementStep()\n"
    "  chipy.WriteOut(10)\n";

// The case's command.py drives the run, as in LMGC90 2025: its literals are the run's parameters
// (COMMAND.DAT is not read), and a flag that overrides one of them is named.
TEST(LmgcSolve, TheScriptsLiteralsAreTheRunParameters) {
  const fs::path dir = default_case_copy("solve_script");
  std::ofstream(dir / "command.py") << kScript;
  const ToolRun run = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --theta 0.6");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("warning[L4011]"), std::string::npos) << run.output;
  EXPECT_NE(
      run.output.find("command.py:5:7: warning[L4008]: theta is 0.6 (flag); command.py passes 0.5 (--theta)"),
      std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("dt is"), std::string::npos) << run.output;
  const std::string csv = read_file(dir / "OUTBOX" / "run_parameters.csv");
  for (const char* row : {"dt,\"0.0005\",command.py", "nb_steps,\"30\",command.py",
                          "tol,\"0.0001\",command.py", "gs_it1,\"20\",command.py", "gs_it2,\"30\",command.py",
                          "freq_write,\"10\",command.py", "theta,\"0.6\",flag"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  EXPECT_TRUE(fs::exists(dir / "OUTBOX" / "DOF.OUT.3"));
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.OUT.4"));
}

// --command-dat: the legacy driver; every parameter of the script that differs is named.
TEST(LmgcSolve, CommandDatDrivesWhenAskedAndTheScriptsDifferencesAreNamed) {
  const fs::path dir = default_case_copy("solve_script_dat");
  std::ofstream(dir / "command.py") << kScript;
  const ToolRun run = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --command-dat --steps 30");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find(
                "command.py:4:7: warning[L4008]: dt is 0.001 (COMMAND.DAT); command.py passes 0.0005 (--dt)"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("theta is"), std::string::npos);
  EXPECT_EQ(run.output.find("nb_steps is"), std::string::npos);
  EXPECT_EQ(run.output.find("L4013"), std::string::npos);
  EXPECT_NE(read_file(dir / "OUTBOX" / "run_parameters.csv").find("dt,\"0.001\",COMMAND.DAT"),
            std::string::npos);
}

// Read, not run (--read-script): what the script computes cannot be read without running it, and
// the value run instead is named with its flag. A literal the run cannot take is an error at the call.
TEST(LmgcSolve, AComputedScriptParameterIsNamedAndABadOneRefused) {
  const fs::path dir = default_case_copy("solve_script_computed");
  std::ofstream(dir / "command.py") << "import sys\nfrom pylmgc90 import chipy\n"
                                       "dt = float(sys.argv[1])\n"
                                       "chipy.TimeEvolution_SetTimeStep(dt)\n"
                                       "for k in range(5):\n  chipy.IncrementStep()\n";
  ToolRun run = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --read-script");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(
      run.output.find("command.py:4:7: warning[L4013]: command.py computes dt (dt); lmgc-solve runs 0.001 "
                      "(its default) (--dt)"),
      std::string::npos)
      << run.output;
  std::ofstream(dir / "command.py") << "from pylmgc90 import chipy\nchipy.TimeEvolution_SetTimeStep(-1e-3)\n"
                                       "for k in range(5):\n  chipy.IncrementStep()\n";
  run = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --read-script");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("command.py:2:7: error[L4010]: dt = -0.001 is not a value a run can take"),
            std::string::npos)
      << run.output;
  // lmgc-check says the same.
  run = run_tool_both_streams("lmgc-check", "'" + dir.string() + "'");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("error[L4010]"), std::string::npos) << run.output;
}

// An output that cannot be written (a POSTPRO file on a full device) stops the run with exit 4,
// not 1 ("invalid data"); a stale temporary of a killed run is removed, never left or renamed.
TEST(LmgcSolve, AnOutputThatCannotBeWrittenExitsFour) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path dir = default_case_copy("solve_full");
  std::ofstream(dir / "DATBOX" / "POSTPRO.DAT")
      << "KINETIC ENERGY                :\nSTEP 1                        :\nEND\n";
  fs::create_directories(dir / "POSTPRO");
  fs::create_directories(dir / "OUTBOX");
  fs::create_symlink("/dev/full", dir / "POSTPRO" / "KINETIC_ENERGY.DAT");
  std::ofstream(dir / "OUTBOX" / ".DOF.LAST.tmp") << "half";
  const ToolRun run = run_tool_both_streams("lmgc-solve", "'" + dir.string() + "' --quiet --steps 20");
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_NE(run.output.find("KINETIC_ENERGY.DAT"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / ".DOF.LAST.tmp"));
}

// A file size limit (ulimit -f, what a batch scheduler may set): the write that crosses it fails,
// the run stops with exit 4, and every file under its final name is whole (DOF.OUT.n are written
// under a temporary name and renamed).
TEST(LmgcSolve, AFileSizeLimitStopsTheRunWithItsFilesWhole) {
  const fs::path dir = default_case_copy("solve_ulimit");
  // 64 blocks of 1 KiB (POSIX sh's ulimit -f unit is 512 bytes on some shells: 32 KiB at least).
  const ToolRun run = run_tool_both_streams(
      "lmgc-solve", "'" + dir.string() + "' --quiet --steps 3000 --write-every 1", "ulimit -f 64; ");
  EXPECT_EQ(run.exit_code, 4) << run.output;
  int outputs = 0;
  for (const auto& e : fs::directory_iterator(dir / "OUTBOX")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("DOF.OUT.", 0) != 0) continue;
    ++outputs;
    const std::string text = read_file(e.path());
    EXPECT_NE(text.find("$$$$$$"), std::string::npos) << name << " is cut";
  }
  EXPECT_GT(outputs, 0);
}

TEST(LmgcSolve, StrictExitsThreeWhenAStepHitsTheIterationCap) {
  LMGC_REQUIRE_SHARED();
  // 1024 disks with one sweep per step cannot reach 1e-12: every step with contacts hits the cap.
  const fs::path dir = scratch_dir("solve_strict");
  fs::copy(examples_dir() / "RIGID_2D" / "1024DK_BoxJC" / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  const std::string args =
      "'" + dir.string() + "' --quiet --steps 60 --gs-it1 1 --gs-it2 1 --tol 1e-12 --write-every 0";
  EXPECT_EQ(run_tool("lmgc-solve", args + " --strict").exit_code, 3);
  EXPECT_EQ(run_tool("lmgc-solve", args).exit_code, 0);
}

}  // namespace
}  // namespace lmgc::test
