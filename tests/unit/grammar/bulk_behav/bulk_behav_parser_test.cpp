// BULK_BEHAV.DAT: laws and their sub-blocks, and broken files with their exact diagnostic.
#include "grammar/bulk_behav/parser.hpp"

#include <gtest/gtest.h>

#include "grammar/bulk_behav/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kRigid =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n"
    "$behav  lawty\n"
    " PLEXx  RIGID                           Umas= 0.2000000D+04\n";

const std::string kElasPlas =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2= 0.0000000D+00  grv3= 0.0000000D+00\n"
    "$behav  lawty\n"
    " Stee1  ELAS_PLAS                       Umas= 0.7800000D+04\n"
    "                                        elas: standard\n"
    "                                        ani_: isotropic\n"
    "                                        EYng= 0.2000000D+12  EPss= 0.3000000D+00\n"
    "                                        crit: Von-Mises\n"
    "                                        isoh: Swift\n"
    "                                        C0__= 0.1000000D+03  EPS0= 0.4000000D+00  n___= 0.1000000D+01\n"
    "                                        cinh: none\n"
    "                                        vpla: none\n";

const Diagnostic& first(const DiagnosticSink& sink) {
  static const Diagnostic none{"none", Severity::note, {}, "no diagnostic", {}, {}};
  return sink.items().empty() ? none : sink.items()[0];
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line, std::uint32_t column) {
  DiagnosticSink sink;
  parse_bulk_behav(SourceText("BULK_BEHAV.DAT", text), sink);
  EXPECT_EQ(first(sink).code, code) << first(sink).message;
  EXPECT_EQ(first(sink).where.span.line, line) << first(sink).message;
  EXPECT_EQ(first(sink).where.span.column, column) << first(sink).message;
}

TEST(BulkBehavParser, ReadsGravityAndRigidDensity) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse_bulk_behav(SourceText("BULK_BEHAV.DAT", kRigid), sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_TRUE(f.has_gravity);
  EXPECT_DOUBLE_EQ(f.gravity[1].value, -9.81);
  double rho = 0;
  ASSERT_TRUE(bulk_density(f, "PLEXx", rho));
  EXPECT_DOUBLE_EQ(rho, 2000.0);
  EXPECT_FALSE(bulk_density(f, "OTHER", rho));
}

TEST(BulkBehavParser, ReadsElasticPlasticSubBlocks) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse_bulk_behav(SourceText("BULK_BEHAV.DAT", kElasPlas), sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.laws.size(), 1u);
  ASSERT_EQ(f.laws[0].blocks.size(), 2u);
  const BulkBlock& elas = f.laws[0].blocks[0];
  EXPECT_EQ(elas.lines[1].word.value, "isotropic");
  EXPECT_DOUBLE_EQ(elas.lines[2].values[0].value, 2e11);
  const BulkBlock& plas = f.laws[0].blocks[1];
  EXPECT_EQ(plas.lines[1].word.value, "Swift");
  EXPECT_DOUBLE_EQ(plas.lines[2].values[2].value, 1.0);
}

TEST(BulkBehavParser, GuideSpellingOfGravityIsAcceptedWithANote) {
  std::string text = kRigid;
  text.replace(0, 6, "$gravity");
  DiagnosticSink sink;
  const BulkBehavFile f = parse_bulk_behav(SourceText("BULK_BEHAV.DAT", text), sink);
  EXPECT_TRUE(f.has_gravity);
  EXPECT_EQ(first(sink).code, "L1018");
  EXPECT_NE(write_bulk_behav(f).find("$gravy\n"), std::string::npos);
}

TEST(BulkBehavWriter, EchoUsesInternalLabelsAndBlankLines) {
  DiagnosticSink sink;
  const std::string echo = write_bulk_behav(parse_bulk_behav(SourceText("BULK_BEHAV.DAT", kElasPlas), sink));
  EXPECT_NE(echo.find("                                        elas: standard     \n"), std::string::npos);
  EXPECT_NE(echo.find("EPss= 0.3000000D+00\n \n                                        crit: Von-Mises    \n"), std::string::npos);
  EXPECT_NE(echo.find("vpla: none         \n \n \n"), std::string::npos);
}

TEST(BulkBehavBroken, MissingGravity) {
  expect_diagnostic("$behav  lawty\n PLEXx  RIGID                           Umas= 0.2000000D+04\n", "L1012", 2, 60);
}
TEST(BulkBehavBroken, UnknownLawType) {
  std::string t = kRigid;
  t.replace(t.find("RIGID"), 5, "RIGIDE");
  expect_diagnostic(t, "L1001", 4, 9);
}
TEST(BulkBehavBroken, MalformedDensity) {
  std::string t = kRigid;
  t.replace(t.find("0.2000000D+04"), 13, "0.2OOOOOOD+04");
  expect_diagnostic(t, "L1002", 4, 46);
}
TEST(BulkBehavBroken, GravityValueOutOfRange) {
  std::string t = kRigid;
  t.replace(t.find("-0.9810000D+01"), 14, "-0.98100D+9999");
  expect_diagnostic(t, "L1003", 2, 46);
}
TEST(BulkBehavBroken, WrongElasLabel) {
  std::string t = kElasPlas;
  t.replace(t.find("elas:"), 5, "elsa:");
  expect_diagnostic(t, "L1016", 5, 41);
}
TEST(BulkBehavBroken, UnknownAnisotropy) {
  std::string t = kElasPlas;
  t.replace(t.find("isotropic"), 9, "isotrope ");
  expect_diagnostic(t, "L1017", 6, 47);
}
TEST(BulkBehavBroken, TruncatedLaw) {
  const std::string t = kElasPlas.substr(0, kElasPlas.find("                                        crit"));
  expect_diagnostic(t, "L1006", 7, 81);
}
TEST(BulkBehavBroken, DensityShiftedOneColumnRight) {
  std::string t = kRigid;
  t.replace(t.find("Umas= 0.2000000D+04"), 19, "Umas=  0.2000000D+04");
  expect_diagnostic(t, "L1011", 4, 46);
}

}  // namespace
}  // namespace lmgc::grammar
