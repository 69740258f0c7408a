// lmgc-check as a user runs it: exit codes, text and JSON output, --echo, --explain.
#include <gtest/gtest.h>
#include <sys/stat.h>

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

// A byte that is not UTF-8 (a Latin-1 accent in a colour) quoted by a message: the JSON output is
// still one valid array (the byte replaced), not an abort.
TEST(LmgcCheck, JsonOfAMessageQuotingANonUtf8ByteIsValid) {
  const fs::path dir = default_case_copy("check_latin1");
  std::string bodies = read_file(dir / "DATBOX" / "BODIES.DAT");
  bodies.replace(bodies.find("BLEUx"), 5, "BL\xC9Ux");
  write(dir / "DATBOX" / "BODIES.DAT", bodies);
  const ToolRun run = run_tool("lmgc-check", "'" + dir.string() + "' --json");
  EXPECT_EQ(run.exit_code, 1);
  const auto json = nlohmann::json::parse(run.output, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << run.output;
  ASSERT_TRUE(json.is_array());
  EXPECT_FALSE(json.empty());
}

// Thousands of damaged lines: every error is counted, the first 5000 shown, and the rest stated by
// L9004, in text and in JSON; an error after them is not lost among the warnings.
TEST(LmgcCheck, DiagnosticsBeyondTheLimitAreStatedInEveryMode) {
  const fs::path dir = default_case_copy("check_many");
  std::string tact = read_file(dir / "DATBOX" / "TACT_BEHAV.DAT");
  std::string tail;
  for (int k = 0; k < 6000; ++k) tail += " zzz\n";  // a line LMGC90 skips: a warning each (L1019)
  write(dir / "DATBOX" / "TACT_BEHAV.DAT", tact + tail);
  // DRV_DOF.DAT is read after TACT_BEHAV.DAT: its error comes after the 6000 warnings.
  std::string drv = read_file(dir / "DATBOX" / "DRV_DOF.DAT");
  drv.replace(drv.find("0.1000000D+01"), 13, "0.10OOOOOD+01");
  write(dir / "DATBOX" / "DRV_DOF.DAT", drv);
  const ToolRun text = run_tool("lmgc-check", "'" + dir.string() + "' --no-color");
  EXPECT_EQ(text.exit_code, 1);
  EXPECT_NE(text.output.find("error[L1002]"), std::string::npos);
  const ToolRun json_run = run_tool("lmgc-check", "'" + dir.string() + "' --json");
  const auto json = nlohmann::json::parse(json_run.output, nullptr, false);
  ASSERT_TRUE(json.is_array()) << json_run.output.substr(0, 200);
  bool error_shown = false, overflow_stated = false;
  for (const auto& d : json) {
    error_shown |= d["code"] == "L1002";
    overflow_stated |= d["code"] == "L9004";
  }
  EXPECT_TRUE(error_shown);
  EXPECT_TRUE(overflow_stated);
  EXPECT_NE(text.output.find("[L9004]"), std::string::npos);
}

// Input files that are not files: a symbolic link loop, a FIFO, /dev/zero. Each is refused with L9001
// (exit 1); nothing blocks, nothing is read without bound, nothing aborts.
TEST(LmgcCheck, InputsThatAreNotFilesAreRefused) {
  const fs::path dir = default_case_copy("check_not_files");
  fs::remove(dir / "DATBOX" / "BODIES.DAT");
  fs::create_symlink(dir / "DATBOX" / "LOOP.DAT", dir / "DATBOX" / "BODIES.DAT");
  fs::create_symlink(dir / "DATBOX" / "BODIES.DAT", dir / "DATBOX" / "LOOP.DAT");
  fs::remove(dir / "DATBOX" / "POSTPRO.DAT");
  ASSERT_EQ(::mkfifo((dir / "DATBOX" / "POSTPRO.DAT").c_str(), 0600), 0);
  fs::remove(dir / "DATBOX" / "DOF.INI");
  fs::create_symlink("/dev/zero", dir / "DATBOX" / "DOF.INI");
  const ToolRun check = run_tool("lmgc-check", "'" + dir.string() + "' --json");
  EXPECT_EQ(check.exit_code, 1);
  const auto json = nlohmann::json::parse(check.output, nullptr, false);
  ASSERT_TRUE(json.is_array()) << check.output;
  int refused = 0;
  for (const auto& d : json) refused += d["code"] == "L9001";
  EXPECT_GE(refused, 3) << check.output;
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet").exit_code, 1);
}

}  // namespace
}  // namespace lmgc::test
