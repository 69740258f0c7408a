// Every GPV file LMGC90 wrote for the examples (.LAST and every .OUT.n: the whole set takes about
// 0.1 s) is reproduced byte for byte; every GPV.INI parses and survives
// parse(write(parse(file))) == parse(file).
#include <gtest/gtest.h>

#include "grammar/gpv/parser.hpp"
#include "grammar/gpv/writer.hpp"
#include "tests/support/gzip.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(GpvConformance, LmgcOutputsAreReproducedByteForByte) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  for (const auto& dir : test::example_cases()) {
    const auto outbox = dir / "reference_lmgc90" / "OUTBOX";
    if (!std::filesystem::is_directory(outbox)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(outbox)) {
      if (entry.path().filename().string().rfind("GPV.", 0) != 0) continue;
      SCOPED_TRACE(entry.path().string());
      const std::string text = test::read_maybe_gzip(entry.path());
      ASSERT_FALSE(text.empty());
      DiagnosticSink sink;
      const GpvFile f = parse_gpv(SourceText("GPV", text), sink);
      // No diagnostic at all, not even a warning, on what LMGC90 wrote.
      EXPECT_EQ(sink.items().size(), 0u) << (sink.items().empty() ? "" : sink.items()[0].message);
      EXPECT_FALSE(f.bodies.empty());
      EXPECT_TRUE(write_gpv(f) == text);
      ++compared;
    }
  }
  EXPECT_GE(compared, 200);
}

TEST(GpvConformance, EveryInitialFileParses) {
  LMGC_REQUIRE_SHARED();
  for (const auto& path : test::example_files("GPV.INI")) {
    SCOPED_TRACE(path.string());
    DiagnosticSink sink;
    const GpvFile f = parse_gpv(SourceText(path.string(), test::read_file(path)), sink);
    EXPECT_FALSE(sink.has_errors()) << (sink.items().empty() ? "" : sink.items()[0].message);
    DiagnosticSink again;
    EXPECT_TRUE(parse_gpv(SourceText("echo", write_gpv(f)), again) == f);
  }
}

}  // namespace
}  // namespace lmgc::grammar
