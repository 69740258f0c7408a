// Every example BULK_BEHAV.DAT parses, round-trips, and echoes exactly as LMGC90's BULK_BEHAV.OUT.
#include <gtest/gtest.h>

#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(BulkBehavConformance, EveryExampleParsesRoundTripsAndEchoesAsLmgc90) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  for (const auto& dir : test::example_cases()) {
    const auto input = dir / "DATBOX" / "BULK_BEHAV.DAT";
    if (!std::filesystem::exists(input)) continue;
    SCOPED_TRACE(test::case_name(dir));
    DiagnosticSink sink;
    const BulkBehavFile f = parse_bulk_behav(SourceText(input.string(), test::read_file(input)), sink);
    EXPECT_FALSE(sink.has_errors());
    const std::string echo = write_bulk_behav(f);
    DiagnosticSink again_sink;
    EXPECT_TRUE(parse_bulk_behav(SourceText("echo", echo), again_sink) == f);
    const auto reference = dir / "reference_lmgc90" / "OUTBOX" / "BULK_BEHAV.OUT";
    if (std::filesystem::exists(reference)) {
      ++compared;
      EXPECT_TRUE(echo == test::read_file(reference)) << "echo differs from LMGC90's BULK_BEHAV.OUT";
    }
  }
  EXPECT_GE(compared, 20);
}

}  // namespace
}  // namespace lmgc::grammar
