// Every case of LMGC90's example set checks without error (the examples run in LMGC90), and its
// warnings are exactly those of the reviewed snapshot examples_warnings.txt (one line per
// warning: case, code, file:line). A new or vanished warning on real data fails here: review it,
// then refresh the snapshot from the file this test writes next to the build
// (test_scratch/examples_warnings.actual.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"
#include "validate/checks.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

fs::path snapshot_path() {
  return fs::path(LMGC_SOURCE_DIR) / "tests" / "conformance" / "validate" / "examples_warnings.txt";
}

// The snapshot's lines, comments ('#') and blank lines left out.
std::vector<std::string> snapshot_lines() {
  std::vector<std::string> lines;
  std::istringstream in(read_file(snapshot_path()));
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

TEST(ExamplesSnapshot, EveryExampleChecksWithoutErrorAndWithTheReviewedWarnings) {
  LMGC_REQUIRE_SHARED();
  const auto cases = example_cases();
  ASSERT_GE(cases.size(), 20u);
  std::vector<std::string> warnings;
  for (const fs::path& dir : cases) {
    const std::string name = case_name(dir);
    grammar::DiagnosticSink sink(100000);
    const auto files = case_folder::load_case(dir, sink);
    ASSERT_TRUE(files.has_value()) << name;
    validate::check_case(*files, sink);
    for (const grammar::Diagnostic& d : sink.items()) {
      const std::string where =
          fs::path(d.where.file).filename().string() + ":" + std::to_string(d.where.span.line);
      EXPECT_NE(d.severity, grammar::Severity::error)
          << name << " " << where << ": [" << d.code << "] " << d.message;
      if (d.severity == grammar::Severity::warning) warnings.push_back(name + " " + d.code + " " + where);
    }
  }
  // The actual list, for review and for refreshing the snapshot.
  const fs::path actual = fs::path(LMGC_BINARY_DIR) / "test_scratch" / "examples_warnings.actual.txt";
  fs::create_directories(actual.parent_path());
  std::ofstream out(actual, std::ios::binary);
  for (const std::string& w : warnings) out << w << "\n";
  out.close();

  const std::vector<std::string> expected = snapshot_lines();
  ASSERT_FALSE(expected.empty()) << "no snapshot at " << snapshot_path();
  std::string diff;
  std::size_t differences = 0;
  for (std::size_t i = 0; i < std::max(expected.size(), warnings.size()); ++i) {
    const std::string a = i < expected.size() ? expected[i] : "(none)";
    const std::string b = i < warnings.size() ? warnings[i] : "(none)";
    if (a != b && ++differences <= 20)
      diff += "  warning " + std::to_string(i + 1) + ": snapshot '" + a + "', now '" + b + "'\n";
  }
  EXPECT_TRUE(diff.empty()) << "warnings differ from " << snapshot_path() << " (actual list: " << actual
                            << ")\n"
                            << diff;
}

}  // namespace
}  // namespace lmgc::test
