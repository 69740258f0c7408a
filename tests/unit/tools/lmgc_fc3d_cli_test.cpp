// lmgc-fc3d end to end: its table, its summary line, its exit codes.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

std::filesystem::path fc3d_problems() {
  return shared_dir() / "fc3d" / "problems";
}

#define REQUIRE_FC3D()                                                                               \
  do {                                                                                               \
    if (!std::filesystem::is_directory(fc3d_problems()))                                             \
      GTEST_SKIP() << "FCLIB problems not found at " << fc3d_problems() << " (see LMGC_SHARED_DIR)"; \
  } while (0)

TEST(LmgcFc3dCli, SolvesSmallProblemsAndPrintsTheSummaryLine) {
  REQUIRE_FC3D();
  const auto dir = fc3d_problems() / "fc3d";
  const ToolRun run = run_tool("lmgc-fc3d", "'" + (dir / "Confeti-ex13-4contact-Fc3D-SBM.hdf5").string() +
                                                "' '" + (dir / "Box_Stacks-i0122-82-5_local.hdf5").string() +
                                                "' '" + (dir / "OneObject-i100000-499.hdf5").string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("solved 3/3 to 1e-08"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("Box_Stacks-i0122-82-5_local.hdf5"), std::string::npos);
}

TEST(LmgcFc3dCli, SolvesATwoDimensionalProblem) {
  REQUIRE_FC3D();
  const ToolRun run = run_tool(
      "lmgc-fc3d", "'" + (fc3d_problems() / "fc2d" / "FrictionContactProblem00727.hdf5").string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("solved 1/1"), std::string::npos) << run.output;
}

TEST(LmgcFc3dCli, UnsolvedWithinTheSweepCapExitsThree) {
  REQUIRE_FC3D();
  const ToolRun run =
      run_tool("lmgc-fc3d", "--method nlgs --max-sweeps 2 '" +
                                (fc3d_problems() / "fc3d" / "KaplasTower-i1061-4.hdf5").string() + "'");
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_NE(run.output.find("solved 0/1"), std::string::npos) << run.output;
}

TEST(LmgcFc3dCli, NonHdf5FileExitsOneAndSolvesTheOthers) {
  const auto dir = scratch_dir("lmgc_fc3d_bad_file");
  const auto bad = dir / "not_a_problem.hdf5";
  std::ofstream(bad) << "this is text\n";
  const ToolRun run = run_tool("lmgc-fc3d", "'" + bad.string() + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("solved 0/1"), std::string::npos) << run.output;
}

TEST(LmgcFc3dCli, MissingFileIsAUsageError) {
  const ToolRun run = run_tool("lmgc-fc3d", "/nonexistent/problem.hdf5");
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
}  // namespace lmgc::test
