// DRV_DOF.DAT and evolution files: what the parser reads, what the echo writes, and one exact
// diagnostic (code, line, column) per broken input.
#include <gtest/gtest.h>

#include <string>

#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kTemplate =
    "$dofty  numbr [CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]...*...[RAMPI.....+.....RAMP.*.time]";
const std::string kValues =
    "  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  0.0000000D+00";
const std::string kDofLine = " vlocy      1" + kValues;  // values at 15-28 ... 90-103

std::string rigid_block(const std::string& dof_line = kDofLine) {
  return "$bdyty\n RBDY2      1\n$nodty\n NO3xx      1\n" + kTemplate + "\n" + dof_line + "\n$$$$$$\n";
}

DrvDofFile parse(const std::string& text, DiagnosticSink& sink) {
  return parse_drv_dof(SourceText("DRV_DOF.DAT", text), sink);
}

void expect_one(const DiagnosticSink& sink, const std::string& code, std::uint32_t line,
                std::uint32_t column) {
  ASSERT_FALSE(sink.items().empty()) << "expected " << code;
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.column, column) << sink.items()[0].message;
}

TEST(DrvDofParser, ReadsRigidBlock) {
  DiagnosticSink sink;
  const std::string text =
      "$bdyty\n RBDY2  1025\n$nodty\n NO3xx      1\n" + kTemplate + "\n" +
      " force      2 -0.1000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  "
      "0.2500000D+02\n vlocy      1 evolution vy.dat\n$$$$$$\n";
  const DrvDofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 0u);
  ASSERT_EQ(file.bodies.size(), 1u);
  const DrvDofBody& body = file.bodies[0];
  EXPECT_EQ(body.body_type.value, "RBDY2");
  EXPECT_EQ(body.rank.value, 1025);  // left-justified in 9-15
  ASSERT_EQ(body.nodes.size(), 1u);
  ASSERT_EQ(body.nodes[0].dofs.size(), 2u);
  const DrivenDof& force = body.nodes[0].dofs[0];
  EXPECT_EQ(force.kind.value, "force");
  EXPECT_EQ(force.dof.value, 2);
  EXPECT_DOUBLE_EQ(force.parameters[0].value, -0.1);
  EXPECT_DOUBLE_EQ(force.parameters[5].value, 25.0);
  const DrivenDof& evolution = body.nodes[0].dofs[1];
  EXPECT_TRUE(evolution.uses_evolution);
  EXPECT_EQ(evolution.evolution_file.value, "vy.dat");
}

TEST(DrvDofParser, EchoSortsDofsAndPadsEvolutionName) {
  DiagnosticSink sink;
  const std::string text = "$bdyty\n RBDY2  7\n$nodty\n NO3xx      1\n" + kTemplate + "\n force      1" +
                           kValues + "\n vlocy      2 evolution vy.dat\n vlocy      1" + kValues +
                           "\n$$$$$$\n";
  const DrvDofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 0u);
  const std::string expected = "     \n! DOF\n     \n$bdyty\n RBDY2        7\n$nodty\n NO3xx      1\n" +
                               kTemplate + "\n vlocy      1" + kValues + "\n force      1" + kValues +
                               "\n vlocy      2 evolution vy.dat" + std::string(34, ' ') +
                               "\n$$$$$$\n      \n" + "!" + std::string(71, '-') + "\n";
  EXPECT_EQ(write_drv_dof(file), expected);
}

TEST(DrvDofParser, ReadsThermalMailxBlockWithSeveralNodes) {
  DiagnosticSink sink;
  const std::string text = "$bdyty\n MAILx      1\n$models\n THERM\n$nodty\n NO1xx     21\n" + kTemplate +
                           "\n temp       1" + kValues + "\n$nodty\n NO1xx      2\n" + kTemplate +
                           "\n temp       1" + kValues + "\n$$$$$$\n";
  const DrvDofFile file = parse(text, sink);
  ASSERT_EQ(sink.items().size(), 0u);
  ASSERT_EQ(file.bodies.size(), 1u);
  EXPECT_EQ(file.bodies[0].model.value, "THERM");
  ASSERT_EQ(file.bodies[0].nodes.size(), 2u);
  EXPECT_EQ(file.bodies[0].nodes[0].number.value, 21);
  EXPECT_EQ(file.bodies[0].nodes[0].dofs[0].kind.value, "temp");
  // Echo: nodes sorted; the RBDY2 module writes its dashed line first in 2D.
  const std::string echo = write_drv_dof(file);
  const std::string start = "     \n! DOF\n     \n!" + std::string(71, '-') + "\n$bdyty\n MAILx      1\n";
  EXPECT_EQ(echo.substr(0, start.size()), start);
  EXPECT_LT(echo.find(" NO1xx      2"), echo.find(" NO1xx     21"));
}

TEST(DrvDofParser, GuideDofytyIsANoteAndDofsAreRead) {
  DiagnosticSink sink;
  const std::string text =
      "$bdyty\n RBDY2      1\n$nodty\n NO3xx      1\n$dofyty\n"
      "numbr [CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]\n" +
      kDofLine + "\n$$$$$$\n";
  const DrvDofFile file = parse(text, sink);
  expect_one(sink, "L1018", 5, 1);
  EXPECT_EQ(sink.items()[0].severity, Severity::note);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(file.bodies.size(), 1u);
  EXPECT_EQ(file.bodies[0].nodes[0].dofs.size(), 1u);
}

// Broken inputs: one exact diagnostic each.
TEST(DrvDofBroken, TruncatedBlock) {
  DiagnosticSink sink;
  parse("$bdyty\n RBDY2      1\n$nodty\n NO3xx      1\n" + kTemplate + "\n" + kDofLine + "\n", sink);
  expect_one(sink, "L1005", 6, 104);  // at the end of the last line
}

TEST(DrvDofBroken, UnknownBodyType) {
  DiagnosticSink sink;
  std::string text = rigid_block();
  text.replace(text.find("RBDY2"), 5, "RBDY4");
  parse(text, sink);
  expect_one(sink, "L1001", 2, 2);
}

TEST(DrvDofBroken, MalformedNumber) {
  DiagnosticSink sink;
  std::string line = kDofLine;
  line[18] = 'x';  // column 19, inside the CT field 15-28
  parse(rigid_block(line), sink);
  expect_one(sink, "L1002", 6, 15);
}

TEST(DrvDofBroken, ValueShiftedOutOfItsColumns) {
  DiagnosticSink sink;
  parse(rigid_block(" vlocy      1 " + kValues), sink);  // every value one column right
  expect_one(sink, "L1011", 6, 15);
}

// LMGC90 ends the dof list at an unknown keyword and stops there: one error, and the dof line
// after it is read on (not a second "unknown keyword").
TEST(DrvDofBroken, UnknownDofKeywordThenAValidDof) {
  DiagnosticSink sink;
  const std::string second = " vlocy      2" + kValues;
  std::string unknown = kDofLine;
  unknown.replace(1, 5, "vlocx");
  const DrvDofFile file = parse(rigid_block(unknown + "\n" + second), sink);
  expect_one(sink, "L1001", 6, 2);
  EXPECT_EQ(sink.items().size(), 1u);
  ASSERT_EQ(file.bodies.size(), 1u);
  ASSERT_EQ(file.bodies[0].nodes.size(), 1u);
  ASSERT_EQ(file.bodies[0].nodes[0].dofs.size(), 1u);
  EXPECT_EQ(file.bodies[0].nodes[0].dofs[0].dof.value, 2);
}

TEST(DrvDofBroken, DofNumberWhollyOutsideItsColumns) {
  DiagnosticSink sink;
  parse(rigid_block(" vlocy 1     " + kValues), sink);  // the number in column 8
  expect_one(sink, "L1011", 6, 8);
  EXPECT_EQ(sink.items()[0].severity, Severity::warning);
  EXPECT_EQ(sink.items().size(), 1u);  // not also "dof number 0"
  DiagnosticSink right;
  parse(rigid_block(" vlocy       1" + kValues.substr(1)), right);  // the number in column 14
  expect_one(right, "L1011", 6, 14);
  EXPECT_EQ(right.items().size(), 1u);
}

TEST(DrvDofBroken, MissingNodtyLine) {
  DiagnosticSink sink;
  parse("$bdyty\n RBDY2      1\n NO3xx      1\n" + kTemplate + "\n" + kDofLine + "\n$$$$$$\n", sink);
  expect_one(sink, "L1012", 3, 1);
}

TEST(DrvDofBroken, MissingDoftyLine) {
  DiagnosticSink sink;
  parse("$bdyty\n RBDY2      1\n$nodty\n NO3xx      1\n" + kDofLine + "\n$$$$$$\n", sink);
  expect_one(sink, "L1012", 5, 1);
}

TEST(DrvDofBroken, DofNumberOutOfRange) {
  DiagnosticSink sink;
  parse(rigid_block(" vlocy      4" + kValues), sink);  // NO3xx has dofs 1..3
  expect_one(sink, "L1003", 6, 9);
}

TEST(DrvDofBroken, RigidNodeNumberMustBeOne) {
  DiagnosticSink sink;
  std::string text = rigid_block();
  text.replace(text.find(" NO3xx      1"), 13, " NO3xx      2");
  parse(text, sink);
  expect_one(sink, "L1003", 4, 9);
}

TEST(DrvDofBroken, EvolutionWithoutFileName) {
  DiagnosticSink sink;
  parse(rigid_block(" force      2 evolution"), sink);
  expect_one(sink, "L1015", 6, 25);
}

TEST(DrvDofBroken, ThermalKeywordInMechanicalBlock) {
  DiagnosticSink sink;
  parse("$bdyty\n MAILx      1\n$model\n MECAx\n$nodty\n NO2xx      5\n" + kTemplate + "\n temp       1" +
            kValues + "\n$$$$$$\n",
        sink);
  expect_one(sink, "L1017", 8, 2);
}

TEST(DrvDofBroken, MailxWithoutModel) {
  DiagnosticSink sink;
  parse("$bdyty\n MAILx      1\n$nodty\n NO2xx      5\n" + kTemplate + "\n" + kDofLine + "\n$$$$$$\n", sink);
  expect_one(sink, "L1012", 3, 1);
}

// LMGC90 reads a DRV_DOF.DAT without any '$bdyty' as "no driven dof" (read_driven_dof scans
// for '$bdyty' to the end of the file), so a file of comments only is valid and empty.
TEST(DrvDofParser, FileOfCommentsOnlyDrivesNothingAndIsNotAnError) {
  DiagnosticSink sink;
  const DrvDofFile file = parse("! only a comment\n\n", sink);
  EXPECT_TRUE(sink.items().empty());
  EXPECT_TRUE(file.bodies.empty());
}

TEST(DrvDofBroken, NeverCrashesOnGarbage) {
  const std::string inputs[] = {"$bdyty",
                                "$bdyty\n",
                                "$bdyty\n MAILx",
                                "$bdyty\n MAILx\n$model",
                                "$bdyty\n RBDY2\n$nodty",
                                "$bdyty\n RBDY2\n$nodty\n NO3xx\n$dofyty",
                                "\t\t$$$$$$\n$bdyty\n$$$$$$\n",
                                std::string(500, '$')};
  for (const auto& text : inputs) {
    DiagnosticSink sink;
    parse(text, sink);
    EXPECT_TRUE(sink.has_errors() || sink.warning_count() > 0) << text;
  }
}

// A block whose node drives no dof is not echoed, so it must not put its module's section in
// the echo either: the echo of the echo is the echo.
TEST(DrvDofWriter, BlockWithoutDrivenDofsLeavesNoSectionInTheEcho) {
  DiagnosticSink sink;
  const DrvDofFile file = parse(
      "$bdyty\n MAILx      1\n$model\n MECAx\n$nodty\n NO3xx      1\n" + kTemplate + "\n" + " vlocy      3" +
          kValues + "\n$$$$$$\n$bdyty\n RBDY2      1\n$nodty\n NO3xx      1\n" + kTemplate + "\n$$$$$$\n",
      sink);
  ASSERT_FALSE(sink.has_errors()) << sink.items()[0].code << " " << sink.items()[0].message;
  const std::string echo = write_drv_dof(file);
  EXPECT_EQ(echo.find("RBDY2"), std::string::npos) << echo;
  DiagnosticSink again;
  EXPECT_EQ(write_drv_dof(parse(echo, again)), echo);
}

// The echo of a 3D mesh that drives no dof is the bare header; read back alone it would be taken
// for a 2D file, so the echo of the echo is written, as LMGC90 writes it, for the case's modules:
// the first file's setup.
TEST(DrvDofWriter, EchoOfAnEchoWithoutDrivenDofsKeepsTheCaseSetup) {
  DiagnosticSink sink;
  const DrvDofFile file = parse(
      "$bdyty\n MAILx      1\n$model\n MECAx\n$nodty\n NO3xx      1\n" + kTemplate + "\n$$$$$$\n", sink);
  ASSERT_FALSE(sink.has_errors());
  const DrvDofEchoSetup setup = drv_dof_echo_setup_of(file);
  EXPECT_EQ(setup.dimension, 3);
  const std::string echo = write_drv_dof(file, setup);
  DiagnosticSink again;
  EXPECT_EQ(write_drv_dof(parse(echo, again), setup), echo);
}

// A node given twice, under NO1xx and under NO2xx, is one node (LMGC90 takes nodes by number): the
// echo writes it once with the wider type, which holds the second dof, so the echo reads back.
TEST(DrvDofWriter, NodeGivenUnderTwoTypesIsEchoedWithTheWiderOne) {
  DiagnosticSink sink;
  const DrvDofFile file =
      parse("$bdyty\n MAILx      1\n$model\n MECAx\n$nodty\n NO1xx      5\n" + kTemplate +
                "\n$nodty\n NO2xx      5\n" + kTemplate + "\n vlocy      2" + kValues + "\n$$$$$$\n",
            sink);
  ASSERT_FALSE(sink.has_errors()) << sink.items()[0].code << " " << sink.items()[0].message;
  const std::string echo = write_drv_dof(file);
  EXPECT_NE(echo.find(" NO2xx      5"), std::string::npos) << echo;
  EXPECT_EQ(echo.find("NO1xx"), std::string::npos) << echo;
  DiagnosticSink again;
  EXPECT_EQ(write_drv_dof(parse(echo, again)), echo);
  EXPECT_FALSE(again.has_errors());
}

// Evolution files.
EvolutionFile evolution(const std::string& text, DiagnosticSink& sink) {
  return parse_evolution(SourceText("vy.dat", text), sink);
}

TEST(EvolutionParser, ReadsListDirectedPairs) {
  DiagnosticSink sink;
  const EvolutionFile file = evolution(
      "  0.000000000000000E+000  0.000000000000000E+000\n   1.50000000000000      -3.000000000000000E-002\n"
      "\n 2.0, 4.0\n",
      sink);
  ASSERT_EQ(sink.items().size(), 0u);
  ASSERT_EQ(file.points.size(), 3u);
  EXPECT_DOUBLE_EQ(file.points[1].time.value, 1.5);
  EXPECT_DOUBLE_EQ(file.points[1].value.value, -0.03);
  EXPECT_DOUBLE_EQ(file.points[2].value.value, 4.0);
  // As gfortran 12 writes `write(nfich,*) x, fx` (LMGC90's echo of an evolution file).
  EXPECT_EQ(write_evolution(file),
            "   0.0000000000000000        0.0000000000000000     \n"
            "   1.5000000000000000       -2.9999999999999999E-002\n"
            "   2.0000000000000000        4.0000000000000000     \n");
}

// gfortran's list-directed REAL(8) output around its F/E boundaries (printed by gfortran 12.2 for the
// same values): F form from 0.1 to below 1e17 after rounding to 17 digits, E form otherwise.
TEST(EvolutionWriter, WritesGfortransListDirectedForm) {
  EvolutionFile file;
  const auto pair = [&](double t, double v) { file.points.push_back({Real{t}, Real{v}}); };
  pair(0.99999999999999999, 9.99999999999999999e16);
  pair(0.099999999999999999, 5e-324);
  pair(0.09999, -0.03);
  pair(123456.789, 1e16);
  pair(-0.5, 2.5e300);
  EXPECT_EQ(write_evolution(file),
            "   1.0000000000000000        1.0000000000000000E+017\n"
            "  0.10000000000000001        4.9406564584124654E-324\n"
            "   9.9989999999999996E-002  -2.9999999999999999E-002\n"
            "   123456.78900000000        10000000000000000.     \n"
            " -0.50000000000000000        2.5000000000000001E+300\n");
}

TEST(EvolutionBroken, SinglePair) {
  DiagnosticSink sink;
  evolution("0.0 1.0\n", sink);
  expect_one(sink, "L1014", 1, 1);
}

TEST(EvolutionBroken, RepeatedTime) {
  DiagnosticSink sink;
  evolution("0.0 0.0\n1.0 1.0\n  1.0 2.0\n", sink);
  expect_one(sink, "L2016", 3, 3);
}

TEST(EvolutionBroken, DecreasingTime) {
  DiagnosticSink sink;
  evolution("0.0 0.0\n2.0 1.0\n1.0 2.0\n", sink);
  expect_one(sink, "L2016", 3, 1);
}

TEST(EvolutionBroken, MalformedValue) {
  DiagnosticSink sink;
  evolution("0.0 0.0\n1.0 1.x\n2.0 1.0\n", sink);
  expect_one(sink, "L1002", 2, 5);
}

TEST(EvolutionBroken, MissingValue) {
  DiagnosticSink sink;
  evolution("0.0 0.0\n1.0\n2.0 1.0\n", sink);
  expect_one(sink, "L1015", 2, 4);
}

TEST(EvolutionBroken, CommentLineIsNotAllowed) {
  DiagnosticSink sink;
  evolution("! t v\n0.0 0.0\n1.0 1.0\n", sink);
  expect_one(sink, "L1002", 1, 1);
}

// Lines cut at once by a '/' hold no pair at all: still too few pairs, not an empty evolution.
TEST(EvolutionBroken, LinesWithoutAnyValueAreTooFewPairs) {
  DiagnosticSink sink;
  const EvolutionFile file = evolution("//1.01\n/ 2.0 3.0\n", sink);
  EXPECT_TRUE(file.points.empty());
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, "L1014") << sink.items()[0].message;
}

TEST(EvolutionBroken, EmptyFile) {
  DiagnosticSink sink;
  evolution("", sink);
  expect_one(sink, "L1009", 0, 0);
}

}  // namespace
}  // namespace lmgc::grammar
