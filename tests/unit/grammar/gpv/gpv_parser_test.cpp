// GPV files: bodies, elements, model blocks of Gauss-point values; broken files.
#include "grammar/gpv/parser.hpp"

#include <gtest/gtest.h>

#include "grammar/gpv/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kFile =
    "     \n! Gauss Point Values\n      \n$steps      100              time= 0.1000000D+00\n \n"
    "!-----------------------------------------------------------------------\n"
    "$bdyty\n MAILx      1\n$blmty\n Q4xxx      1\n$model\n THERM\n"
    " 0.2930000D+03\n 0.1853783D+03-0.3637979D-11 0.0000000D+00\n"
    "$$$$$$\n!-----------------------------------------------------------------------\n";

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line, std::uint32_t column) {
  DiagnosticSink sink;
  parse_gpv(SourceText("GPV.INI", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(GpvParser, ReadsValuesWithoutSeparators) {
  DiagnosticSink sink;
  const GpvFile f = parse_gpv(SourceText("GPV.LAST", kFile), sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.bodies.size(), 1u);
  const auto& block = f.bodies[0].elements[0].models[0];
  EXPECT_EQ(block.model.value, "THERM");
  ASSERT_EQ(block.lines.size(), 2u);
  ASSERT_EQ(block.lines[1].size(), 3u);
  EXPECT_DOUBLE_EQ(block.lines[1][1].value, -0.3637979e-11);
}

TEST(GpvWriter, CanonicalTextIsAFixedPoint) {
  DiagnosticSink sink;
  EXPECT_EQ(write_gpv(parse_gpv(SourceText("GPV.LAST", kFile), sink)), kFile);
}

TEST(GpvBroken, MissingStepsHeader) { expect_diagnostic("$bdyty\n MAILx      1\n$$$$$$\n", "L1012", 3, 7); }
TEST(GpvBroken, NotAMailxBody) {
  std::string t = kFile;
  t.replace(t.find(" MAILx"), 6, " RBDY2");
  expect_diagnostic(t, "L1001", 8, 2);
}
TEST(GpvBroken, UnclosedBody) {
  std::string t = kFile.substr(0, kFile.find("$$$$$$"));
  expect_diagnostic(t, "L1005", 14, 43);
}
TEST(GpvBroken, MalformedValue) {
  std::string t = kFile;
  t.replace(t.find("0.2930000D+03"), 13, "0.29300O0D+03");
  expect_diagnostic(t, "L1002", 13, 1);
}
TEST(GpvBroken, StrayLineBetweenBodies) { expect_diagnostic(kFile + "garbage\n", "L1013", 17, 1); }
TEST(GpvBroken, TruncatedAfterModel) {
  expect_diagnostic("$steps      0                time= 0.0000000D+00\n$bdyty\n MAILx      1\n$blmty\n Q4xxx      1\n$model\n",
                    "L1006", 6, 7);
}

}  // namespace
}  // namespace lmgc::grammar
