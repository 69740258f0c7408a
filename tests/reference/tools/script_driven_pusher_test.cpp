// reference_cases/script_driven_pusher: a case loaded from its own command.py (a pusher whose
// velocity the script sets every step, a disk kicked by PutBodyVector), run by lmgc-run, follows
// LMGC90's trajectory (lmgc90_trajectory.csv, the same script run by LMGC90) within 1e-9 m
// (README.md there gives the tolerance's reason).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_tool.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<double>> read_csv(const fs::path& path) {
  std::vector<std::vector<double>> rows;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // names
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(ScriptDrivenPusher, FollowsLmgc90sTrajectoryWithin1e9) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "script_driven_pusher";
  const fs::path dir = scratch_dir("script_driven_pusher");
  fs::copy(source, dir, fs::copy_options::recursive);
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto ours = read_csv(dir / "trajectory.csv");
  const auto lmgc90 = read_csv(source / "lmgc90_trajectory.csv");
  ASSERT_EQ(ours.size(), 60u);
  ASSERT_EQ(ours.size(), lmgc90.size());
  double worst = 0.0;
  for (std::size_t r = 0; r < ours.size(); ++r) {
    ASSERT_EQ(ours[r].size(), lmgc90[r].size());
    EXPECT_EQ(ours[r][0], lmgc90[r][0]);  // step
    for (std::size_t c = 2; c < ours[r].size(); ++c)
      worst = std::max(worst, std::abs(ours[r][c] - lmgc90[r][c]));
  }
  EXPECT_LE(worst, 1e-9);
  std::printf("largest position difference with LMGC90: %.3g m\n", worst);
  // The kicks happened: the small disk rose above its resting height 0.05 m and landed again.
  double highest = 0.0;
  for (const auto& row : ours) highest = std::max(highest, row[14 + 1]);
  EXPECT_GT(highest, 0.09);
  EXPECT_NEAR(ours[25][15], 0.05, 1e-12);  // step 260: landed, at rest on the floor
}

}  // namespace
}  // namespace lmgc::test
