// COMMAND.DAT: lexical rules, classification, control structures, expansion, broken files.
#include <gtest/gtest.h>

#include <algorithm>

#include "grammar/command/expand.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/command/writer.hpp"

namespace lmgc::grammar {
namespace {

// The canonical NLGS block of state-and-outputs.md §2.1.2 inside a loading loop of 3 steps.
const std::string kProgram =
    "#23456789012345678901234567890:\n"
    "ECHO OFF                      :\n"
    "TIME STEP                     :\n"
    "1.D-03                        : the step\n"
    "COMPUTE BOX                   :\n"
    "COMPUTE MASS                  :\n"
    "loading step                  : label of the loop\n"
    "INCREMENT STEP                :\n"
    "APPELLE Signorini Coulomb     :\n"
    "WRITE OUT DOF STEP 10         :\n"
    "REPETE 2 FOIS                 :\n"
    "DEPUIS loading step           :\n"
    "FIN DU PROGRAMME\n"
    "#-----------------------------:\n"
    "SUB Signorini Coulomb         :\n"
    ".doing Signorini Coulomb      : a message\n"
    "RECUP Rloc                    :\n"
    "NLGS CHECK TYPE               :\n"
    "Quad 0.1666D-04               : tol\n"
    "1.D0                          : RELAX\n"
    "EX PREP NLGS                  :\n"
    "Stored_Delassus_Loops         :\n"
    ">more                         :\n"
    "  >iteration                  :\n"
    "    EX ITER NLGS              :\n"
    "  REPETE 3 FOIS               :\n"
    "  DEPUIS >iteration           :\n"
    "  AFTER ITER CHECK            :\n"
    "  IOK = FLAG 1                :\n"
    "  INTO AFTER ITER CHECK       :\n"
    "  STOP REPETE SI IOK = 0      :\n"
    "REPETE 4 FOIS                 :\n"
    "DEPUIS >more                  :\n"
    "EX POST NLGS                  :\n"
    "STOCK Rloc                    :\n"
    "RETOUR                        :\n"
    "FIN DU FICHIER\n"
    "\n"
    "text after the end\n";

CommandFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_command(SourceText("COMMAND.DAT", text), sink);
}

std::size_t count(const std::vector<ExecutedCommand>& run, std::string_view keyword) {
  return static_cast<std::size_t>(
      std::count_if(run.begin(), run.end(), [&](const ExecutedCommand& c) { return c.keyword == keyword; }));
}

TEST(CommandParser, ClassifiesLinesAsChicReadsThem) {
  DiagnosticSink sink;
  const CommandFile f = parse(kProgram, sink);
  EXPECT_TRUE(sink.items().empty()) << sink.items()[0].message;
  ASSERT_EQ(f.lines.size(), 39u);
  EXPECT_EQ(f.lines[0].kind, CommandLineKind::comment);
  EXPECT_EQ(f.lines[1].kind, CommandLineKind::control);
  EXPECT_EQ(f.lines[2].kind, CommandLineKind::keyword);
  EXPECT_EQ(f.lines[2].keyword, "TIME STEP");
  EXPECT_EQ(f.lines[3].kind, CommandLineKind::argument);
  EXPECT_DOUBLE_EQ(f.lines[3].value->reals[0].value, 1e-3);
  EXPECT_EQ(f.lines[3].trailer, "                        : the step");
  EXPECT_EQ(f.lines[6].kind, CommandLineKind::label);
  EXPECT_EQ(f.lines[8].keyword, "APPEL");
  EXPECT_EQ(f.lines[8].parameter, "Signorini Coulomb");
  EXPECT_EQ(f.lines[9].keyword, "WRITE OUT DOF");
  EXPECT_EQ(f.lines[9].parameter, "STEP 10");
  EXPECT_EQ(f.lines[15].kind, CommandLineKind::message);
  EXPECT_EQ(f.lines[18].value->kind, CommandArgumentKind::type_tol);
  EXPECT_EQ(f.lines[18].value->word.value, "Quad");
  EXPECT_DOUBLE_EQ(f.lines[18].value->reals[0].value, 0.1666e-4);
  EXPECT_EQ(f.lines[21].value->word.value, "Stored_Delassus_Loops");
  EXPECT_EQ(f.lines[23].indent, 2u);
  EXPECT_EQ(f.lines[23].text.value, ">iteration");
  EXPECT_EQ(f.lines[23].kind, CommandLineKind::label);
  EXPECT_EQ(f.lines[26].parameter, ">iteration");
  EXPECT_EQ(f.lines[37].kind, CommandLineKind::after_end);
  EXPECT_EQ(f.lines[38].kind, CommandLineKind::after_end);
}

TEST(CommandWriter, ReproducesTheTextByteForByte) {
  for (const std::string& text :
       {kProgram, std::string("NO CHECK CHIC COMMAND  \r\nFIN DU PROGRAMME\r\nFIN DU FICHIER"),
        std::string("   \n#\n  x  :  y  \n"), std::string()}) {
    DiagnosticSink sink;
    EXPECT_EQ(write_command(parse(text, sink)), text);
  }
}

// state-and-outputs.md §2.1.2: REPETE n gives n + 1 passes. Never converged: (3+1) sweeps per
// check, (4+1) checks per step, (2+1) steps.
TEST(CommandExpansion, RepeteGivesOneMorePassThanItsCount) {
  DiagnosticSink sink;
  const CommandFile f = parse(kProgram, sink);
  const CommandFlagRule never_converged[] = {{"AFTER ITER CHECK", 1, 1}};
  const auto run = expand_command_program(f, 100000, sink, never_converged);
  EXPECT_TRUE(sink.items().empty());
  EXPECT_EQ(count(run, "INCREMENT STEP"), 3u);
  EXPECT_EQ(count(run, "AFTER ITER CHECK"), 3u * 5u);
  EXPECT_EQ(count(run, "EX ITER NLGS"), 3u * 5u * 4u);
  EXPECT_EQ(count(run, "EX POST NLGS"), 3u);
  EXPECT_EQ(run[0].keyword, "TIME STEP");
  ASSERT_EQ(run[0].arguments.size(), 1u);
  EXPECT_EQ(run[0].line, 3u);
  const auto nlgs = std::find_if(run.begin(), run.end(),
                                 [](const ExecutedCommand& c) { return c.keyword == "NLGS CHECK TYPE"; });
  ASSERT_NE(nlgs, run.end());
  EXPECT_EQ(nlgs->arguments.size(), 2u);
  EXPECT_EQ(nlgs->module, "nlgs");
}

// With every flag at 0, 'STOP REPETE SI IOK = 0' leaves the check loop at the first check, and
// the loop counters are reset so that the next step runs the loops again.
TEST(CommandExpansion, StopRepeteLeavesTheEnclosingLoop) {
  DiagnosticSink sink;
  const auto run = expand_command_program(parse(kProgram, sink), 100000, sink);
  EXPECT_EQ(count(run, "AFTER ITER CHECK"), 3u);
  EXPECT_EQ(count(run, "EX ITER NLGS"), 3u * 4u);
}

TEST(CommandExpansion, StopsAtTheBound) {
  DiagnosticSink sink;
  const auto run = expand_command_program(parse(kProgram, sink), 7, sink);
  EXPECT_EQ(run.size(), 7u);
}

TEST(CommandExpansion, CapJumpsToItsTarget) {
  const std::string text =
      "NO CHECK CHIC COMMAND\nstart\nINCREMENT STEP\nIOK = 1\nCAP SI IOK = 1\nSUR TOTO\nCOMPUTE DOF\nTOTO\n"
      "REPETE 1 FOIS\nDEPUIS start\nFIN DU PROGRAMME\nFIN DU FICHIER\n";
  DiagnosticSink sink;
  const auto run = expand_command_program(parse(text, sink), 100, sink);
  EXPECT_TRUE(sink.items().empty());
  EXPECT_EQ(count(run, "INCREMENT STEP"), 2u);
  EXPECT_EQ(count(run, "COMPUTE DOF"), 0u);
}

TEST(CommandExpansion, RunParametersOfTheProgram) {
  DiagnosticSink sink;
  const CommandRunParameters p = command_run_parameters(parse(kProgram, sink), sink);
  EXPECT_TRUE(sink.items().empty());
  EXPECT_DOUBLE_EQ(p.dt, 1e-3);
  EXPECT_EQ(p.steps, 3);
  EXPECT_EQ(p.norm, "Quad");
  EXPECT_DOUBLE_EQ(p.tolerance, 0.1666e-4);
  EXPECT_DOUBLE_EQ(p.relax, 1.0);
  EXPECT_EQ(p.storage, "Stored_Delassus_Loops");
  EXPECT_EQ(p.gs_it1, 4);
  EXPECT_EQ(p.gs_it2, 5);
  EXPECT_EQ(p.write_every, 10);
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  DiagnosticSink sink;
  parse(text, sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.column, column) << sink.items()[0].message;
}

const std::string kHead = "NO CHECK CHIC COMMAND\n";
const std::string kTail = "FIN DU PROGRAMME\nFIN DU FICHIER\n";

TEST(CommandBroken, MissingFinDuProgramme) {
  expect_diagnostic("COMPUTE BOX\nCOMPUTE MASS\n", "L1012", 2, 13);
}
TEST(CommandBroken, MissingFinDuFichier) {
  expect_diagnostic(kHead + "FIN DU PROGRAMME\nSUB x\n", "L1012", 3, 6);
}
TEST(CommandBroken, UnknownKeywordIsAWarning) {
  DiagnosticSink sink;
  parse(kHead + "  COMPTE MASS   : typo\n" + kTail, sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].severity, Severity::warning);
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 3u);
}
TEST(CommandBroken, MalformedRealArgument) {
  expect_diagnostic(kHead + "TIME STEP\n  1.x-3\n" + kTail, "L1002", 3, 3);
}
TEST(CommandBroken, MalformedIntegerArgument) {
  expect_diagnostic(kHead + "CUNDALL ITERATION\n2.5\n" + kTail, "L1004", 3, 1);
}
TEST(CommandBroken, MissingToleranceOfTheCheckType) {
  expect_diagnostic(kHead + "NLGS CHECK TYPE\nQuad\n1.\n" + kTail, "L1015", 3, 1);
}
TEST(CommandBroken, WriteOutWithoutStep) {
  expect_diagnostic(kHead + "WRITE OUT DOF\n" + kTail, "L1015", 2, 1);
}
TEST(CommandBroken, CallOfAMissingSubroutine) {
  expect_diagnostic(kHead + "APPELLE reading data\n" + kTail, "L1012", 2, 1);
}
TEST(CommandBroken, SubroutineWithoutRetour) {
  expect_diagnostic(kHead + "APPELLE x\nFIN DU PROGRAMME\nSUB x\nREAD BODIES\nFIN DU FICHIER\n", "L1012", 4,
                    1);
}
TEST(CommandBroken, LoopLabelNotFound) {
  expect_diagnostic(kHead + "REPETE 3 FOIS\nDEPUIS nowhere\n" + kTail, "L1012", 3, 1);
}
TEST(CommandBroken, RepeteWithoutFois) {
  expect_diagnostic(kHead + "a\nREPETE 3\nDEPUIS a\n" + kTail, "L1004", 3, 1);
}
TEST(CommandBroken, RepeteNotFollowedByDepuis) {
  expect_diagnostic(kHead + "a\nREPETE 3 FOIS\na\n" + kTail, "L1013", 4, 1);
}
TEST(CommandBroken, FlagNumberOutOfRange) {
  expect_diagnostic(kHead + "IOK = FLAG 16\nINTO AFTER ITER CHECK\n" + kTail, "L1003", 2, 7);
}
TEST(CommandBroken, MissingComputeBox) {
  expect_diagnostic("COMPUTE MASS\n" + kTail, "L1012", 3, 15);
}
TEST(CommandBroken, ArgumentCutByTheEndOfTheSection) {
  expect_diagnostic(kHead + "FIN DU PROGRAMME\nSUB x\nRETOUR\nTHETA\nFIN DU FICHIER\n", "L1002", 6, 1);
}

}  // namespace
}  // namespace lmgc::grammar
