// GPV files: bodies, elements, model blocks of Gauss-point values kept line by line; broken files
// with their exact diagnostic.
#include <gtest/gtest.h>

#include "grammar/gpv/parser.hpp"
#include "grammar/gpv/writer.hpp"

namespace lmgc::grammar {
namespace {

// Lines 1-16.
const std::string kFile =
    "     \n! Gauss Point Values\n      \n$steps      100              time= 0.1000000D+00\n \n"
    "!-----------------------------------------------------------------------\n"
    "$bdyty\n MAILx      1\n$blmty\n Q4xxx      1\n$model\n THERM\n"
    " 0.2930000D+03\n 0.1853783D+03-0.3637979D-11 0.0000000D+00\n"
    "$$$$$$\n!-----------------------------------------------------------------------\n";

// A MECAx element whose internal-variable vector (11 values) wraps after 9 values, as '(9D14.7)'
// writes it, then an empty vector (an empty record).
const std::string kWrapped =
    "     \n! Gauss Point Values\n      \n$steps        2              time= 0.2000000D-01\n \n"
    "!-----------------------------------------------------------------------\n"
    "$bdyty\n MAILx      3\n$blmty\n H8xxx     12\n$model\n MECAx\n"
    "-0.1000000D+01 0.2000000D+01 0.3000000D+01 0.4000000D+01 0.5000000D+01 0.6000000D+01\n"
    " 0.1000000D-03 0.2000000D-03 0.3000000D-03 0.4000000D-03 0.5000000D-03 0.6000000D-03\n"
    " 0.1000000D+00 0.2000000D+00 0.3000000D+00 0.4000000D+00 0.5000000D+00 0.6000000D+00"
    " 0.7000000D+00 0.8000000D+00 0.9000000D+00\n"
    " 0.1000000D+01 0.1100000D+01\n"
    "\n"
    "$blmty\n H8xxx     13\n$model\n MECAx\n 0.1000000D+01\n$model\n THERM\n 0.2930000D+03\n"
    "$$$$$$\n!-----------------------------------------------------------------------\n";

GpvFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_gpv(SourceText("GPV.LAST", text), sink);
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  DiagnosticSink sink;
  parse_gpv(SourceText("GPV.INI", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(GpvParser, ReadsValuesWithoutSeparators) {
  DiagnosticSink sink;
  const GpvFile f = parse(kFile, sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(f.step.value, 100);
  ASSERT_EQ(f.bodies.size(), 1u);
  EXPECT_EQ(f.bodies[0].number.value, 1);
  const auto& block = f.bodies[0].elements[0].models[0];
  EXPECT_EQ(block.model.value, "THERM");
  ASSERT_EQ(block.lines.size(), 2u);
  ASSERT_EQ(block.lines[1].size(), 3u);
  EXPECT_DOUBLE_EQ(block.lines[1][1].value, -0.3637979e-11);
}

TEST(GpvParser, WrappedAndEmptyVectorsAreKeptLineByLine) {
  DiagnosticSink sink;
  const GpvFile f = parse(kWrapped, sink);
  EXPECT_EQ(sink.items().size(), 0u);
  ASSERT_EQ(f.bodies.size(), 1u);
  ASSERT_EQ(f.bodies[0].elements.size(), 2u);
  const GpvElement& first = f.bodies[0].elements[0];
  EXPECT_EQ(first.type.value, "H8xxx");
  EXPECT_EQ(first.number.value, 12);
  ASSERT_EQ(first.models.size(), 1u);
  const auto& lines = first.models[0].lines;
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[2].size(), 9u);
  EXPECT_EQ(lines[3].size(), 2u);
  EXPECT_TRUE(lines[4].empty());
  EXPECT_DOUBLE_EQ(lines[0][0].value, -1.0);
  const GpvElement& second = f.bodies[0].elements[1];
  ASSERT_EQ(second.models.size(), 2u);
  EXPECT_EQ(second.models[1].model.value, "THERM");
}

TEST(GpvWriter, CanonicalTextIsAFixedPoint) {
  DiagnosticSink sink;
  EXPECT_EQ(write_gpv(parse(kFile, sink)), kFile);
  EXPECT_EQ(write_gpv(parse(kWrapped, sink)), kWrapped);
}

TEST(GpvWriter, FileWithoutBodiesEndsWithTheDashedLine) {
  GpvFile f;
  f.step = Integer{0};
  f.time = Real{0.0};
  const std::string text = write_gpv(f);
  EXPECT_EQ(text.substr(text.size() - 73),
            "!-----------------------------------------------------------------------\n");
  DiagnosticSink sink;
  EXPECT_EQ(parse(text, sink), f);
  EXPECT_FALSE(sink.has_errors());
}

TEST(GpvParser, HeaderOnlyInitialFile) {
  DiagnosticSink sink;
  const GpvFile f =
      parse("! Gauss Point Values\n\n$steps      0                time= 0.0000000D+00      \n", sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_TRUE(f.bodies.empty());
}

TEST(GpvParser, EveryTruncationOfAFileIsReadWithoutCrashing) {
  for (std::size_t size = 0; size <= kWrapped.size(); ++size) {
    DiagnosticSink sink;
    const GpvFile f = parse(kWrapped.substr(0, size), sink);
    EXPECT_LE(f.bodies.size(), 1u);
    (void)write_gpv(f);
  }
}

// Broken inputs: one diagnostic each, with its exact code and position.
TEST(GpvBroken, MissingStepsHeader) {
  expect_diagnostic("$bdyty\n MAILx      1\n$$$$$$\n", "L1012", 1, 2);
}
TEST(GpvBroken, NotAMailxBody) {
  std::string t = kFile;
  t.replace(t.find(" MAILx"), 6, " RBDY2");
  expect_diagnostic(t, "L1001", 8, 2);
}
TEST(GpvBroken, UnknownElement) {
  std::string t = kFile;
  t.replace(t.find(" Q4xxx"), 6, " Q5xxx");
  expect_diagnostic(t, "L1001", 10, 2);
}
TEST(GpvBroken, UnclosedBody) {
  std::string t = kFile.substr(0, kFile.find("$$$$$$"));
  expect_diagnostic(t, "L1005", 14, 43);
}
TEST(GpvBroken, NextBodyBeforeTheEndOfThisOne) {
  std::string t = kFile;
  t.replace(t.find("$$$$$$"), 6, "$bdyty\n MAILx      2\n$$$$$$");
  expect_diagnostic(t, "L1005", 15, 1);  // at the '$bdyty' keyword, column 1 as in BODIES and DRV_DOF
}
TEST(GpvBroken, MalformedValue) {
  std::string t = kFile;
  t.replace(t.find("0.2930000D+03"), 13, "0.29300O0D+03");
  expect_diagnostic(t, "L1002", 13, 1);
}
TEST(GpvBroken, MalformedSecondValueOfALine) {
  std::string t = kFile;
  t.replace(t.find("-0.3637979D-11"), 14, "-0.36379x9D-11");
  expect_diagnostic(t, "L1002", 14, 15);
}
TEST(GpvBroken, MalformedElementNumber) {
  std::string t = kFile;
  t.replace(t.find(" Q4xxx      1"), 13, " Q4xxx     1a");
  expect_diagnostic(t, "L1004", 10, 7);
}
TEST(GpvBroken, StrayLineBetweenBodies) {
  expect_diagnostic(kFile + "garbage\n", "L1013", 17, 1);
}
TEST(GpvBroken, TruncatedAfterModel) {
  expect_diagnostic(
      "$steps      0                time= 0.0000000D+00\n$bdyty\n MAILx      1\n$blmty\n Q4xxx      "
      "1\n$model\n",
      "L1006", 6, 7);
}

}  // namespace
}  // namespace lmgc::grammar
