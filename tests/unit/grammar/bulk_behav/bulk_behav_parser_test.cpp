// BULK_BEHAV.DAT: laws and their sub-blocks, the echo of each law family, and broken files with
// their exact diagnostic. docs/lmgc90-facts/datbox-inputs.md §2, §10.
#include <gtest/gtest.h>

#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kGravity =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n";

const std::string kRigid = kGravity +
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

const std::string kThermoElas =
    kGravity +
    "$behav  lawty\n"
    " acier  THERMO_ELAS                     Umas= 0.8000000D+04\n"
    "                                        elas: standard\n"
    "                                        ani_: isotropic\n"
    "                                        EYng= 0.2000000D+12  EPss= 0.3000000D+00\n"
    "                                        cplt:\n"
    "                                        Dila= 0.2000000D-06\n"
    "                                        Tref= 0.2730000D+03\n"
    "                                        ther:\n"
    "                                        SPHV= 0.1125000D+01\n"
    "                                        COCO= 0.3000000D+03\n";

const Diagnostic& first(const DiagnosticSink& sink) {
  static const Diagnostic none{"none", Severity::note, {}, "no diagnostic", {}, {}};
  return sink.items().empty() ? none : sink.items()[0];
}

BulkBehavFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_bulk_behav(SourceText("BULK_BEHAV.DAT", text), sink);
}

// The echo without LMGC90's 19-line header.
std::string echo_body(const std::string& text) {
  DiagnosticSink sink;
  const std::string out = write_bulk_behav(parse(text, sink));
  EXPECT_FALSE(sink.has_errors()) << first(sink).code << ": " << first(sink).message;
  std::size_t at = 0;
  for (int k = 0; k < 19 && at != std::string::npos; ++k) at = out.find('\n', at) + 1;
  return out.substr(at);
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  DiagnosticSink sink;
  parse(text, sink);
  EXPECT_EQ(first(sink).code, code) << first(sink).message;
  EXPECT_EQ(first(sink).where.span.line, line) << first(sink).message;
  EXPECT_EQ(first(sink).where.span.column, column) << first(sink).message;
}

std::string law(const std::string& lines) {
  return kGravity + "$behav  lawty\n" + lines;
}

constexpr const char* kGravityEcho =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n"
    " \n";

// --- reading ---------------------------------------------------------------------------------

TEST(BulkBehavParser, ReadsGravityAndRigidDensity) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse(kRigid, sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_TRUE(f.has_gravity);
  EXPECT_DOUBLE_EQ(f.gravity[1].value, -9.81);
  EXPECT_EQ(f.gravity[1].span.column, 46);
  double rho = 0;
  ASSERT_TRUE(bulk_density(f, "PLEXx", rho));
  EXPECT_DOUBLE_EQ(rho, 2000.0);
  EXPECT_FALSE(bulk_density(f, "OTHER", rho));
}

TEST(BulkBehavParser, ReadsElasticPlasticSubBlocks) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse(kElasPlas, sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(f.laws.size(), 1u);
  ASSERT_EQ(f.laws[0].blocks.size(), 2u);
  const BulkBlock& elas = f.laws[0].blocks[0];
  EXPECT_EQ(elas.kind, BulkBlockKind::elas);
  ASSERT_EQ(elas.options.size(), 2u);
  EXPECT_EQ(elas.options[1].value, "isotropic");
  ASSERT_EQ(elas.lines.size(), 1u);
  EXPECT_DOUBLE_EQ(elas.lines[0].values[0].value, 2e11);
  const BulkBlock& plas = f.laws[0].blocks[1];
  ASSERT_EQ(plas.options.size(), 4u);
  EXPECT_EQ(plas.options[1].value, "Swift");
  ASSERT_EQ(plas.lines.size(), 1u);
  EXPECT_DOUBLE_EQ(plas.lines[0].values[2].value, 1.0);
}

TEST(BulkBehavParser, LabelsOfPlasticityLinesAreNotChecked) {
  // LMGC90 reads only columns 47-59 of the PLAS lines (a real example writes 'visc:' for 'vpla:').
  std::string t = kElasPlas;
  t.replace(t.find("vpla:"), 5, "visc:");
  DiagnosticSink sink;
  parse(t, sink);
  EXPECT_TRUE(sink.items().empty());
}

TEST(BulkBehavParser, GuideSpellingOfGravityIsAcceptedWithANote) {
  std::string text = kRigid;
  text.replace(0, 6, "$gravity");
  DiagnosticSink sink;
  const BulkBehavFile f = parse(text, sink);
  EXPECT_TRUE(f.has_gravity);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(first(sink).code, "L1018");
  EXPECT_EQ(first(sink).severity, Severity::note);
  EXPECT_EQ(first(sink).where.span.line, 1u);
  EXPECT_EQ(first(sink).where.span.column, 1u);
  EXPECT_NE(write_bulk_behav(f).find("\n$gravy\n"), std::string::npos);
  EXPECT_EQ(write_bulk_behav(f).find("gravity"), std::string::npos);
}

TEST(BulkBehavParser, FieldInsteadOfValues) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse(law(" Mat01  ELAS                            Umas=field\n"
                                    "                                        elas: standard\n"
                                    "                                        ani_: isotropic\n"
                                    "                                        EYng=field\n"),
                                sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(f.laws.size(), 1u);
  EXPECT_TRUE(f.laws[0].density_field);
  EXPECT_TRUE(f.laws[0].blocks[0].lines[0].field);
}

TEST(BulkBehavParser, DiscreteLawIsTwoDimensionalWhenItsThirdColumnsAreBlank) {
  DiagnosticSink sink;
  const BulkBehavFile f =
      parse(law(" Spr01  DISCRETE                        m1  = 0.1000000D+01  m2  = 0.2000000D+01\n"
                "                                        k1  = 0.3000000D+01  k2  = 0.4000000D+01\n"
                "                                        c1  = 0.5000000D+01  c2  = 0.6000000D+01\n"),
            sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(f.laws.size(), 1u);
  EXPECT_EQ(f.laws[0].first_line_values.size(), 2u);
  ASSERT_EQ(f.laws[0].blocks.size(), 1u);
  EXPECT_EQ(f.laws[0].blocks[0].lines[1].values.size(), 2u);
  EXPECT_DOUBLE_EQ(f.laws[0].blocks[0].lines[1].values[1].value, 6.0);
}

TEST(BulkBehavParser, CommentLinesMayInterruptALaw) {
  std::string t = kElasPlas;
  t.insert(t.find("                                        crit"), "! a comment\n\n# another\n");
  DiagnosticSink sink;
  DiagnosticSink plain_sink;
  EXPECT_TRUE(parse(t, sink) == parse(kElasPlas, plain_sink));
  EXPECT_TRUE(sink.items().empty());
}

// --- echo: one law of each family, written as LMGC90's formats write it ---------------------

TEST(BulkBehavWriter, ElasticPlasticEchoHasItsBlankLines) {
  const std::string body = echo_body(kElasPlas);
  EXPECT_EQ(body,
            "$gravy\n"
            "                   grv1= 0.0000000D+00  grv2= 0.0000000D+00  grv3= 0.0000000D+00\n"
            " \n"
            "$behav  lawty\n"
            " Stee1  ELAS_PLAS                       Umas= 0.7800000D+04\n"
            "                                        elas: standard     \n"
            "                                        ani_: isotropic    \n"
            "                                        EYng= 0.2000000D+12  EPss= 0.3000000D+00\n"
            " \n"
            "                                        crit: Von-Mises    \n"
            "                                        isoh: Swift        \n"
            "                                        C0__= 0.1000000D+03  EPS0= 0.4000000D+00  n___= "
            "0.1000000D+01\n"
            "                                        cinh: none         \n"
            "                                        vpla: none         \n"
            " \n"
            " \n");
}

TEST(BulkBehavWriter, HeaderIsLmgc90CommentBlock) {
  DiagnosticSink sink;
  const std::string out = write_bulk_behav(parse(kRigid, sink));
  EXPECT_EQ(out.substr(0, 73), "! File BULK_BEHAV                                                       \n");
  EXPECT_NE(out.find("\n  ! The symbol   'behav'   stands for the nickname of a bulk behaviour  \n"),
            std::string::npos);
  EXPECT_NE(out.find(std::string(72, ' ') + "\n$gravy\n"), std::string::npos);
}

TEST(BulkBehavWriter, ThermoElasticEcho) {
  EXPECT_EQ(echo_body(kThermoElas),
            std::string(kGravityEcho) +
                "$behav  lawty\n"
                " acier  THERMO_ELAS                     Umas= 0.8000000D+04\n"
                "                                        elas: standard     \n"
                "                                        ani_: isotropic    \n"
                "                                        EYng= 0.2000000D+12  EPss= 0.3000000D+00\n"
                " \n"
                "                                        cplt:\n"
                "                                        Dila= 0.2000000D-06\n"
                "                                        Tref= 0.2730000D+03\n"
                " \n"
                "                                        ther:\n"
                "                                        SPHV= 0.1125000D+01\n"
                "                                        COCO= 0.3000000D+03\n"
                " \n"
                " \n");
}

TEST(BulkBehavWriter, FieldEchoWritesFieldAfterEveryLabel) {
  const std::string body =
      echo_body(law(" Mat01  ELAS                            Umas=field\n"
                    "                                        elas: standard\n"
                    "                                        ani_: isotropic\n"
                    "                                        EYng=field\n"));
  EXPECT_NE(body.find(" Mat01  ELAS                            Umas=field\n"), std::string::npos);
  EXPECT_NE(body.find("                                        EYng=field  EPss=field\n \n \n"),
            std::string::npos);
}

TEST(BulkBehavWriter, AnisotropicValuesHaveBlankLabels) {
  std::string lines =
      " Mat01  VISCO_ELAS                      Umas= 0.1000000D+01\n"
      "                                        elas: standard\n"
      "                                        ani_: isotropic\n"
      "                                        EYng= 0.1000000D+01  EPss= 0.2000000D+00\n"
      "                                        visc: KelvinVoigt\n"
      "                                        ani_: anisotropic\n";
  for (int i = 0; i < 7; ++i)
    lines +=
        "                                        Cijk= 0.1000000D+01  Cijk= 0.2000000D+01  Cijk= "
        "0.3000000D+01\n";
  const std::string body = echo_body(law(lines));
  EXPECT_NE(body.find("                                        visc: KelvinVoigt  \n"
                      "                                        ani_: anisotropic  \n"
                      "                                              0.1000000D+01        0.2000000D+01      "
                      "  0.3000000D+01\n"),
            std::string::npos);
  EXPECT_EQ(body.substr(body.size() - 7), "01\n \n \n");
}

TEST(BulkBehavWriter, ThermoElectroRigidEcho) {
  const std::string body =
      echo_body(law(" Cu_01  THERMO_ELECTRO_RIGID            Umas= 0.8900000D+04\n"
                    "                                        iso:\n"
                    "                                        TCnd= 0.4000000D+03\n"
                    "                                        Hspe= 0.3850000D+03\n"
                    "                                        Eeq_= 0.1000000D+12  NUeq= 0.3000000D+00\n"
                    "                                        ECnd= 0.6000000D+08\n"
                    "                                        Eel_= 0.1000000D+12  NUel= 0.3000000D+00\n"
                    "                                        WSlw= NHU14\n"
                    "                                        WSmx= 0.1000000D+01  WSmn= 0.0000000D+00\n"
                    "                                        CtTi= 0.1000000D-02  AcTi= 0.2000000D+00\n"));
  EXPECT_EQ(body, std::string(kGravityEcho) +
                      "$behav  lawty\n"
                      " Cu_01  THERMO_ELECTRO_RIGID            Umas= 0.8900000D+04\n"
                      "                                        iso:\n"
                      "                                        TCnd= 0.4000000D+03\n"
                      "                                        Hspe= 0.3850000D+03\n"
                      "                                        Eeq_= 0.1000000D+12  NUeq= 0.3000000D+00\n"
                      "                                        ECnd= 0.6000000D+08\n"
                      "                                        Eel_= 0.1000000D+12  NUel= 0.3000000D+00\n"
                      "                                        WSlw= NHU14\n"
                      "                                        WSmx= 0.1000000D+01  WSmn= 0.0000000D+00\n"
                      "                                        CtTi= 0.1000000D-02  AcTi= 0.2000000D+00\n"
                      " \n"
                      " \n");
}

TEST(BulkBehavWriter, JointAndUserMaterialEcho) {
  const std::string body =
      echo_body(law(" Jnt01  JOINT_MC                        kt  = 0.1000000D+01  knc = 0.2000000D+01  knt = "
                    "0.3000000D+01\n"
                    "                                        kncc= 0.4000000D+01  ec  = 0.5000000D+01\n"
                    "                                        ftrc= 0.6000000D+01\n"
                    "                                        phi = 0.7000000D+01  C   = 0.8000000D+01  zmu = "
                    "0.9000000D+01\n"
                    "$behav  lawty\n"
                    " Usr01  USER_MAT                        Umas= 0.1000000D+01\n"
                    "  my_material.mat   \n"));
  EXPECT_EQ(body, std::string(kGravityEcho) +
                      "$behav  lawty\n"
                      " Jnt01  JOINT_MC                        kt  = 0.1000000D+01  knc = 0.2000000D+01  knt "
                      "= 0.3000000D+01\n"
                      "                                        kncc= 0.4000000D+01  ec  = 0.5000000D+01\n"
                      "                                        ftrc= 0.6000000D+01\n"
                      "                                        phi = 0.7000000D+01  C   = 0.8000000D+01  zmu "
                      "= 0.9000000D+01\n"
                      " \n"
                      "$behav  lawty\n"
                      " Usr01  USER_MAT                        Umas= 0.1000000D+01\n"
                      "                                        my_material.mat" +
                      std::string(35, ' ') +
                      "\n"
                      " \n");
}

TEST(BulkBehavWriter, UnknownLawIsKeptBlankAsLmgc90DoesAndItsLinesAreSkipped) {
  DiagnosticSink sink;
  const BulkBehavFile f = parse(law(" Mat01  PLASTIC_FANTASTIC               Umas= 0.1000000D+01\n"
                                    "                                        elas: standard\n"
                                    "$behav  lawty\n"
                                    " PLEXx  RIGID                           Umas= 0.2000000D+04\n"),
                                sink);
  ASSERT_EQ(sink.items().size(), 1u);  // L1001 only: the unknown law's own lines are skipped quietly
  EXPECT_EQ(sink.items()[0].code, "L1001");
  ASSERT_EQ(f.laws.size(), 2u);
  EXPECT_EQ(f.laws[0].law_type.value, "unknown");
  EXPECT_EQ(f.laws[0].nickname.value, "");
  const std::string out = write_bulk_behav(f);
  EXPECT_NE(out.find(" \n$behav  lawty\n \n$behav  lawty\n PLEXx  RIGID"), std::string::npos);
}

// --- broken files: one diagnostic each, exact code and position -----------------------------

TEST(BulkBehavBroken, MissingGravity) {
  expect_diagnostic("$behav  lawty\n PLEXx  RIGID                           Umas= 0.2000000D+04\n", "L1012",
                    2, 60);
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
TEST(BulkBehavBroken, WrongThermMarker) {
  std::string t = kThermoElas;
  t.replace(t.find("ther:"), 5, "thrm:");
  expect_diagnostic(t, "L1016", 11, 41);
}
TEST(BulkBehavBroken, UnknownAnisotropy) {
  std::string t = kElasPlas;
  t.replace(t.find("isotropic"), 9, "isotrope ");
  expect_diagnostic(t, "L1017", 6, 47);
}
TEST(BulkBehavBroken, UnknownIsotropicHardening) {
  std::string t = kElasPlas;
  t.replace(t.find("Swift"), 5, "Swoft");
  expect_diagnostic(t, "L1017", 9, 47);
}
TEST(BulkBehavBroken, ElasticModelNotImplementedInLmgc90) {
  std::string t = kElasPlas;
  t.replace(t.find("standard"), 8, "HartSmith");
  expect_diagnostic(t, "L1017", 5, 47);
}
TEST(BulkBehavBroken, DilatationOfAnisotropicElasticity) {
  std::string lines =
      " Mat01  ELAS_DILA                       Umas= 0.1000000D+01\n"
      "                                        elas: standard\n"
      "                                        ani_: anisotropic\n";
  for (int i = 0; i < 7; ++i) lines += "                                        Cijk= 0.1000000D+01\n";
  lines +=
      "                                        cplt:\n"
      "                                        Tref= 0.2730000D+03\n";
  expect_diagnostic(law(lines), "L1017", 14, 41);
}
TEST(BulkBehavBroken, UnknownChemicalLaw) {
  expect_diagnostic(law(" Chem1  CHEMICAL_RIGID                  Umas= 0.1000000D+01\n"
                        "                                        WSlw= XYZ99\n"),
                    "L1017", 5, 47);
}
TEST(BulkBehavBroken, TruncatedLaw) {
  const std::string t = kElasPlas.substr(0, kElasPlas.find("                                        crit"));
  expect_diagnostic(t, "L1006", 7, 81);
}
TEST(BulkBehavBroken, LawCutShortByTheNextLaw) {
  const std::string t = kElasPlas.substr(0, kElasPlas.find("                                        cinh")) +
                        kRigid.substr(kGravity.size());
  expect_diagnostic(t, "L1013", 11, 1);
}
TEST(BulkBehavBroken, DensityShiftedOneColumnRight) {
  std::string t = kRigid;
  t.replace(t.find("Umas= 0.2000000D+04"), 19, "Umas=  0.2000000D+04");
  expect_diagnostic(t, "L1011", 4, 46);
}
TEST(BulkBehavBroken, MissingUserMaterialFileNameLine) {
  expect_diagnostic(law(" Usr01  USER_MAT                        Umas= 0.1000000D+01\n"), "L1006", 4, 60);
}
// LMGC90 writes the file name unquoted (A50) and would read its own echo as the name 'a'.
TEST(BulkBehavBroken, QuotedUserMaterialFileNameWithABlank) {
  expect_diagnostic(law(" Usr01  USER_MAT                        Umas= 0.1000000D+01\n"
                        "  'a name, with blanks'\n"),
                    "L1017", 5, 1);
}
TEST(BulkBehavBroken, StrayLineBetweenLaws) {
  expect_diagnostic(kRigid + "stray text\n", "L1019", 5, 1);
}
TEST(BulkBehavBroken, EmptyFile) {
  expect_diagnostic("! only a comment\n", "L1009", 0, 0);
}

}  // namespace
}  // namespace lmgc::grammar
