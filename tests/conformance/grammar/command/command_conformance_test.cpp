// Every example COMMAND.DAT parses without error, is written back byte for byte (comments after
// column 30 included) and expands into a run.
#include <gtest/gtest.h>

#include "grammar/command/expand.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/command/writer.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(CommandConformance, EveryExampleParsesRoundTripsAndExpands) {
  LMGC_REQUIRE_SHARED();
  const auto files = test::example_files("COMMAND.DAT");
  ASSERT_GE(files.size(), 18u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const std::string text = test::read_file(path);
    DiagnosticSink sink;
    const CommandFile f = parse_command(SourceText(path.string(), text), sink);
    for (const Diagnostic& d : sink.items())
      EXPECT_NE(d.severity, Severity::error) << d.code << " line " << d.where.span.line << ": " << d.message;
    EXPECT_EQ(write_command(f), text);
    DiagnosticSink again;
    EXPECT_TRUE(parse_command(SourceText("echo", write_command(f)), again) == f);

    DiagnosticSink run_sink;
    const auto run = expand_command_program(f, 5000, run_sink);
    EXPECT_FALSE(run_sink.has_errors());
    EXPECT_GT(run.size(), 20u);
  }
}

// RIGID_2D/1024DK_BoxJC: 'REPETE 3999 FOIS' around the step, 'REPETE 32 FOIS' around the sweep
// and 'REPETE 100 FOIS' around the check (state-and-outputs.md §2.1.2: n + 1 passes).
TEST(CommandConformance, RunParametersOf1024DiskBox) {
  LMGC_REQUIRE_SHARED();
  const auto path = test::examples_dir() / "RIGID_2D/1024DK_BoxJC/DATBOX/COMMAND.DAT";
  DiagnosticSink sink;
  const CommandRunParameters p =
      command_run_parameters(parse_command(SourceText(path.string(), test::read_file(path)), sink), sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_DOUBLE_EQ(p.dt, 2e-4);
  EXPECT_DOUBLE_EQ(p.theta, 0.5);
  EXPECT_EQ(p.steps, 4000);
  EXPECT_EQ(p.gs_it1, 33);
  EXPECT_EQ(p.gs_it2, 101);
  EXPECT_EQ(p.norm, "Quad");
  EXPECT_EQ(p.storage, "Stored_Delassus_Loops");
  EXPECT_EQ(p.write_every, 100);
  EXPECT_TRUE(p.quick_scramble);
  EXPECT_EQ(p.x_period, 0.0);
}

// RIGID_2D/500PL_PerioBoxJC: 'PERIODIC CONDITION' with the period 1.1 on the next line.
TEST(CommandConformance, PeriodOfThePeriodicPolygonBox) {
  LMGC_REQUIRE_SHARED();
  const auto path = test::examples_dir() / "RIGID_2D/500PL_PerioBoxJC/DATBOX/COMMAND.DAT";
  DiagnosticSink sink;
  const CommandRunParameters p =
      command_run_parameters(parse_command(SourceText(path.string(), test::read_file(path)), sink), sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_DOUBLE_EQ(p.x_period, 1.1);
}

}  // namespace
}  // namespace lmgc::grammar
