// lmgc-check as a user runs it: exit codes, text and JSON output, --echo, --explain.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(LmgcCheck, DefaultCaseHasNoErrorAndExitsZero) {
  const fs::path dir = default_case_copy("check_ok");
  const ToolRun run = run_tool("lmgc-check", dir.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("0 errors, 0 warnings"), std::string::npos) << run.output;
}

TEST(LmgcCheck, BrokenNumberGivesCompilerStyleDiagnosticAndExitOne) {
  const fs::path dir = default_case_copy("check_broken");
  std::string bodies = read_file(dir / "DATBOX" / "BODIES.DAT");
  bodies.replace(bodies.find("byrd= 0.1000000D+00"), 19, "byrd= 0.10OOOOOD+00");
  write(dir / "DATBOX" / "BODIES.DAT", bodies);
  const ToolRun run = run_tool("lmgc-check", dir.string() + " --no-color");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("DATBOX/BODIES.DAT:9:35: error[L1002]:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("    9 |  DISKx      1  color  BLEUx  byrd= 0.10OOOOOD+00"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("      |                                   ^~~~~~~~~~~~~~"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("1 error, 0 warnings"), std::string::npos) << run.output;
}

TEST(LmgcCheck, JsonModePrintsOnlyAJsonArrayWithTheDocumentedFields) {
  const fs::path dir = default_case_copy("check_json");
  std::string bodies = read_file(dir / "DATBOX" / "BODIES.DAT");
  bodies.replace(bodies.find("DISKx"), 5, "DISCx");
  write(dir / "DATBOX" / "BODIES.DAT", bodies);
  const ToolRun run = run_tool("lmgc-check", dir.string() + " --json");
  EXPECT_EQ(run.exit_code, 1);
  const auto json = nlohmann::json::parse(run.output);  // throws (and fails) on any stray text
  ASSERT_TRUE(json.is_array());
  ASSERT_FALSE(json.empty());
  const auto& d = json[0];
  for (const char* field :
       {"file", "line", "column", "end_column", "severity", "code", "message", "related", "hint"})
    EXPECT_TRUE(d.contains(field)) << field;
  EXPECT_EQ(d["code"], "L1001");
  EXPECT_EQ(d["line"], 9);
  EXPECT_EQ(d["column"], 2);
  EXPECT_EQ(d["severity"], "error");
}

TEST(LmgcCheck, MissingRequiredFileIsAnErrorNamingIt) {
  const fs::path dir = default_case_copy("check_missing");
  fs::remove(dir / "DATBOX" / "TACT_BEHAV.DAT");
  const ToolRun run = run_tool("lmgc-check", dir.string() + " --no-color");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("error[L9001]: 'TACT_BEHAV.DAT' is missing"), std::string::npos) << run.output;
}

TEST(LmgcCheck, FolderWithoutDatboxIsAUsageErrorExitTwo) {
  const fs::path dir = scratch_dir("check_no_datbox");
  EXPECT_EQ(run_tool("lmgc-check", dir.string()).exit_code, 2);
  EXPECT_EQ(run_tool("lmgc-check", "").exit_code, 2);
  EXPECT_EQ(run_tool("lmgc-check", "--no-such-flag x").exit_code, 2);
}

TEST(LmgcCheck, EchoWritesOutboxAndNeverTouchesDatbox) {
  const fs::path dir = default_case_copy("check_echo");
  std::map<std::string, std::string> before;
  for (const auto& e : fs::directory_iterator(dir / "DATBOX"))
    before[e.path().filename().string()] = read_file(e.path());
  const ToolRun run = run_tool("lmgc-check", dir.string() + " --echo");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"BODIES.OUT", "BULK_BEHAV.OUT", "TACT_BEHAV.OUT", "DRV_DOF.OUT"})
    EXPECT_TRUE(fs::is_regular_file(dir / "OUTBOX" / name)) << name;
  EXPECT_NE(read_file(dir / "OUTBOX" / "BODIES.OUT").find(" RBDY2        2\n"), std::string::npos);
  std::map<std::string, std::string> after;
  for (const auto& e : fs::directory_iterator(dir / "DATBOX"))
    after[e.path().filename().string()] = read_file(e.path());
  EXPECT_EQ(before, after);
  for (const auto& e : fs::directory_iterator(dir / "OUTBOX"))
    EXPECT_NE(e.path().filename().string().front(), '.') << "temporary file left: " << e.path();
}

TEST(LmgcCheck, EchoIsNotWrittenFromACaseWithErrors) {
  const fs::path dir = default_case_copy("check_echo_errors");
  write(dir / "DATBOX" / "BODIES.DAT", "$bdyty\n RBDY9      1\n$$$$$$\n");
  EXPECT_EQ(run_tool("lmgc-check", dir.string() + " --echo").exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "BODIES.OUT"));
}

TEST(LmgcCheck, ExplainPrintsTheLongDescription) {
  const ToolRun run = run_tool("lmgc-check", "--explain L1011");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.output.find("L1011 (warning): value outside its columns"), std::string::npos) << run.output;
  EXPECT_EQ(run_tool("lmgc-check", "--explain L0000").exit_code, 2);
}

TEST(LmgcCheck, WerrorTurnsWarningsIntoFailure) {
  const fs::path dir = default_case_copy("check_werror");
  std::string bodies = read_file(dir / "DATBOX" / "BODIES.DAT");
  write(dir / "DATBOX" / "BODIES.DAT", "stray line\n" + bodies);
  EXPECT_EQ(run_tool("lmgc-check", dir.string()).exit_code, 0);
  EXPECT_EQ(run_tool("lmgc-check", dir.string() + " --werror").exit_code, 1);
}

}  // namespace
}  // namespace lmgc::test
