// Every example MODELS.DAT parses, round-trips, and echoes exactly as LMGC90's MODELS.OUT.
#include <gtest/gtest.h>

#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(ModelsConformance, EveryExampleParsesRoundTripsAndEchoesAsLmgc90) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  for (const auto& input : test::example_files("MODELS.DAT")) {
    SCOPED_TRACE(input.string());
    DiagnosticSink sink;
    const ModelsFile f = parse_models(SourceText(input.string(), test::read_file(input)), sink);
    for (const Diagnostic& d : sink.items())
      EXPECT_NE(d.severity, Severity::error) << d.code << " line " << d.where.span.line << ": " << d.message;
    const std::string echo = write_models(f);
    DiagnosticSink again;
    EXPECT_TRUE(parse_models(SourceText("echo", echo), again) == f);
    const auto reference = input.parent_path().parent_path() / "reference_lmgc90" / "OUTBOX" / "MODELS.OUT";
    if (std::filesystem::exists(reference)) {
      ++compared;
      EXPECT_TRUE(echo == test::read_file(reference)) << "echo differs from LMGC90's MODELS.OUT";
    }
  }
  EXPECT_GE(compared, 8);
}

}  // namespace
}  // namespace lmgc::grammar
