// Every example COMMAND.DAT parses without error, is echoed exactly, and its run parameters read off.
#include <gtest/gtest.h>

#include "grammar/command/parser.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(CommandConformance, EveryExampleParsesAndEchoesExactly) {
  LMGC_REQUIRE_SHARED();
  const auto files = test::example_files("COMMAND.DAT");
  ASSERT_GE(files.size(), 17u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const std::string text = test::read_file(path);
    DiagnosticSink sink;
    const CommandFile f = parse_command(SourceText(path.string(), text), sink);
    EXPECT_FALSE(sink.has_errors());
    EXPECT_TRUE(write_command(f) == text);
    const CommandRunParameters p = command_run_parameters(f, sink);
    EXPECT_GT(p.dt, 0.0);
    EXPECT_GE(p.steps, 1);
  }
}

}  // namespace
}  // namespace lmgc::grammar
