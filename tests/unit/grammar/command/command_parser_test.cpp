// COMMAND.DAT: line roles, arguments, the symbolic run, and broken files.
#include "grammar/command/parser.hpp"

#include <gtest/gtest.h>

namespace lmgc::grammar {
namespace {

// The canonical NLGS block of the examples, inside a 3-step loop.
const std::string kProgram =
    "TIME STEP                     :\n"
    "1.D-3                         :\n"
    "step                          : label\n"
    "INCREMENT STEP                :\n"
    "NLGS CHECK TYPE               :\n"
    "Quad 0.1666D-03               : tol\n"
    "1.0D0                         : RELAX\n"
    "EX PREP NLGS                  :\n"
    "Stored_Delassus_Loops         :\n"
    ">more                         :\n"
    "  >iteration                  :\n"
    "    EX ITER NLGS              :\n"
    "  REPETE 10 FOIS              :\n"
    "  DEPUIS >iteration           :\n"
    "  AFTER ITER CHECK            :\n"
    "  IOK = FLAG 1                :\n"
    "  INTO AFTER ITER CHECK       :\n"
    "  STOP REPETE SI IOK = 0      :\n"
    "REPETE 100 FOIS               :\n"
    "DEPUIS >more                  :\n"
    "EX POST NLGS                  :\n"
    "REPETE 2 FOIS                 :\n"
    "DEPUIS step                   :\n"
    "FIN DU PROGRAMME\n"
    "FIN DU FICHIER\n";

std::size_t count(const std::vector<ExecutedCommand>& run, const std::string& statement) {
  std::size_t n = 0;
  for (const auto& c : run) n += c.statement == statement;
  return n;
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line, std::uint32_t column) {
  DiagnosticSink sink;
  parse_command(SourceText("COMMAND.DAT", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(CommandParser, TextIsEchoedExactly) {
  DiagnosticSink sink;
  EXPECT_EQ(write_command(parse_command(SourceText("COMMAND.DAT", kProgram), sink)), kProgram);
  EXPECT_FALSE(sink.has_errors());
}

TEST(CommandExpansion, RepeteNGivesNPlusOnePasses) {
  DiagnosticSink sink;
  const CommandFile f = parse_command(SourceText("COMMAND.DAT", kProgram), sink);
  // IOK stays 1 ("not converged"): every NLGS loop runs to its end.
  const auto run = expand_command_program(f, 1'000'000, sink, [](const std::string&, int) { return 1; });
  EXPECT_EQ(count(run, "INCREMENT STEP"), 3u);               // REPETE 2 -> 3 steps
  EXPECT_EQ(count(run, "AFTER ITER CHECK"), 3u * 101u);      // REPETE 100 -> 101 checks per step
  EXPECT_EQ(count(run, "EX ITER NLGS"), 3u * 101u * 11u);    // REPETE 10 -> 11 sweeps per check
}

TEST(CommandExpansion, ConvergedCheckLeavesTheOuterLoop) {
  DiagnosticSink sink;
  const CommandFile f = parse_command(SourceText("COMMAND.DAT", kProgram), sink);
  const auto run = expand_command_program(f, 1'000'000, sink);  // IOK = 0 at the first check
  EXPECT_EQ(count(run, "AFTER ITER CHECK"), 3u);
  EXPECT_EQ(count(run, "EX POST NLGS"), 3u);
}

TEST(CommandParameters, AreReadOffTheProgram) {
  DiagnosticSink sink;
  const CommandFile f = parse_command(SourceText("COMMAND.DAT", kProgram), sink);
  const CommandRunParameters p = command_run_parameters(f, sink);
  EXPECT_DOUBLE_EQ(p.dt, 1e-3);
  EXPECT_EQ(p.steps, 3);
  EXPECT_EQ(p.norm, "Quad ");
  EXPECT_DOUBLE_EQ(p.tolerance, 0.1666e-3);
  EXPECT_EQ(p.gs_it1, 11);
  EXPECT_EQ(p.gs_it2, 101);
  EXPECT_EQ(p.storage, "Stored_Delassus_Loops");
}

TEST(CommandBroken, UnknownStatementIsAWarning) { expect_diagnostic("TIME STAP\nFIN DU PROGRAMME\n", "L1019", 1, 1); }
TEST(CommandBroken, RepeteWithoutDepuis) { expect_diagnostic("REPETE 3 FOIS\nINCREMENT STEP\nFIN DU PROGRAMME\n", "L1013", 1, 1); }
TEST(CommandBroken, RepeteWithoutCount) { expect_diagnostic("x\nREPETE FOIS\nDEPUIS x\nFIN DU PROGRAMME\n", "L1003", 2, 1); }
TEST(CommandBroken, CallOfAMissingSubroutine) { expect_diagnostic("APPELLE nowhere\nFIN DU PROGRAMME\n", "L1013", 1, 9); }
TEST(CommandBroken, MissingEndOfProgram) { expect_diagnostic("INCREMENT STEP\n", "L1012", 1, 15); }
TEST(CommandBroken, ArgumentLineMissingAtEndOfFile) { expect_diagnostic("FIN DU PROGRAMME\nTIME STEP\n", "L1006", 2, 10); }

}  // namespace
}  // namespace lmgc::grammar
