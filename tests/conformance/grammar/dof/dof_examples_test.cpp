// write(parse(F)) == F for every DOF.LAST / DOF.OUT.n that LMGC90 wrote in the example set
// (reference_lmgc90/OUTBOX, gzip-compressed ones included when `gzip` is available), and every
// DATBOX/DOF.INI parses with no error and round-trips through the writer.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "grammar/dof/parser.hpp"
#include "grammar/dof/writer.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

std::string describe(const DiagnosticSink& sink) {
  std::ostringstream s;
  std::size_t shown = 0;
  for (const auto& d : sink.items()) {
    if (++shown > 10) break;
    s << d.code << " " << d.where.file << ":" << d.where.span.line << ":" << d.where.span.column << " "
      << d.message << "\n";
  }
  return s.str();
}

// Test-only decompression of the few large reference files stored as .gz.
bool gunzip(const std::filesystem::path& path, std::string& text) {
  const std::string command = "gzip -dc '" + path.string() + "' 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return false;
  char buffer[65536];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) text.append(buffer, n);
  return pclose(pipe) == 0 && !text.empty();
}

bool is_dof_state_file(const std::string& name) {
  return name == "DOF.LAST" || name == "DOF.LAST.gz" || name.rfind("DOF.OUT.", 0) == 0;
}

TEST(DofExamples, WriteOfParseIsIdentityForEveryLmgc90DofFile) {
  LMGC_REQUIRE_SHARED();
  int compared = 0, compressed = 0, skipped_compressed = 0;
  for (const auto& case_dir : test::example_cases()) {
    const auto outbox = case_dir / "reference_lmgc90" / "OUTBOX";
    if (!std::filesystem::is_directory(outbox)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(outbox))
      if (entry.is_regular_file() && is_dof_state_file(entry.path().filename().string()))
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
      SCOPED_TRACE(path.string());
      std::string text;
      if (path.extension() == ".gz") {
        if (!gunzip(path, text)) {
          ++skipped_compressed;
          continue;
        }
        ++compressed;
      } else {
        text = test::read_file(path);
      }
      DiagnosticSink sink;
      const DofFile file = parse_dof(SourceText(path.string(), text), sink);
      ASSERT_EQ(sink.items().size(), 0u) << describe(sink);
      ASSERT_EQ(write_dof(file), text);
      ++compared;
    }
  }
  EXPECT_GT(compared, 800);
  RecordProperty("compared", compared);
  RecordProperty("compressed", compressed);
  if (skipped_compressed > 0) std::printf("note: %d .gz DOF files skipped (no gzip)\n", skipped_compressed);
}

TEST(DofExamples, EveryDofIniParsesWithoutErrorAndRoundTrips) {
  LMGC_REQUIRE_SHARED();
  const auto files = test::example_files("DOF.INI");
  ASSERT_EQ(files.size(), 20u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    DiagnosticSink sink;
    const DofFile file = parse_dof(SourceText(path.string(), test::read_file(path)), sink);
    EXPECT_FALSE(sink.has_errors()) << describe(sink);
    const std::string text = write_dof(file);
    DiagnosticSink again;
    const DofFile reparsed = parse_dof(SourceText("written", text), again);
    EXPECT_EQ(again.items().size(), 0u) << describe(again);
    EXPECT_EQ(reparsed, file);
    EXPECT_EQ(write_dof(reparsed), text);
  }
}

}  // namespace
}  // namespace lmgc::grammar
