// Vloc_Rloc: interaction blocks by module, and broken files with their exact diagnostic.
#include "grammar/vloc_rloc/parser.hpp"

#include <gtest/gtest.h>

#include "grammar/vloc_rloc/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kHeader =
    "     \n! Vloc_Rloc\n      \n$steps      300              time= 0.6000000D-01\n \n"
    "!-----------------------------------------------------------------------\n";
const std::string kBlock =
    "$icdan  DKDKx      642\n"
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj\n"
    " RBDY2      2  DISKx      1  iqsc1  RBDY2    844  DISKx      1  stick    844\n"
    "                             rlt/H-0.4336294D-01  rln/H 0.1146651D+00  rls/H 0.0000000D+00\n"
    "                             vlt =-0.6938894D-17  vln =-0.1258967D-07  vls = 0.0000000D+00\n"
    "                             gapTT 0.0000000D+00\n"
    "                             n(1)= 0.8987325D+00  n(2)= 0.4384974D+00  n(3)= 0.0000000D+00\n"
    "                             coo1= 0.8982992D-01  coo2= 0.9350228D-03  coo3= 0.0000000D+00\n"
    " \n";

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line, std::uint32_t column) {
  DiagnosticSink sink;
  parse_vloc_rloc(SourceText("Vloc_Rloc.INI", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(VlocRlocParser, ReadsTheDataLineAndVectors) {
  DiagnosticSink sink;
  const VlocRlocFile f = parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", kHeader + kBlock), sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(f.step.value, 300);
  ASSERT_EQ(f.interactions.size(), 1u);
  const VlocRlocInteraction& c = f.interactions[0];
  EXPECT_EQ(c.number.value, 642);
  ASSERT_EQ(c.words.size(), 6u);  // cdbdy, cdtac, behav, anbdy, antac, sttus
  EXPECT_EQ(c.words[3].value, "RBDY2");
  EXPECT_EQ(c.words[5].value, "stick");
  ASSERT_EQ(c.integers.size(), 5u);
  EXPECT_EQ(c.integers[2].value, 844);
  ASSERT_EQ(c.vectors.size(), 5u);
  EXPECT_DOUBLE_EQ(c.vectors[0].values[1].value, 0.1146651);
  EXPECT_EQ(c.vectors[2].labels[0], "gapTT");
}

TEST(VlocRlocWriter, CanonicalTextIsAFixedPoint) {
  DiagnosticSink sink;
  const std::string text = kHeader + kBlock;
  EXPECT_EQ(write_vloc_rloc(parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", text), sink)), text);
}

TEST(VlocRlocParser, HeaderOnlyFileHasNoInteraction) {
  DiagnosticSink sink;
  EXPECT_TRUE(parse_vloc_rloc(SourceText("Vloc_Rloc.INI", kHeader), sink).interactions.empty());
  EXPECT_FALSE(sink.has_errors());
}

TEST(VlocRlocBroken, MissingStepsHeader) { expect_diagnostic("! nothing\n!\n" + kBlock, "L1012", 11, 2); }
TEST(VlocRlocBroken, UnknownModule) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("DKDKx"), 5, "DKXXx");
  expect_diagnostic(t, "L1001", 7, 9);
}
TEST(VlocRlocBroken, MalformedReaction) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("-0.4336294D-01"), 14, "-0.43362Q4D-01");
  expect_diagnostic(t, "L1002", 10, 35);
}
TEST(VlocRlocBroken, MalformedBodyNumber) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("  844  DISKx"), 5, "  8x4");
  expect_diagnostic(t, "L1004", 9, 44);
}
TEST(VlocRlocBroken, TruncatedBlock) { expect_diagnostic(kHeader + "$icdan  DKDKx        1\n", "L1006", 7, 23); }
TEST(VlocRlocBroken, MalformedStepTime) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("0.6000000D-01"), 13, "0.6000000D-X1");
  expect_diagnostic(t, "L1002", 4, 35);
}

}  // namespace
}  // namespace lmgc::grammar
