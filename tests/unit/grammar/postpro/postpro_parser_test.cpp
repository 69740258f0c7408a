// POSTPRO.DAT: commands and arguments as LMGC90 reads them, and broken files.
#include <gtest/gtest.h>

#include "grammar/postpro/parser.hpp"
#include "grammar/postpro/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kFile =
    "#23456789012345678901234567890:\n"
    "BODY TRACKING                 :\n"
    "STEP 1                        :\n"
    "2                             :\n"
    "54                            :\n"
    "1025                          :\n"
    "SOLVER INFORMATIONS           :\n"
    "STEP 10                       :\n"
    "END                           :\n";

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column, int dimension = 2) {
  DiagnosticSink sink;
  parse_postpro(SourceText("POSTPRO.DAT", text), sink, dimension);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(PostproParser, ReadsCommandsPeriodsAndBodyLists) {
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", kFile), sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.commands.size(), 2u);
  EXPECT_EQ(f.commands[0].name.value, "BODY TRACKING");
  ASSERT_EQ(f.commands[0].arguments.size(), 3u);
  EXPECT_EQ(f.commands[0].arguments[2].integers[0].value, 1025);
  EXPECT_EQ(f.commands[1].period.value, 10);
}

TEST(PostproParser, ACommandReadAsAColourIsConsumedWithAWarning) {
  const std::string text =
      "AVERAGE VELOCITY EVOLUTION    :\nSTEP 1                        :\n"
      "DENSE SAMPLE COMPACITY        :\nSTEP 1                        :\nEND\n";
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", text), sink);
  ASSERT_EQ(f.commands.size(), 1u);
  EXPECT_EQ(f.commands[0].arguments[0].word.value, "DENSE");
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 3u);
  EXPECT_FALSE(sink.has_errors());
}

// RIGID_2D/500PL_PerioBoxJC: the consumed command's STEP line is then skipped as a STEP line,
// and the commands after it are read normally.
TEST(PostproParser, CommandsAfterAConsumedOneAreRead) {
  const std::string text =
      "AVERAGE VELOCITY EVOLUTION    :\nSTEP 1                        :\n"
      "DENSE SAMPLE COMPACITY        :\nSTEP 1                        :\n"
      "TORQUE EVOLUTION              :\nSTEP 1\n1\n501\nEND\n";
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", text), sink, 2);
  ASSERT_EQ(f.commands.size(), 2u);
  EXPECT_EQ(f.commands[1].name.value, "TORQUE EVOLUTION");
  EXPECT_EQ(f.commands[1].arguments[1].integers[0].value, 501);
}

TEST(PostproParser, ReadsEveryArgumentFormat) {
  const std::string text =
      "MP VALUE TRACKING\nSTEP 2\n1\n     12 3\n"
      "NEW MECAx SETS\nSTEP 1\n      1\n      1\n      1      2 \n      2\n      4\n"
      "NEW DIST SETS\nSTEP 1\n1\n1, 2 3 4\n"
      "COMPACITY EVOLUTION\nSTEP 1\nMAT01\nCOUETTE\n7\n8\n"
      "QUASI SLIDING CONTACT\nSTEP 1\n 2.5000000E-01\n"
      "DENSE SAMPLE COMPACITY\nSTEP 1\nINTER   1024\n"
      "CLxxx ANALYSIS\nSTEP 1\n1\n 5 6\nEND\n";
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", text), sink, 2);
  EXPECT_TRUE(sink.items().empty()) << sink.items()[0].message;
  ASSERT_EQ(f.commands.size(), 7u);
  EXPECT_EQ(f.commands[0].period.value, 2);
  EXPECT_EQ(f.commands[0].arguments[1].integers[0].value, 12);
  EXPECT_EQ(f.commands[0].arguments[1].integers[1].value, 3);
  EXPECT_EQ(f.commands[1].arguments.size(), 5u);
  EXPECT_EQ(f.commands[1].arguments[2].integers[1].value, 2);
  EXPECT_EQ(f.commands[2].arguments[1].integers.size(), 4u);
  EXPECT_EQ(f.commands[3].arguments.size(), 4u);
  EXPECT_DOUBLE_EQ(f.commands[4].arguments[0].reals[0].value, 0.25);
  EXPECT_EQ(f.commands[5].arguments[0].integers[0].value, 1024);
  EXPECT_EQ(f.commands[6].arguments[1].integers[1].value, 6);
  // The canonical writer reads back to the same file.
  DiagnosticSink again;
  EXPECT_TRUE(parse_postpro(SourceText("echo", write_postpro(f)), again, 2) == f);
  EXPECT_TRUE(again.items().empty());
}

TEST(PostproParser, UnknownDimensionAcceptsCommandsOfBothReaders) {
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(
      SourceText("P", "TRIAXIAL COMPACITY\nSTEP 1\n1\n2\n3\n4\n5\n6\nPLPLx ANALYSIS\nSTEP 1\nEND\n"), sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(f.commands.size(), 2u);
}

TEST(PostproParser, DimensionDecidesTheSectorsArgument) {
  const std::string text = "NORMAL CONTACT DISTRIBUTION   :\nSTEP 1\n12\nEND\n";
  DiagnosticSink s2, s3;
  EXPECT_EQ(parse_postpro(SourceText("P", text), s2, 2).commands[0].arguments.size(), 1u);
  EXPECT_TRUE(parse_postpro(SourceText("P", text), s3, 3).commands[0].arguments.empty());
}

TEST(PostproBroken, UnknownCommand) {
  expect_diagnostic("BODY TRAKING\nSTEP 1\nEND\n", "L1001", 1, 1);
}
// LMGC90 stops at an unknown command: its STEP and argument lines are skipped up to the next
// command, not reported one by one.
TEST(PostproBroken, UnknownCommandSkipsItsArguments) {
  std::string t = kFile;
  t.replace(t.find("BODY TRACKING "), 14, "BODY TRAKING  ");
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", t), sink, 2);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1001");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  ASSERT_EQ(f.commands.size(), 1u);
  EXPECT_EQ(f.commands[0].name.value, "SOLVER INFORMATIONS");
}
// An I7 argument is columns 1-7 of its line: a longer number is read cut, and said so.
TEST(PostproBroken, BodyNumberSpillsOutOfI7) {
  std::string t = kFile;
  t.replace(t.find("1025    "), 8, "10250000");
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", t), sink, 2);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1011");
  EXPECT_EQ(sink.items()[0].severity, Severity::warning);
  EXPECT_EQ(sink.items()[0].where.span.line, 6u);
  EXPECT_EQ(sink.items()[0].where.span.column, 1u);
  EXPECT_EQ(f.commands[0].arguments[2].integers[0].value, 1025000);
}
TEST(PostproBroken, BlankLine) {
  expect_diagnostic("\nEND\n", "L1013", 1, 1);
}
TEST(PostproBroken, MissingStepLine) {
  expect_diagnostic("SOLVER INFORMATIONS\nEND\n", "L1013", 2, 1);
}
TEST(PostproBroken, StepWithoutPeriod) {
  expect_diagnostic("SOLVER INFORMATIONS\nSTEP\nEND\n", "L1015", 2, 5);
}
TEST(PostproBroken, MissingEnd) {
  expect_diagnostic("SOLVER INFORMATIONS\nSTEP 1\n", "L1012", 2, 7);
}
TEST(PostproBroken, BodyListCutShort) {
  expect_diagnostic("BODY TRACKING\nSTEP 1\n3\n1\n", "L1006", 4, 2);
}
TEST(PostproBroken, MalformedBodyNumber) {
  expect_diagnostic("BODY TRACKING\nSTEP 1\n1\n5x\nEND\n", "L1004", 4, 1);
}
TEST(PostproBroken, CommandOfTheOtherDimension) {
  expect_diagnostic("#\nTRIAXIAL COMPACITY\nSTEP 1\nEND\n", "L1001", 2, 1, 2);
}
TEST(PostproBroken, ZeroPeriod) {
  expect_diagnostic("KINETIC ENERGY\nSTEP   0\nEND\n", "L1003", 2, 8);
}
TEST(PostproBroken, MalformedPeriod) {
  expect_diagnostic("KINETIC ENERGY\nSTEP x1\nEND\n", "L1004", 2, 6);
}
TEST(PostproBroken, UnknownCompacityModel) {
  expect_diagnostic("COMPACITY EVOLUTION\nSTEP 1\nMAT01\nDENSE SAMPLE\nEND\n", "L1017", 4, 1);
}
TEST(PostproBroken, PairWithOneValue) {
  expect_diagnostic("DOUBLETS TORQUE EVOLUTION\nSTEP 1\n1\n 7\nEND\n", "L1015", 4, 1, 3);
}
TEST(PostproBroken, MalformedListedInteger) {
  expect_diagnostic("CONTACT FORCE DISTRIBUTION\nSTEP 1\n  1.5\nEND\n", "L1004", 3, 3, 3);
}
TEST(PostproBroken, LeadingBlankBeforeACommandName) {
  expect_diagnostic("#\n SOLVER INFORMATIONS\nSTEP 1\nEND\n", "L1001", 2, 1);
}

TEST(PostproWriter, CanonicalLayoutRoundTrips) {
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", kFile), sink);
  const std::string text = write_postpro(f);
  EXPECT_EQ(text, kFile);
}

}  // namespace
}  // namespace lmgc::grammar
