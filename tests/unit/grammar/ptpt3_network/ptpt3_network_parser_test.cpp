// PTPT3_NETWORK.DAT (grammar/ptpt3_network): LMGC90's two record forms, list-directed items, and
// diagnostics at the item that is wrong.
#include <gtest/gtest.h>

#include <string>

#include "grammar/ptpt3_network/parser.hpp"
#include "grammar/ptpt3_network/writer.hpp"

namespace lmgc::grammar {
namespace {

Ptpt3NetworkFile network(const std::string& text, DiagnosticSink& sink) {
  return parse_ptpt3_network(SourceText("PTPT3_NETWORK.DAT", text), sink);
}

// The record LMGC90's own test (test/Basics/PTPT_LoadNetwork) writes: '{:05d} {:05d} 0 0 0 {:f}'.
TEST(Ptpt3NetworkParser, ReadsThePlainFormWithLeadingZerosAndCommas) {
  DiagnosticSink sink;
  const Ptpt3NetworkFile file = network("00001 00008 0 0 0 0.050000\n\n 2, 3, 1, 0, 1, 1.5D-1\n", sink);
  ASSERT_TRUE(sink.items().empty());
  EXPECT_FALSE(file.with_parameters);
  ASSERT_EQ(file.links.size(), 2u);
  EXPECT_EQ(file.links[0].candidate.value, 1);
  EXPECT_EQ(file.links[0].antagonist.value, 8);
  EXPECT_DOUBLE_EQ(file.links[0].reference_length.value, 0.05);
  EXPECT_EQ(file.links[1].x_periods.value, 1);
  EXPECT_EQ(file.links[1].y_periods.value, 0);
  EXPECT_EQ(file.links[1].loop.value, 1);
  EXPECT_DOUBLE_EQ(file.links[1].reference_length.value, 0.15);
  EXPECT_FALSE(file.links[1].surface.has_value());
  // Spans point at the item: column 5 of line 3 holds iantac '3'.
  EXPECT_EQ(file.links[1].antagonist.span.line, 3u);
  EXPECT_EQ(file.links[1].antagonist.span.column, 5u);
}

TEST(Ptpt3NetworkParser, EightItemsAreTheParameterFormSurfNonuc0Mass) {
  DiagnosticSink sink;
  const Ptpt3NetworkFile file = network(" 1 2 0 0 0 0.01 0.5 2.0\n 3 4 0 -1 0 0.02 0.25 3.0\n", sink);
  ASSERT_TRUE(sink.items().empty());
  EXPECT_TRUE(file.with_parameters);
  ASSERT_EQ(file.links.size(), 2u);
  EXPECT_DOUBLE_EQ(file.links[1].surface->value, 0.02);
  EXPECT_DOUBLE_EQ(file.links[1].reference_length.value, 0.25);
  EXPECT_DOUBLE_EQ(file.links[1].mass->value, 3.0);
  EXPECT_EQ(file.links[1].y_periods.value, -1);
}

TEST(Ptpt3NetworkParser, AnEmptyFileIsANetworkWithoutLinks) {
  DiagnosticSink sink;
  EXPECT_TRUE(network("", sink).links.empty());
  EXPECT_FALSE(sink.has_errors());
}

TEST(Ptpt3NetworkBroken, ARecordShorterThanTheFirstOneNamesTheMissingItem) {
  DiagnosticSink sink;
  const Ptpt3NetworkFile file = network(" 1 2 0 0 0 0.01 0.5 2.0\n 3 4 0 0 0 0.5\n", sink);
  EXPECT_EQ(file.links.size(), 1u);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1015");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_NE(sink.items()[0].message.find("nonuc0"), std::string::npos);
}

TEST(Ptpt3NetworkBroken, ARealWhereAnIntegerIsExpectedIsMalformedAtItsColumns) {
  DiagnosticSink sink;
  const Ptpt3NetworkFile file = network(" 1 2.5 0 0 0 0.5\n", sink);
  EXPECT_TRUE(file.links.empty());
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1004");
  EXPECT_EQ(sink.items()[0].where.span.column, 4u);
  EXPECT_EQ(sink.items()[0].where.span.end_column, 7u);  // one past the last column
  EXPECT_NE(sink.items()[0].message.find("iantac"), std::string::npos);
}

TEST(Ptpt3NetworkBroken, AMalformedLengthAndTrailingTextAreReported) {
  DiagnosticSink sink;
  network(" 1 2 0 0 0 0.5x\n 1 3 0 0 0 0.5 7\n", sink);
  ASSERT_EQ(sink.items().size(), 2u);
  EXPECT_EQ(sink.items()[0].code, "L1002");
  EXPECT_EQ(sink.items()[1].code, "L1019");
  EXPECT_EQ(sink.items()[1].where.span.column, 16u);
}

TEST(Ptpt3NetworkWriter, WritesOneRecordPerLinkThatReadsBackExactly) {
  DiagnosticSink sink;
  const Ptpt3NetworkFile file = network(" 1 8 1 0 1 0.1\n", sink);
  const std::string text = write_ptpt3_network(file);
  EXPECT_EQ(text, " 1 8 1 0 1 1.0000000000000001E-01\n");
  EXPECT_EQ(network(text, sink), file);
  EXPECT_TRUE(sink.items().empty());
}

}  // namespace
}  // namespace lmgc::grammar
