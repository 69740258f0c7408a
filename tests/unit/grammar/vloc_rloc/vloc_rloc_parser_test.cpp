// Vloc_Rloc: the interaction catalogue, interaction blocks by module (2D, 3D, xxl, internal
// variables), and broken files with their exact diagnostic.
#include <gtest/gtest.h>

#include <map>

#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"

namespace lmgc::grammar {
namespace {

// Lines 1-6.
const std::string kHeader =
    "     \n! Vloc_Rloc\n      \n$steps      300              time= 0.6000000D-01\n \n"
    "!-----------------------------------------------------------------------\n";
// Lines 7-15 after kHeader.
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
// A 3D block: the vector lines of PRPRx come in the order rl, vl, gap, coo, t, n, s.
const std::string kPrprBlock =
    "$icdan  PRPRx        3\n"
    " cdbdy  numbr  cdtac  numbr  CDVER  behav  anbdy  numbr  antac  numbr  sttus\n"
    " RBDY3      4  POLYR      1     12  sico5  RBDY3      9  POLYR      1  slide\n"
    "                             rlt/H-0.1234567D+05  rln/H 0.7654321D+06  rls/H-0.1111111D+06\n"
    "                             vlt = 0.1000000D-02  vln =-0.2000000D-03  vls = 0.0000000D+00\n"
    "                             gapTT-0.4500000D-03\n"
    "                             coo1= 0.1450000D+02  coo2= 0.1170000D+02  coo3= 0.2240000D+01\n"
    "                             t(1)=-0.0000000D+00  t(2)= 0.8000000D+00  t(3)= 0.6000000D+00\n"
    "                             n(1)= 0.0000000D+00  n(2)= 0.6000000D+00  n(3)=-0.8000000D+00\n"
    "                             s(1)=-0.1000000D+01  s(2)= 0.0000000D+00  s(3)= 0.0000000D+00\n"
    "#taille_ele     saut_de_ut     saut_de_un     saut_de_us     beta           TPSini\n"
    "  0.2500000D+00 -0.1000000D-03  0.2000000D-03  0.0000000D+00  0.1000000D+01 -0.9900000D+02\n"
    " \n";

VlocRlocFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", text), sink);
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  DiagnosticSink sink;
  parse_vloc_rloc(SourceText("Vloc_Rloc.INI", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(VlocRlocCatalogue, TitlesHaveTheWidthLmgcWritesThemWith) {
  // The A-format width of each module's title line (state-and-outputs.md §1.4.1, §1.4.2).
  const std::map<std::string, std::size_t> widths = {
      {"DKDKx", 76},  {"DKJCx", 76}, {"DKKDx", 76}, {"DKDKL", 76},  {"CLJCx", 76},  {"PTPT2", 76},
      {"P2P2L", 76},  {"CLALp", 83}, {"DKALp", 89}, {"DKPLx", 103}, {"PLJCx", 103}, {"PLPLx", 90},
      {"PLALp", 103}, {"PRPRx", 76}, {"PRPLx", 76}, {"PRASp", 76},  {"SPSPx", 76},  {"SPPLx", 76},
      {"CDCDx", 76},  {"CDPLx", 76}, {"SPCDx", 76}, {"SPDCx", 76},  {"SPPRx", 69},  {"CSASx", 69},
      {"CSPRx", 76},  {"PTPT3", 76}};
  std::size_t normal = 0;
  for (const InteractionKind& kind : interaction_catalogue()) {
    SCOPED_TRACE(std::string(kind.type));
    if (kind.xxl) {
      EXPECT_EQ(kind.title.size(), kind.type == "SPSPx" ? 84u : 86u);
      EXPECT_EQ(kind.icdan_width, kind.dimension == 2 ? 10 : 7);
      continue;
    }
    ++normal;
    ASSERT_TRUE(widths.count(std::string(kind.type)));
    EXPECT_EQ(kind.title.size(), widths.at(std::string(kind.type)));
    EXPECT_EQ(kind.icdan_width, 7);
    EXPECT_EQ(find_interaction_kind(kind.type), &kind);  // the normal layout comes first
  }
  EXPECT_EQ(normal, widths.size());
  // CSPRx writes its 69-character title with A76: right-justified behind 7 blanks.
  EXPECT_EQ(find_interaction_kind("CSPRx")->title.substr(0, 8), "        ");
  EXPECT_EQ(find_interaction_kind("CSASp"), nullptr);  // module CSASp writes and reads 'CSASx'
}

TEST(VlocRlocCatalogue, DataItemsFollowTheFortranFormat) {
  const auto items = data_items("1X A5 2X I10 9X A5");
  ASSERT_EQ(items.size(), 6u);
  EXPECT_EQ(items[1].kind, 'A');
  EXPECT_EQ(items[3].kind, 'I');
  EXPECT_EQ(items[3].width, 10);
  EXPECT_EQ(items[4].kind, 'X');
  EXPECT_EQ(items[4].width, 9);
  EXPECT_EQ(items[5].width, 5);
  // Every data line of the table is at most 180 columns and starts with 1X.
  for (const InteractionKind& kind : interaction_catalogue()) {
    int width = 0;
    for (const DataItem& item : data_items(kind.data_format)) width += item.width;
    EXPECT_LE(width, 180) << kind.type;
    EXPECT_EQ(data_items(kind.data_format)[0].kind, 'X') << kind.type;
  }
}

TEST(VlocRlocParser, ReadsTheDataLineAndVectors) {
  DiagnosticSink sink;
  const VlocRlocFile f = parse(kHeader + kBlock, sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(f.step.value, 300);
  EXPECT_DOUBLE_EQ(f.time.value, 0.06);
  ASSERT_EQ(f.interactions.size(), 1u);
  const VlocRlocInteraction& c = f.interactions[0];
  EXPECT_EQ(c.number.value, 642);
  EXPECT_FALSE(c.xxl);
  ASSERT_EQ(c.words.size(), 6u);  // cdbdy, cdtac, behav, anbdy, antac, sttus
  EXPECT_EQ(c.words[3].value, "RBDY2");
  EXPECT_EQ(c.words[5].value, "stick");
  ASSERT_EQ(c.integers.size(), 5u);
  EXPECT_EQ(c.integers[2].value, 844);
  ASSERT_EQ(c.vectors.size(), 5u);
  EXPECT_DOUBLE_EQ(c.vectors[0].values[1].value, 0.1146651);
  EXPECT_EQ(c.vectors[2].labels[0], "gapTT");
  EXPECT_EQ(c.vectors[2].values.size(), 1u);
  EXPECT_TRUE(c.internal_lines.empty());
}

TEST(VlocRlocWriter, CanonicalTextIsAFixedPoint) {
  DiagnosticSink sink;
  const std::string text = kHeader + kBlock + kPrprBlock;
  EXPECT_EQ(write_vloc_rloc(parse(text, sink)), text);
  EXPECT_EQ(sink.items().size(), 0u);
}

TEST(VlocRlocParser, ThreeDimensionalBlockKeepsItsLineOrderAndInternals) {
  DiagnosticSink sink;
  const VlocRlocFile f = parse(kHeader + kPrprBlock, sink);
  ASSERT_EQ(f.interactions.size(), 1u);
  const VlocRlocInteraction& c = f.interactions[0];
  ASSERT_EQ(c.vectors.size(), 7u);
  EXPECT_EQ(c.vectors[3].labels[0], "coo1=");
  EXPECT_EQ(c.vectors[6].labels[2], "s(3)=");
  ASSERT_EQ(c.integers.size(), 5u);
  EXPECT_EQ(c.integers[2].value, 12);  // CDVER
  EXPECT_EQ(c.internal_comment.substr(0, 11), "#taille_ele");
  const std::vector<Real> internals = vloc_rloc_internal_values(c);
  ASSERT_EQ(internals.size(), 6u);
  EXPECT_DOUBLE_EQ(internals[5].value, -99.0);
}

TEST(VlocRlocParser, DkdkxInternalsWrapSixPerLineWithoutNames) {
  std::string text = kHeader + kBlock;
  text.insert(text.size() - 2,
              "  0.1000000D+01  0.2000000D+01  0.3000000D+01  0.4000000D+01  0.5000000D+01  0.6000000D+01\n"
              "  0.7000000D+01\n");
  DiagnosticSink sink;
  const VlocRlocFile f = parse(text, sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.interactions.size(), 1u);
  EXPECT_EQ(f.interactions[0].internal_lines.size(), 2u);
  EXPECT_TRUE(f.interactions[0].internal_comment.empty());
  EXPECT_EQ(vloc_rloc_internal_values(f.interactions[0]).size(), 7u);
  EXPECT_EQ(write_vloc_rloc(f), text);
}

TEST(VlocRlocParser, InternalValuesPastColumn180AreKept) {
  // A law with 17 internal variables (EXPO_CZM) writes a 255-column values line.
  DiagnosticSink sink;
  VlocRlocFile f = parse(kHeader + kPrprBlock, sink);
  ASSERT_EQ(f.interactions.size(), 1u);
  std::vector<Real> line;
  for (int k = 1; k <= 17; ++k) line.push_back(Real{0.5 * k});
  f.interactions[0].internal_lines = {line};
  const std::string text = write_vloc_rloc(f);
  DiagnosticSink again;
  const VlocRlocFile back = parse(text, again);
  EXPECT_FALSE(again.has_errors());
  EXPECT_EQ(back, f);
  EXPECT_DOUBLE_EQ(vloc_rloc_internal_values(back.interactions[0])[16].value, 8.5);
}

TEST(VlocRlocParser, XxlLayoutIsRecognisedByItsTitle) {
  // DKDKx with more than 99999 verlet contacts: I10 interaction and body numbers, A86 title,
  // named internal variables on one line.
  const std::string block =
      "$icdan  DKDKx     1234567\n"
      " cdbdy       numbr  cdtac  numbr  behav  anbdy       numbr  antac  numbr  sttus   iadj\n"
      " RBDY2      123456  DISKx      1  iqsc0  RBDY2      234567  DISKx      1  stick   4321\n"
      "                             rlt/H 0.1000000D+00  rln/H 0.2000000D+00  rls/H 0.0000000D+00\n"
      "                             vlt = 0.0000000D+00  vln = 0.0000000D+00  vls = 0.0000000D+00\n"
      "                             gapTT 0.0000000D+00\n"
      "                             n(1)= 0.1000000D+01  n(2)= 0.0000000D+00  n(3)= 0.0000000D+00\n"
      "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
      "#taille_ele\n"
      "  0.2500000D+00\n"
      " \n";
  DiagnosticSink sink;
  const VlocRlocFile f = parse(kHeader + block, sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.interactions.size(), 1u);
  const VlocRlocInteraction& c = f.interactions[0];
  EXPECT_TRUE(c.xxl);
  EXPECT_EQ(c.number.value, 1234567);
  ASSERT_EQ(c.integers.size(), 5u);
  EXPECT_EQ(c.integers[0].value, 123456);
  EXPECT_EQ(c.integers[2].value, 234567);
  EXPECT_EQ(c.integers[4].value, 4321);
  EXPECT_EQ(write_vloc_rloc(f), kHeader + block);
}

TEST(VlocRlocParser, HeaderOnlyFileHasNoInteraction) {
  DiagnosticSink sink;
  EXPECT_TRUE(parse(kHeader, sink).interactions.empty());
  EXPECT_FALSE(sink.has_errors());
}

TEST(VlocRlocParser, UnknownModuleSkipsItsWholeBlockOnly) {
  std::string t = kHeader + kBlock + kBlock;
  t.replace(t.find("DKDKx"), 5, "DKXXx");
  DiagnosticSink sink;
  const VlocRlocFile f = parse(t, sink);
  EXPECT_EQ(sink.items().size(), 1u);  // one L1001, no complaint about the lines of the block
  EXPECT_EQ(f.interactions.size(), 1u);
}

TEST(VlocRlocParser, EveryTruncationOfAFileIsReadWithoutCrashing) {
  const std::string text = kHeader + kBlock + kPrprBlock;
  for (std::size_t size = 0; size <= text.size(); ++size) {
    DiagnosticSink sink;
    const VlocRlocFile f = parse(text.substr(0, size), sink);
    EXPECT_LE(f.interactions.size(), 2u);
    (void)write_vloc_rloc(f);
  }
}

// Broken inputs: one diagnostic each, with its exact code and position.
TEST(VlocRlocBroken, MissingStepsHeader) {
  expect_diagnostic("! nothing\n!\n" + kBlock, "L1012", 3, 2);
}
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
TEST(VlocRlocBroken, TruncatedBlock) {
  expect_diagnostic(kHeader + "$icdan  DKDKx        1\n", "L1006", 7, 23);
}
TEST(VlocRlocBroken, MalformedStepTime) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("0.6000000D-01"), 13, "0.6000000D-X1");
  expect_diagnostic(t, "L1002", 4, 35);
}
TEST(VlocRlocBroken, MissingGapLine) {
  // rl and vl lines, then the block's closing blank line where the gap line is required.
  std::string t = kHeader + kBlock;
  const std::size_t gap = t.find("                             gapTT");
  t.erase(gap, t.find(" \n", gap) - gap);
  expect_diagnostic(t, "L1012", 12, 30);
}
TEST(VlocRlocBroken, MissingDataLine) {
  const std::string t = kHeader +
                        "$icdan  DKDKx        1\n"
                        " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj\n" +
                        kBlock;
  expect_diagnostic(t, "L1012", 9, 1);
}
TEST(VlocRlocBroken, MalformedInternalValue) {
  std::string t = kHeader + kBlock;
  t.insert(t.size() - 2, "  0.1000000D+01  0.20O0000D+01\n");
  expect_diagnostic(t, "L1002", 15, 17);
}
TEST(VlocRlocBroken, InteractionNumberOutOfRange) {
  std::string t = kHeader + kBlock;
  t.replace(t.find("$icdan  DKDKx      642"), 22, "$icdan  DKDKx  9999999999");
  expect_diagnostic(t, "L1003", 7, 16);
}
TEST(VlocRlocBroken, StrayLineBetweenBlocksIsAWarning) {
  DiagnosticSink sink;
  parse(kHeader + kBlock + "stray text\n" + kBlock, sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 16u);
  EXPECT_EQ(sink.items()[0].where.span.column, 1u);
  EXPECT_FALSE(sink.has_errors());
}

}  // namespace
}  // namespace lmgc::grammar
