// DOF.INI / DOF.OUT.n / DOF.LAST: what the parser reads, the writer's layout, and one exact
// diagnostic (code, line, column) per broken input.
#include <gtest/gtest.h>

#include <string>

#include "grammar/dof/parser.hpp"
#include "grammar/dof/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kDashes = "!" + std::string(71, '-') + "\n";
const std::string kHeader =
    "     \n! DOF\n     \n$steps        0              time= 0.0000000D+00\n \n" + kDashes;
const std::string kLead = std::string(27, ' ');
const std::string kXLine = " NO3xx      1" + std::string(14, ' ') +
                           "  X(1)= 0.1000000D+01  X(2)=-0.2000000D+01  X(3)= 0.3000000D+00";
const std::string kVLine = kLead + "  V(1)= 0.0000000D+00  V(2)= 0.0000000D+00  V(3)= 0.1000000D-02";

std::string rbdy2_body() {
  return "$bdyty\n RBDY2        1\n$nodty\n" + kXLine + "\n" + kVLine + "\n$$$$$$\n      \n";
}

DofFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_dof(SourceText("DOF.INI", text), sink);
}

void expect_one(const DiagnosticSink& sink, const std::string& code, std::uint32_t line,
                std::uint32_t column) {
  ASSERT_FALSE(sink.items().empty()) << "expected " << code;
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.column, column) << sink.items()[0].message;
}

TEST(DofParser, ReadsRbdy2AndWritesItBack) {
  const std::string text = kHeader + rbdy2_body() + kDashes + kDashes;
  DiagnosticSink sink;
  const DofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 0u);
  EXPECT_EQ(file.step.value, 0);
  ASSERT_EQ(file.sections.size(), 2u);  // RBDY2 module, then an empty module
  ASSERT_EQ(file.sections[0].bodies.size(), 1u);
  const DofNode& node = file.sections[0].bodies[0].nodes[0];
  ASSERT_EQ(node.x.size(), 3u);
  EXPECT_DOUBLE_EQ(node.x[1].value, -2.0);
  EXPECT_DOUBLE_EQ(node.v[2].value, 0.001);
  EXPECT_TRUE(node.frame.empty());
  EXPECT_EQ(write_dof(file), text);
}

TEST(DofParser, ReadsRbdy3FrameAndThermalMailx) {
  const std::string rbdy3 =
      "$bdyty\n RBDY3        2\n$nodty\n NO6xx      1" + std::string(14, ' ') +
      "  X(1)= 0.1000000D+01  X(2)= 0.0000000D+00  X(3)= 0.0000000D+00\n" + kLead +
      "  X(4)= 0.0000000D+00  X(5)= 0.0000000D+00  X(6)= 0.0000000D+00\n" + kLead +
      "  V(1)= 0.0000000D+00  V(2)= 0.0000000D+00  V(3)= 0.0000000D+00\n" + kLead +
      "  V(4)= 0.0000000D+00  V(5)= 0.0000000D+00  V(6)= 0.2000000D+01\n" + kLead +
      "  a(1)= 0.1000000D+01  a(2)= 0.0000000D+00  a(3)= 0.0000000D+00\n" + kLead +
      "  b(1)= 0.0000000D+00  b(2)= 0.1000000D+01  b(3)= 0.0000000D+00\n" + kLead +
      "  g(1)= 0.0000000D+00  g(2)= 0.0000000D+00  g(3)= 0.1000000D+01\n$$$$$$\n      \n";
  const std::string thermal = "$bdyty\n MAILx      1\n$model\n THERM\n$nodty\n NO1xx      1" +
                              std::string(14, ' ') + "  T(1)= 0.2930000D+03\n NO1xx      2" +
                              std::string(14, ' ') + "  T(1)= 0.2948538D+03\n$$$$$$\n      \n";
  const std::string text = kHeader + rbdy3 + kDashes + thermal + kDashes;
  DiagnosticSink sink;
  const DofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 0u);
  ASSERT_EQ(file.sections.size(), 2u);
  const DofNode& rigid = file.sections[0].bodies[0].nodes[0];
  EXPECT_EQ(rigid.frame.size(), 9u);
  EXPECT_DOUBLE_EQ(rigid.v[5].value, 2.0);
  const DofBody& mailx = file.sections[1].bodies[0];
  EXPECT_EQ(mailx.model.value, "THERM");
  ASSERT_EQ(mailx.nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(mailx.nodes[1].x[0].value, 294.8538);
  EXPECT_EQ(write_dof(file), text);
}

TEST(DofParser, HandWrittenIniWithoutDashesAndLabelsIgnored) {
  // datbox-inputs.md §6: labels are not read; a label that is not LMGC90's is said (L1022), its
  // value read.
  const std::string text = "$steps      5                time= 0.5000000D+00\n$bdyty\n RBDY2  3\n$nodty\n" +
                           kXLine + "\n" + kLead + "  c(1)= 0.1000000D+01\n$$$$$$\n";
  DiagnosticSink sink;
  const DofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1022");
  EXPECT_EQ(file.step.value, 5);
  ASSERT_EQ(file.sections.size(), 1u);
  EXPECT_FALSE(file.sections[0].closed);
  EXPECT_EQ(file.sections[0].bodies[0].number.value, 3);
  EXPECT_DOUBLE_EQ(file.sections[0].bodies[0].nodes[0].v[0].value, 1.0);
}

// A damaged label: LMGC90 reads the value by its columns; a warning points at the label (L1022).
TEST(DofParser, DamagedLabelIsAWarningAndTheValueIsRead) {
  std::string x_line = kXLine;
  x_line.replace(x_line.find("X(2)="), 5, "X(2)#");
  const std::string text = kHeader + "$bdyty\n RBDY2        1\n$nodty\n" + x_line + "\n" + kLead +
                           "  V(1)= 0.1000000D+01\n$$$$$$\n";
  DiagnosticSink sink;
  const DofFile file = parse(text, sink);
  expect_one(sink, "L1022", 10, static_cast<std::uint32_t>(kXLine.find("X(2)=") + 1));
  EXPECT_EQ(sink.items()[0].severity, Severity::warning);
  ASSERT_EQ(file.sections.size(), 1u);
  EXPECT_EQ(file.sections[0].bodies[0].nodes[0].x.size(), 3u);
}

// Broken inputs: one exact diagnostic each.
TEST(DofBroken, MissingStepsHeader) {
  DiagnosticSink sink;
  parse("! DOF\n" + rbdy2_body(), sink);
  expect_one(sink, "L1012", 2, 1);
}

TEST(DofBroken, TruncatedNode) {
  DiagnosticSink sink;
  parse(kHeader + "$bdyty\n RBDY2        1\n$nodty\n" + kXLine + "\n", sink);
  expect_one(sink, "L1006", 10, static_cast<std::uint32_t>(kXLine.size() + 1));
}

TEST(DofBroken, UnknownBodyType) {
  DiagnosticSink sink;
  std::string text = kHeader + rbdy2_body();
  text.replace(text.find("RBDY2"), 5, "RBDY9");
  parse(text, sink);
  expect_one(sink, "L1001", 8, 2);
}

TEST(DofBroken, MalformedValue) {
  DiagnosticSink sink;
  std::string text = kHeader + rbdy2_body();
  text.replace(text.find("-0.2000000D+01"), 14, "-0.2000x00D+01");
  parse(text, sink);
  expect_one(sink, "L1002", 10, 56);
}

TEST(DofBroken, MissingNodty) {
  DiagnosticSink sink;
  parse(kHeader + "$bdyty\n RBDY2        1\n" + kXLine + "\n" + kVLine + "\n$$$$$$\n", sink);
  expect_one(sink, "L1012", 9, 1);
}

TEST(DofBroken, EndOfBlockWhereVelocityLineIsExpected) {
  DiagnosticSink sink;
  parse(kHeader + "$bdyty\n RBDY2        1\n$nodty\n" + kXLine + "\n$$$$$$\n", sink);
  expect_one(sink, "L1013", 11, 1);
}

TEST(DofBroken, BlockNotClosedBeforeNextBody) {
  DiagnosticSink sink;
  parse(kHeader + "$bdyty\n RBDY2        1\n$nodty\n" + kXLine + "\n" + kVLine + "\n" + rbdy2_body(), sink);
  expect_one(sink, "L1005", 12, 1);
}

TEST(DofBroken, Rbdy3BodyNumberMissing) {
  DiagnosticSink sink;
  std::string text = kHeader + rbdy2_body();
  text.replace(text.find(" RBDY2        1"), 15, " RBDY3");
  parse(text, sink);
  expect_one(sink, "L1015", 8, 9);
}

TEST(DofBroken, StepsTimeShiftedRight) {
  DiagnosticSink sink;
  // One column right: LMGC90 reads '0.1000000D+0' (0.1) from 35-48 instead of 1.
  std::string steps = "$steps      0";
  steps.resize(34, ' ');
  parse(steps + "  0.1000000D+01\n" + rbdy2_body(), sink);
  expect_one(sink, "L1011", 1, 35);
}

TEST(DofBroken, TimeShiftedLeftLosingOnlyAZeroIsAccepted) {
  DiagnosticSink sink;
  const DofFile file = parse("$steps      0              time= 0.0000000D+00\n" + rbdy2_body(), sink);
  EXPECT_EQ(sink.items().size(), 0u);
  EXPECT_EQ(file.time.value, 0.0);
}

TEST(DofBroken, NeverCrashesOnGarbage) {
  const std::string inputs[] = {"$steps",
                                "$bdyty",
                                "$steps\n$bdyty\n MAILx\n$model\n MECAx\n$nodty\n NO2xx",
                                "$steps\n$bdyty\n RBDY3 x\n$nodty\n NO6xx\n",
                                "!rigid part\n$bdyty\n MAILx\n",
                                std::string(300, '!') + "\n" + std::string(300, '$')};
  for (const auto& text : inputs) {
    DiagnosticSink sink;
    parse(text, sink);  // reports or not, but returns
    EXPECT_LE(sink.items().size(), 1000u);
  }
}

}  // namespace
}  // namespace lmgc::grammar
