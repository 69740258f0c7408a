// POSTPRO.DAT: commands and arguments as LMGC90 reads them, and broken files.
#include "grammar/postpro/parser.hpp"

#include <gtest/gtest.h>

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

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line, std::uint32_t column) {
  DiagnosticSink sink;
  parse_postpro(SourceText("POSTPRO.DAT", text), sink);
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
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, "L1019");
}

TEST(PostproParser, DimensionDecidesTheSectorsArgument) {
  const std::string text = "NORMAL CONTACT DISTRIBUTION   :\nSTEP 1\n12\nEND\n";
  DiagnosticSink s2, s3;
  EXPECT_EQ(parse_postpro(SourceText("P", text), s2, 2).commands[0].arguments.size(), 1u);
  EXPECT_TRUE(parse_postpro(SourceText("P", text), s3, 3).commands[0].arguments.empty());
}

TEST(PostproBroken, UnknownCommand) { expect_diagnostic("BODY TRAKING\nSTEP 1\nEND\n", "L1001", 1, 1); }
TEST(PostproBroken, BlankLine) { expect_diagnostic("\nEND\n", "L1013", 1, 1); }
TEST(PostproBroken, MissingStepLine) { expect_diagnostic("SOLVER INFORMATIONS\nEND\n", "L1013", 2, 1); }
TEST(PostproBroken, StepWithoutPeriod) { expect_diagnostic("SOLVER INFORMATIONS\nSTEP\nEND\n", "L1015", 2, 5); }
TEST(PostproBroken, MissingEnd) { expect_diagnostic("SOLVER INFORMATIONS\nSTEP 1\n", "L1012", 2, 7); }
TEST(PostproBroken, BodyListCutShort) { expect_diagnostic("BODY TRACKING\nSTEP 1\n3\n1\n", "L1006", 4, 2); }
TEST(PostproBroken, MalformedBodyNumber) { expect_diagnostic("BODY TRACKING\nSTEP 1\n1\n5x\nEND\n", "L1004", 4, 1); }

TEST(PostproWriter, CanonicalLayoutRoundTrips) {
  DiagnosticSink sink;
  const PostproFile f = parse_postpro(SourceText("POSTPRO.DAT", kFile), sink);
  const std::string text = write_postpro(f);
  EXPECT_EQ(text, kFile);
}

}  // namespace
}  // namespace lmgc::grammar
