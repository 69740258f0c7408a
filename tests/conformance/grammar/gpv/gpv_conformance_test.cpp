// Every GPV file LMGC90 wrote for the examples is reproduced byte for byte; every GPV.INI parses.
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
      DiagnosticSink sink;
      const GpvFile f = parse_gpv(SourceText("GPV", text), sink);
      EXPECT_FALSE(sink.has_errors());
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
    parse_gpv(SourceText(path.string(), test::read_file(path)), sink);
    EXPECT_FALSE(sink.has_errors());
  }
}

}  // namespace
}  // namespace lmgc::grammar
