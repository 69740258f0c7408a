// The run-parameter table is the one place a run parameter is described: docs/lmgc-solve.md holds
// the table as run_parameters_markdown() renders it, and every row with a flag has what the flag
// layer and --help need.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run/run_parameters.hpp"
#include "tests/support/run_tool.hpp"

namespace lmgc::run {
namespace {

TEST(RunParameterTable, DocsHoldTheGeneratedTable) {
  std::ifstream in(std::filesystem::path(LMGC_SOURCE_DIR) / "docs" / "lmgc-solve.md");
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string table = run_parameters_markdown();
  const bool listed = doc.str().find(table) != std::string::npos;
  if (!listed) std::ofstream(test::scratch_dir("run_parameters_doc") / "run_parameters.table.md") << table;
  EXPECT_TRUE(listed) << "docs/lmgc-solve.md does not hold the generated table (written to "
                         "test_scratch/run_parameters_doc/run_parameters.table.md)";
}

TEST(RunParameterTable, EveryRowSaysWhatItMeansAndEveryFlagIsTaken) {
  for (const RunParameter& p : run_parameters()) {
    EXPECT_FALSE(p.help.empty()) << p.name;
    EXPECT_NE(p.text, nullptr) << p.name;
    if (!p.flag.empty()) {
      EXPECT_NE(p.take, nullptr) << p.name;
    }
    // A COMMAND.DAT keyword is read by the COMMAND.DAT layer (the source point by its own reader).
    if (!p.command_dat.empty() && p.name != "source_point") {
      EXPECT_NE(p.from_command_dat, nullptr) << p.name;
      EXPECT_NE(p.assign, nullptr) << p.name;
    }
  }
}

TEST(RunParameterTable, FlagHelpNamesTheCallTheKeywordAndTheDefault) {
  const RunParameter* dt = find_run_parameter_by_flag("--dt");
  ASSERT_NE(dt, nullptr);
  EXPECT_EQ(flag_help(*dt),
            "time step [s] [command.py: TimeEvolution_SetTimeStep; COMMAND.DAT: TIME STEP; default 0.001]");
}

}  // namespace
}  // namespace lmgc::run
