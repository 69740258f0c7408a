// TACT_BEHAV.DAT parser: broken inputs (exact code, line, column), LMGC90's reading quirks,
// the `$seety` block and the echo layout.
#include <gtest/gtest.h>

#include <string>

#include "grammar/tact_behav/parser.hpp"
#include "grammar/tact_behav/see_table.hpp"
#include "grammar/tact_behav/writer.hpp"

namespace lmgc::grammar {
namespace {

TactBehavFile parse(const std::string& text, DiagnosticSink& sink) {
  const SourceText source("TACT_BEHAV.DAT", text);
  return parse_tact_behav(source, sink);
}

const std::string kSeeTitle = " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n";

// ---------------------------------------------------------------------------------------------
// Broken inputs: one diagnostic each, with exact code and position.

TEST(TactBehavParserErrors, UnknownLawKeywordPointsAtColumns9To38WithClosestKeyword) {
  DiagnosticSink sink;
  const auto file =
      parse("$behav  lawty\n iqsc0  IQS_CLBX                        fric= 0.5000000D+00\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  const auto& d = sink.items()[0];
  EXPECT_EQ(d.code, "L1001");
  EXPECT_EQ(d.where.span.line, 2u);
  EXPECT_EQ(d.where.span.column, 9u);
  EXPECT_EQ(d.where.span.end_column, 39u);
  EXPECT_NE(d.hint.find("'IQS_CLB'"), std::string::npos) << d.hint;
  EXPECT_TRUE(file.laws.empty());
}

TEST(TactBehavParserErrors, GuideOnlyKeywordNamesTheCurrentOne) {
  DiagnosticSink sink;
  parse(
      "$behav  lawty\n mac01  IQS_MAC_CZM_3D                 dfrc= 0.1000000D+00  sfrc= 0.1000000D+00\n"
      "                                        cn  = 0.1000000D+01  ct  = 0.1000000D+01\n"
      "                                        visc= 0.1000000D+01  dupr= 0.1000000D+01\n",
      sink);
  ASSERT_EQ(sink.items().size(), 1u);
  const auto& d = sink.items()[0];
  EXPECT_EQ(d.code, "L1001");
  EXPECT_EQ(d.where.span.line, 2u);
  EXPECT_EQ(d.where.span.column, 9u);
  EXPECT_NE(d.hint.find("'IQS_MAC_CZM'"), std::string::npos) << d.hint;
}

// Found by fuzzing: a '$seety' block whose data line is missing, the next card's keyword line
// coming instead, was read silently as a pair ('behav' against 'lawty').
TEST(TactBehavParserErrors, KeywordLineWhereTheSeetyDataLineIsExpected) {
  DiagnosticSink sink;
  const auto file = parse("$seety\n" + kSeeTitle + "! a comment\n$behav  lawty\n iqsc0  IQS_CLB" +
                              std::string(25, ' ') + "fric= 0.5000000D+00\n",
                          sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1013");
  EXPECT_EQ(sink.items()[0].where.span.line, 4u);
  EXPECT_TRUE(file.sees.empty());
  ASSERT_EQ(file.laws.size(), 1u);
}

TEST(TactBehavParserErrors, MalformedNumberInTheValueField) {
  DiagnosticSink sink;
  parse("$behav  lawty\n iqsc0  IQS_CLB                         fric= 0.5x00000D+00\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1002");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 46u);
}

TEST(TactBehavParserErrors, OutOfRangeNumberOnAContinuationLine) {
  DiagnosticSink sink;
  parse(
      "$behav  lawty\n rstc1  RST_CLB                         rstn= 0.9000000D+00  rstt= 0.100000D+400\n"
      "                                        fric= 0.5000000D+00\n",
      sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1003");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 67u);
}

TEST(TactBehavParserErrors, TruncatedCardAtEndOfFile) {
  DiagnosticSink sink;
  const auto file = parse(
      "$behav  lawty\n rstc1  RST_CLB                         rstn= 0.9000000D+00  rstt= 0.5000000D+00\n",
      sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1006");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 81u);  // just past the end of the last line
  ASSERT_EQ(file.laws.size(), 1u);                    // kept with what was read
}

TEST(TactBehavParserErrors, FileEndsAfterBehavKeyword) {
  DiagnosticSink sink;
  parse("$behav  lawty\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1006");
  EXPECT_EQ(sink.items()[0].where.span.line, 1u);
  EXPECT_EQ(sink.items()[0].where.span.column, 14u);
}

TEST(TactBehavParserErrors, ValueShiftedOutOfItsColumns) {
  DiagnosticSink sink;
  const auto file =
      parse("$behav  lawty\n iqsc0  IQS_CLB                         fric=  0.5000000D+00\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1011");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 46u);
  ASSERT_EQ(file.laws.size(), 1u);
  EXPECT_EQ(file.laws[0].parameters[0].value, 0.5);  // LMGC90 reads ' 0.5000000D+0'
}

TEST(TactBehavParserErrors, MissingSeeTitleLine) {
  DiagnosticSink sink;
  const auto file =
      parse("$seety\n RBDY2  DISKx  BLEUx  iqsc0  RBDY2  DISKx  BLEUx       0.5000000D-03\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1012");
  EXPECT_EQ(sink.items()[0].where.span.line, 2u);
  EXPECT_EQ(sink.items()[0].where.span.column, 2u);
  ASSERT_EQ(file.sees.size(), 1u);  // recovered: the line is read as the data line
}

TEST(TactBehavParserErrors, SeeEntryRepeatedWithAnotherLaw) {
  DiagnosticSink sink;
  parse("$seety\n" + kSeeTitle + " RBDY2  DISKx  BLEUx  iqsc0  RBDY2  JONCx  WALLx       0.5000000D-03\n" +
            "$seety\n" + kSeeTitle + " RBDY2  JONCx  WALLx  iqsc1  RBDY2  DISKx  BLEUx       0.5000000D-03\n",
        sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L2015");
  EXPECT_EQ(sink.items()[0].where.span.line, 6u);
  EXPECT_EQ(sink.items()[0].where.span.column, 23u);
}

TEST(TactBehavParserErrors, MalformedAlertDistance) {
  DiagnosticSink sink;
  parse("$seety\n" + kSeeTitle + " RBDY2  DISKx  BLEUx  iqsc0  RBDY2  DISKx  BLEUx       0.5OOOOOOD-03\n",
        sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1002");
  EXPECT_EQ(sink.items()[0].where.span.line, 3u);
  EXPECT_EQ(sink.items()[0].where.span.column, 55u);
}

TEST(TactBehavParserErrors, LowerCaseKeywordGetsACaseHint) {
  DiagnosticSink sink;
  parse("$behav  lawty\n iqsc0  iqs_clb                         fric= 0.5000000D+00\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1001");
  EXPECT_NE(sink.items()[0].hint.find("case-sensitive"), std::string::npos);
}

TEST(TactBehavParserErrors, InternalLawIdIsNotReadable) {
  DiagnosticSink sink;
  parse("$behav  lawty\n wet01  WET_CZM\n", sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1001");
  EXPECT_NE(sink.items()[0].hint.find("internal law id"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// What LMGC90 reads.

TEST(TactBehavParser, ParameterLabelsAreIgnoredOnlyColumnsCount) {
  DiagnosticSink sink;
  const auto file = parse(
      "$behav  lawty                           data\n"
      " rdsc1  RST_DS_CLB                      xxxx= 0.9000000D+00        0.5000000D+00\n"
      "! a comment inside the card\n"
      "\n"
      "                                        dyfr= 0.3000000D+00  stfr= 0.5000000D+00\n",
      sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(file.laws.size(), 1u);
  EXPECT_EQ(file.laws[0].nickname.value, "rdsc1");
  EXPECT_EQ(file.laws[0].keyword.value, "RST_DS_CLB");
  ASSERT_EQ(file.laws[0].parameters.size(), 4u);
  EXPECT_EQ(file.laws[0].parameters[0].value, 0.9);
  EXPECT_EQ(file.laws[0].parameters[1].value, 0.5);
  EXPECT_EQ(file.laws[0].parameters[2].value, 0.3);
  EXPECT_EQ(file.laws[0].parameters[3].value, 0.5);
}

TEST(TactBehavParser, ShortCardSwallowsTheNextBehavLineAsLmgc90Does) {
  // IQS_WET_DS_CLB reads 2/1/2 values; written 2/2 it takes the next `$behav` line as values.
  DiagnosticSink sink;
  const auto file = parse(
      "$behav  lawty\n"
      " wet01  IQS_WET_DS_CLB                  cohn= 0.2000000D+01  Wthk= 0.1000000D-02\n"
      "                                        dyfr= 0.2500000D+00  stfr= 0.5500000D+00\n"
      "$behav  lawty\n"
      " iqsc0  IQS_CLB                         fric= 0.5000000D+00\n",
      sink);
  ASSERT_EQ(file.laws.size(), 1u);
  const auto& p = file.laws[0].parameters;
  EXPECT_EQ(p[1].value, 0.001);  // cohet
  EXPECT_EQ(p[2].value, 0.25);   // Wethk from the 'dyfr' field
  EXPECT_EQ(p[3].value, 0.0);    // from the '$behav' line
  ASSERT_EQ(sink.items().size(), 2u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 4u);
  EXPECT_EQ(sink.items()[1].code, "L1019");  // the lost law line
  EXPECT_EQ(sink.items()[1].where.span.line, 5u);
  EXPECT_FALSE(sink.has_errors());
}

TEST(TactBehavParser, PerioDofReadsTheSameFieldThreeTimes) {
  DiagnosticSink sink;
  const auto file = parse(
      "$behav  lawty\n pdof1  PERIO_DOF                       E_XX= 0.1000000D-01\n"
      "                                        E_YY= 0.2000000D-01\n",
      sink);
  ASSERT_EQ(file.laws.size(), 1u);
  ASSERT_EQ(file.laws[0].parameters.size(), 3u);
  for (const auto& value : file.laws[0].parameters) EXPECT_EQ(value.value, 0.01);
  ASSERT_EQ(sink.items().size(), 1u);  // the E_YY line is not read: LMGC90 skips it
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 3u);
}

TEST(TactBehavParser, ElasticWetNtReadsItsThirdPairFromTheSecondLine) {
  DiagnosticSink sink;
  const auto file = parse(
      "$behav  lawty\n ewnt1  ELASTIC_WET_NT                  kn  = 0.1000000D+01  kt  = 0.2000000D+01\n"
      "                                        dmpn= 0.3000000D+01  dmpt= 0.4000000D+01\n",
      sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(file.laws.size(), 1u);
  const auto& p = file.laws[0].parameters;
  EXPECT_EQ(p[4].value, 3.0);
  EXPECT_EQ(p[5].value, 4.0);
}

TEST(TactBehavParser, SeeBlockWithGlobalAlertAndObsoleteNames) {
  DiagnosticSink sink;
  const auto file =
      parse("$seety\n" + kSeeTitle +
                " MAILx  CSxxx  xxxxx  czmc0  MAILx  ASpxx  xxxxx       0.1000000e-01\n"
                "+                                                      0.1000000e+01\n"
                "$seety\n" +
                kSeeTitle + " DISKx  BDARY  BLEUx  iqsc1  JONCx  BDARY  UPxxx       0.5000000D-00\n",
            sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(file.sees.size(), 2u);
  EXPECT_EQ(file.sees[0].candidate_contactor.value, "CSxxx");
  ASSERT_TRUE(file.sees[0].global_alert.has_value());
  EXPECT_EQ(file.sees[0].global_alert->value, 1.0);
  EXPECT_EQ(file.sees[1].candidate_body.value, "DISKx");
  EXPECT_FALSE(file.sees[1].global_alert.has_value());
  EXPECT_EQ(file.sees[1].alert.value, 0.5);
}

TEST(TactBehavParser, KeywordNotInColumns2To6IsNotACard) {
  DiagnosticSink sink;
  const auto file =
      parse(" $behav  lawty\n wet01  IQS_CLB                         fric= 0.5000000D+00\n", sink);
  EXPECT_TRUE(file.laws.empty());
  ASSERT_EQ(sink.items().size(), 2u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 1u);
  EXPECT_FALSE(sink.has_errors());
}

// ---------------------------------------------------------------------------------------------
// LMGC90's see table order and the echo layout.

SeeEntry see(const std::string& cdtac, const std::string& cdcol, const std::string& law,
             const std::string& antac, const std::string& ancol) {
  SeeEntry entry;
  entry.candidate_body = std::string("RBDY2");
  entry.candidate_contactor = cdtac;
  entry.candidate_colour = cdcol;
  entry.law_nickname = law;
  entry.antagonist_body = std::string("RBDY2");
  entry.antagonist_contactor = antac;
  entry.antagonist_colour = ancol;
  entry.alert = 0.1;
  return entry;
}

TEST(TactBehavSeeOrder, SortsByAntagonistThenColourAndDropsDuplicates) {
  const std::vector<SeeEntry> input = {
      see("DISKx", "BLEUx", "iqsc1", "DISKx", "BLEUx"), see("DISKx", "BLEUx", "iqsc0", "JONCx", "UPxxx"),
      see("DISKx", "BLEUx", "iqsc0", "JONCx", "DOWNx"),
      see("JONCx", "DOWNx", "iqsc0", "DISKx", "BLEUx")};  // swapped duplicate
  const auto order = lmgc90_see_order(input);
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0].antagonist_contactor.value, "DISKx");
  EXPECT_EQ(order[1].antagonist_colour.value, "DOWNx");
  EXPECT_EQ(order[2].antagonist_colour.value, "UPxxx");
}

TEST(TactBehavSeeOrder, TiesAreReversedLikeLmgc90) {
  // Same antagonist, candidate differs from antagonist: LMGC90's stale flag moves each entry to
  // the front (RIGID_2D/BouncingBallsDK).
  const auto order = lmgc90_see_order({see("DISKx", "BLEUx", "a", "JONCx", "DOWNx"),
                                       see("DISKx", "VERTx", "b", "JONCx", "DOWNx"),
                                       see("DISKx", "JAUNx", "c", "JONCx", "DOWNx")});
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0].law_nickname.value, "c");
  EXPECT_EQ(order[1].law_nickname.value, "b");
  EXPECT_EQ(order[2].law_nickname.value, "a");
}

TEST(TactBehavWriter, EchoLayout) {
  TactBehavFile file;
  TactLaw glue;
  glue.nickname = std::string("wet01");
  glue.keyword = std::string("COUPLED_DOF");
  TactLaw rst;
  rst.nickname = std::string("rstc1");
  rst.keyword = std::string("RST_CLB");
  rst.parameters = {Real{0.9}, Real{0.5}, Real{0.0}};
  file.laws = {glue, rst};
  SeeEntry entry = see("DISKx", "BLEUx", "rstc1", "DISKx", "BLEUx");
  entry.global_alert = Real{1.0};
  file.sees = {entry};
  const std::string echo = write_tact_behav(file);
  const std::string expected_tail =
      "$behav  lawty\n"
      " wet01  COUPLED_DOF                   \n"
      "$behav  lawty\n"
      " rstc1  RST_CLB                         restn 0.9000000D+00  restt 0.5000000D+00\n"
      "                                        sfric 0.0000000D+00\n"
      " \n"
      "$seety\n" +
      kSeeTitle +
      " RBDY2  DISKx  BLEUx  rstc1  RBDY2  DISKx  BLEUx       0.1000000D+00\n"
      "+                                                      0.1000000D+01\n"
      " \n";
  ASSERT_GE(echo.size(), expected_tail.size());
  EXPECT_EQ(echo.substr(echo.size() - expected_tail.size()), expected_tail);
  EXPECT_EQ(echo.substr(0, 17), "! File BEHAVIOUR ");
}

}  // namespace
}  // namespace lmgc::grammar
