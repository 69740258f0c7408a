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

}  // namespace
}  // namespace lmgc::test
