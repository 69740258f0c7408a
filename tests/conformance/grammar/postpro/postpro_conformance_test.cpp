// Every example POSTPRO.DAT parses without error and round-trips through the canonical layout.
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
    EXPECT_FALSE(sink.has_errors());
    DiagnosticSink again;
    EXPECT_TRUE(parse_postpro(SourceText("echo", write_postpro(f)), again, dimension) == f);
  }
}

}  // namespace
}  // namespace lmgc::grammar
