// Every example POSTPRO.DAT parses without error (with the reader of its dimension) and
// round-trips through the canonical layout.
#include <gtest/gtest.h>

#include "grammar/postpro/parser.hpp"
#include "grammar/postpro/writer.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(PostproConformance, EveryExampleParsesAndRoundTrips) {
  LMGC_REQUIRE_SHARED();
  const auto files = test::example_files("POSTPRO.DAT");
  ASSERT_GE(files.size(), 19u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const int dimension = path.string().find("_3D") != std::string::npos ? 3 : 2;
    DiagnosticSink sink;
    const PostproFile f = parse_postpro(SourceText(path.string(), test::read_file(path)), sink, dimension);
    EXPECT_FALSE(sink.has_errors()) << (sink.items().empty() ? "" : sink.items()[0].message);
    DiagnosticSink again;
    EXPECT_TRUE(parse_postpro(SourceText("echo", write_postpro(f)), again, dimension) == f);
    EXPECT_FALSE(again.has_errors());
    // The same file read without knowing the dimension gives the same commands.
    DiagnosticSink unknown;
    const PostproFile g = parse_postpro(SourceText(path.string(), test::read_file(path)), unknown);
    EXPECT_FALSE(unknown.has_errors());
    ASSERT_EQ(g.commands.size(), f.commands.size());
    for (std::size_t k = 0; k < f.commands.size(); ++k)
      EXPECT_EQ(g.commands[k].name.value, f.commands[k].name.value);
  }
}

// datbox-inputs.md §8: LMGC90 reads 'DENSE SAMPLE COMPACITY' as the colour of 'AVERAGE VELOCITY
// EVOLUTION' in this example; the parser does the same and says so.
TEST(PostproConformance, PerioBoxConsumesDenseSampleCompacity) {
  LMGC_REQUIRE_SHARED();
  const auto path = test::examples_dir() / "RIGID_2D/500PL_PerioBoxJC/DATBOX/POSTPRO.DAT";
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText(path.string(), test::read_file(path)), sink, 2);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 10u);
  ASSERT_EQ(f.commands.size(), 6u);
  EXPECT_EQ(f.commands[3].name.value, "AVERAGE VELOCITY EVOLUTION");
  EXPECT_EQ(f.commands[3].arguments[0].word.value, "DENSE");
  EXPECT_EQ(f.commands[4].name.value, "TORQUE EVOLUTION");
}

}  // namespace
}  // namespace lmgc::grammar
