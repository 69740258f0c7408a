// Every folder of reference_cases/ with a case.json runs with lmgc-solve (its DATBOX/COMMAND.DAT
// gives the run), and each expected quantity of case.json holds within its stated tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// Rows of a POSTPRO BODY TRACKING file: time, x, y, rotation, then displacements and velocities.
std::vector<std::vector<double>> read_table(const fs::path& path) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream values(line);
    std::vector<double> row;
    double v;
    while (values >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

// Heights of the local maxima of the body centre's y, minus `offset`.
std::vector<double> apex_heights(const std::vector<std::vector<double>>& rows, double offset) {
  std::vector<double> apexes;
  for (std::size_t i = 1; i + 1 < rows.size(); ++i)
    if (rows[i][2] >= rows[i - 1][2] && rows[i][2] > rows[i + 1][2]) apexes.push_back(rows[i][2] - offset);
  return apexes;
}

std::vector<fs::path> reference_cases() {
  std::vector<fs::path> cases;
  for (const auto& entry : fs::directory_iterator(fs::path(LMGC_SOURCE_DIR) / "reference_cases"))
    if (fs::exists(entry.path() / "case.json")) cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  return cases;
}

TEST(ReferenceCases, EveryExpectedQuantityHoldsWithinItsTolerance) {
  const auto cases = reference_cases();
  ASSERT_FALSE(cases.empty());
  for (const fs::path& source : cases) {
    SCOPED_TRACE(source.filename().string());
    const auto spec = nlohmann::json::parse(read_file(source / "case.json"));
    const fs::path dir = scratch_dir("reference_" + source.filename().string());
    fs::copy(source / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
    ASSERT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet").exit_code, 0);
    ASSERT_FALSE(spec.at("expected").empty());
    for (const auto& expected : spec.at("expected")) {
      const std::string quantity = expected.at("quantity");
      ASSERT_FALSE(expected.at("source").get<std::string>().empty());
      const double tolerance = expected.at("tolerance");
      if (quantity == "apex_heights") {
        char name[32];
        std::snprintf(name, sizeof name, "BODY_%07d.DAT", expected.at("body").get<int>());
        const auto apexes = apex_heights(read_table(dir / "POSTPRO" / name), expected.at("offset"));
        const auto values = expected.at("values").get<std::vector<double>>();
        ASSERT_GE(apexes.size(), values.size());
        for (std::size_t n = 0; n < values.size(); ++n)
          EXPECT_NEAR(apexes[n], values[n], tolerance) << "apex " << n + 1;
      } else {
        ADD_FAILURE() << "case.json names a quantity this test does not compute: " << quantity;
      }
    }
  }
}

}  // namespace
}  // namespace lmgc::test
