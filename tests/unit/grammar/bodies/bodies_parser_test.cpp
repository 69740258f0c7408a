// BODIES.DAT cards, one behaviour per test, and broken files with their exact diagnostic.
#include <gtest/gtest.h>

#include "grammar/bodies/parser.hpp"
#include "grammar/bodies/writer.hpp"

namespace lmgc::grammar {
namespace {

struct Parsed {
  BodiesFile file;
  DiagnosticSink sink;
};

Parsed parse(const std::string& text) {
  Parsed p;
  p.file = parse_bodies(SourceText("BODIES.DAT", text), p.sink);
  return p;
}

const Diagnostic& first_error(const Parsed& p) {
  for (const auto& d : p.sink.items())
    if (d.severity != Severity::note) return d;
  static const Diagnostic none{"none", Severity::note, {}, "no diagnostic", {}, {}};
  return none;
}

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  const Parsed p = parse(text);
  const Diagnostic& d = first_error(p);
  EXPECT_EQ(d.code, code) << d.message;
  EXPECT_EQ(d.where.span.line, line) << d.message;
  EXPECT_EQ(d.where.span.column, column) << d.message;
}

const std::string kDisk =
    "$bdyty\n"
    " RBDY2      1\n"
    "$blmty\n"
    " PLAIN      1  behav  PLEXx  avrd= 0.1600000D-02  gyrd= 0.1131200D-02\n"
    "$nodty\n"
    " NO3xx      1                coo1= 0.5808000D-01  coo2= 0.4928000D-01  coo3= 0.0000000D+00\n"
    "$tacty\n"
    " DISKx      1  color  BLEUx  byrd= 0.1600000D-02\n"
    "$$$$$$\n";

TEST(BodiesParser, ReadsARigidDisk) {
  const Parsed p = parse(kDisk);
  ASSERT_FALSE(p.sink.has_errors());
  ASSERT_EQ(p.file.bodies.size(), 1u);
  const Body& b = p.file.bodies[0];
  EXPECT_EQ(b.type, BodyType::rbdy2);
  EXPECT_EQ(b.rigid_bulk->behav.value, "PLEXx");
  EXPECT_DOUBLE_EQ(b.rigid_bulk->gyrd.value, 0.0011312);
  ASSERT_EQ(b.nodes.size(), 1u);
  EXPECT_DOUBLE_EQ(b.nodes[0].coordinates[1].value, 0.04928);
  ASSERT_EQ(b.contactors.size(), 1u);
  EXPECT_EQ(b.contactors[0].color.value, "BLEUx");
  EXPECT_DOUBLE_EQ(b.contactors[0].values[0].value, 0.0016);
  EXPECT_EQ(b.contactors[0].values[0].span.line, 8u);
  EXPECT_EQ(b.contactors[0].values[0].span.column, 35u);
}

TEST(BodiesParser, CommentsBlankLinesCrlfAndTrailingSpacesAreAccepted) {
  std::string text = "! comment\n#another\n\n";
  for (char c : kDisk) {
    if (c == '\n')
      text += "   \r\n";
    else
      text += c;
  }
  const Parsed p = parse(text);
  EXPECT_FALSE(p.sink.has_errors());
  EXPECT_TRUE(p.file == parse(kDisk).file);
}

TEST(BodiesParser, ValuesTouchingTheirLabelAndLowerCaseExponents) {
  std::string text = kDisk;
  text.replace(text.find("coo1= 0.5808000D-01"), 19, "coo1=5.8080000e-02 ");
  const Parsed p = parse(text);
  EXPECT_FALSE(p.sink.has_errors());
  EXPECT_DOUBLE_EQ(p.file.bodies[0].nodes[0].coordinates[0].value, 0.05808);
}

TEST(BodiesParser, PolygonVerticesAndClusterOffsets) {
  const Parsed p = parse(
      "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEX1  avrd= 0.4914880D-02\n$nodty\n"
      " NO3xx      1                coo1= 0.1997871D-01  coo2= 0.1997871D-01  coo3= 0.0000000D+00\n$tacty\n"
      " POLYG      1  color  BLEUx  nb_vertex=      3    byrd= 0.0000000D+00\n"
      "                             coo1= 0.3071800D-02  coo2= 0.1843080D-02\n"
      "                             coo1=-0.3071800D-02  coo2= 0.1843080D-02\n"
      "                             coo1=-0.3071800D-02  coo2=-0.1843080D-02\n"
      " DISKb      2  color  BLEUx  byrd= 0.3071800D-02\n"
      "                             coo1= 0.0000000D+00  coo2= 0.1843080D-02\n$$$$$$\n");
  ASSERT_FALSE(p.sink.has_errors());
  const auto& tacts = p.file.bodies[0].contactors;
  ASSERT_EQ(tacts.size(), 2u);
  EXPECT_EQ(tacts[0].vertices.size(), 3u);
  EXPECT_DOUBLE_EQ(tacts[0].vertices[2][1].value, -0.00184308);
  ASSERT_EQ(tacts[1].values.size(), 3u);
  EXPECT_DOUBLE_EQ(tacts[1].values[2].value, 0.00184308);
}

TEST(BodiesParser, MailxElementsModelsAndPolylineContinuations) {
  const Parsed p = parse(
      "$bdyty\n MAILx      1\n$blmty\n Q4xxx      1  nodes      1      2      3      4\n"
      "               model  M2DNL  behav  Stee1\n$nodty\n"
      " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n"
      " NO2xx      2                coo1= 0.1000000D+01  coo2= 0.0000000D+00\n"
      " NO2xx      3                coo1= 0.1000000D+01  coo2= 0.1000000D+01\n"
      " NO2xx      4                coo1= 0.0000000D+00  coo2= 0.1000000D+01\n$tacty\n"
      " CLxxx      1  color  BLEUS  noda=    4  nodb=    1  apab= 0.5000000D+00\n"
      " ALpxx      2  color  BLEUE  noda=    1  nodb=    2\n"
      "+ALpxx      2                noda=    2  nodb=    3\n$$$$$$\n");
  ASSERT_FALSE(p.sink.has_errors());
  const Body& b = p.file.bodies[0];
  EXPECT_EQ(b.type, BodyType::mailx);
  ASSERT_EQ(b.elements.size(), 1u);
  EXPECT_EQ(b.elements[0].nodes[3].value, 4);
  EXPECT_EQ(b.elements[0].models[0].behav.value, "Stee1");
  ASSERT_EQ(b.contactors.size(), 2u);
  EXPECT_EQ(b.contactors[0].nodes[0].value, 4);
  ASSERT_EQ(b.contactors[1].continuations.size(), 1u);
  EXPECT_EQ(b.contactors[1].continuations[0].nodes[1].value, 3);
}

TEST(BodiesParser, BodiesAreGroupedAsLmgc90NumbersThem) {
  const std::string mailx =
      "$bdyty\n MAILx      1\n$blmty\n S2xxx      1  nodes      1      2\n"
      "               model  M2DNL  behav  Stee1\n$nodty\n"
      " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n"
      " NO2xx      2                coo1= 0.1000000D+01  coo2= 0.0000000D+00\n$$$$$$\n";
  const Parsed p = parse(kDisk + mailx);
  ASSERT_EQ(p.file.bodies.size(), 2u);
  EXPECT_EQ(p.file.bodies[0].type, BodyType::mailx);
  EXPECT_EQ(p.file.bodies[1].type, BodyType::rbdy2);
}

// DISPx and xPSID, in the 2012 user's guide, were removed from LMGC90, whose reader stops on them:
// an error, with the body still read so that the file echoes.
TEST(BodiesParser, RemovedPneumaticDisksAreErrors) {
  for (const char* removed : {"DISPx", "xPSID"}) {
    std::string text = kDisk;
    text.replace(text.find("DISKx"), 5, removed);
    const Parsed p = parse(text);
    EXPECT_TRUE(p.sink.has_errors()) << removed;
    ASSERT_FALSE(p.sink.items().empty());
    EXPECT_EQ(p.sink.items()[0].code, "L1001");
    EXPECT_NE(p.sink.items()[0].message.find("removed from LMGC90"), std::string::npos);
    ASSERT_EQ(p.file.bodies.size(), 1u);
  }
}

TEST(BodiesWriter, WritesLmgc90EchoLayout) {
  const std::string echo = write_bodies(parse(kDisk).file);
  EXPECT_NE(echo.find("$bdyty\n RBDY2        1\n$blmty\n"
                      " PLAIN      1  behav  PLEXx  avrd= 0.1600000D-02  gyrd= 0.1131200D-02\n"),
            std::string::npos);
  EXPECT_NE(echo.find(" DISKx      1  color  BLEUx  byrd= 0.1600000D-02\n$$$$$$\n      \n"),
            std::string::npos);
}

// ---- broken files: exact code and position -------------------------------------------------

TEST(BodiesBroken, EmptyFile) {
  expect_diagnostic("", "L1009", 0, 0);
}
TEST(BodiesBroken, OnlyComments) {
  expect_diagnostic("! nothing\n\n# here\n", "L1009", 0, 0);
}

TEST(BodiesBroken, MissingEndOfBodyBeforeNextBody) {
  std::string text = kDisk;
  text.erase(text.find("$$$$$$"), 7);
  expect_diagnostic(text + kDisk, "L1005", 9, 1);
}

TEST(BodiesBroken, TruncatedBlockAtEndOfFile) {
  std::string text = kDisk.substr(0, kDisk.find("$tacty"));
  expect_diagnostic(text, "L1005", 6, 91);
}

TEST(BodiesBroken, UnknownBodyType) {
  std::string text = kDisk;
  text.replace(text.find("RBDY2"), 5, "RBDY9");
  expect_diagnostic(text, "L1001", 2, 2);
}

TEST(BodiesBroken, UnknownContactor) {
  std::string text = kDisk;
  text.replace(text.find("DISKx"), 5, "DISCx");
  expect_diagnostic(text, "L1001", 8, 2);
}

TEST(BodiesBroken, ContactorOfTheWrongBodyType) {
  std::string text = kDisk;
  text.replace(text.find("DISKx"), 5, "SPHER");
  expect_diagnostic(text, "L1001", 8, 2);
}

TEST(BodiesBroken, UnknownNodeType) {
  std::string text = kDisk;
  text.replace(text.find("NO3xx"), 5, "NO7xx");
  expect_diagnostic(text, "L1001", 6, 2);
}

TEST(BodiesBroken, MalformedNumber) {
  std::string text = kDisk;
  text.replace(text.find("0.1600000D-02  gyrd"), 13, "0.16OOOOOD-02");
  expect_diagnostic(text, "L1002", 4, 35);
}

TEST(BodiesBroken, OutOfRangeNumber) {
  std::string text = kDisk;
  text.replace(text.find("byrd= 0.1600000D-02"), 19, "byrd= 0.16000D+9999");
  expect_diagnostic(text, "L1003", 8, 35);
}

TEST(BodiesBroken, ValueShiftedOneColumnRight) {
  std::string text = kDisk;
  text.replace(text.find("byrd= 0.1600000D-02"), 19, "byrd=  0.1600000D-02");
  expect_diagnostic(text, "L1011", 8, 35);
}

TEST(BodiesBroken, ValueShiftedOneColumnLeft) {
  std::string text = kDisk;
  text.replace(text.find("coo2= 0.4928000D-01"), 19, "coo20.4928000D-01  ");
  expect_diagnostic(text, "L1011", 6, 56);
}

TEST(BodiesBroken, TabInsideAReadField) {
  std::string text = kDisk;
  text.replace(text.find("byrd= 0.1600000D-02"), 19, "byrd=\t0.1600000D-02");
  expect_diagnostic(text, "L1007", 8, 35);
}

TEST(BodiesBroken, NonAsciiByte) {
  std::string text = kDisk;
  text.replace(text.find("BLEUx"), 5, "BL\xC3\x89x");
  expect_diagnostic(text, "L1008", 8, 25);
}

TEST(BodiesBroken, TextBeyondColumn180) {
  std::string text = kDisk;
  text.replace(text.find(" RBDY2      1\n"), 14, " RBDY2      1" + std::string(180, ' ') + "x\n");
  expect_diagnostic(text, "L1010", 2, 181);
}

TEST(BodiesBroken, TenMegabyteLineNeitherCrashesNorHangs) {
  std::string text = kDisk;
  text.replace(text.find(" RBDY2      1\n"), 14, " RBDY2      1" + std::string(10 * 1024 * 1024, '7') + "\n");
  expect_diagnostic(text, "L1010", 2, 181);
}

TEST(BodiesBroken, PolygonCutShortByEndOfFile) {
  const std::string text =
      "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEX1  avrd= 0.4914880D-02\n$nodty\n"
      " NO3xx      1                coo1= 0.1997871D-01  coo2= 0.1997871D-01  coo3= 0.0000000D+00\n$tacty\n"
      " POLYG      1  color  BLEUx  nb_vertex=      4\n"
      "                             coo1= 0.3071800D-02  coo2= 0.1843080D-02\n";
  expect_diagnostic(text, "L1006", 9, 70);
}

// A '$...' line where a vertex line is expected ends the polygon (LMGC90 would read '$$$$$$',
// '$bdyty', ... as vertices): one error, and the next body reads normally.
TEST(BodiesBroken, PolygonCutShortByEndOfBody) {
  const std::string text =
      "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEX1  avrd= 0.4914880D-02\n$nodty\n"
      " NO3xx      1                coo1= 0.1997871D-01  coo2= 0.1997871D-01  coo3= 0.0000000D+00\n$tacty\n"
      " POLYG      1  color  BLEUx  nb_vertex=      4\n"
      "                             coo1= 0.3071800D-02  coo2= 0.1843080D-02\n$$$$$$\n" +
      kDisk;
  const Parsed p = parse(text);
  ASSERT_EQ(p.sink.items().size(), 1u) << p.sink.items()[0].message;
  EXPECT_EQ(p.sink.items()[0].code, "L1013");
  EXPECT_EQ(p.sink.items()[0].where.span.line, 10u);
  EXPECT_EQ(p.sink.items()[0].where.span.column, 1u);
  ASSERT_EQ(p.file.bodies.size(), 2u);
  EXPECT_TRUE(p.file.bodies[0].contactors.empty());  // the cut polygon is dropped
  EXPECT_EQ(p.file.bodies[1].contactors.size(), 1u);
}

TEST(BodiesBroken, NodeContinuationCutByNextSection) {
  const std::string text =
      "$bdyty\n RBDY3      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00\n$nodty\n"
      " NO6xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
      "$tacty\n SPHER      1  color  BLEUx  byrd= 0.1000000D+00\n$$$$$$\n";
  expect_diagnostic(text, "L1013", 7, 1);
}

TEST(BodiesBroken, RigidBodyWithTwoNodes) {
  std::string text = kDisk;
  const std::string node =
      " NO3xx      1                coo1= 0.5808000D-01  coo2= 0.4928000D-01  coo3= 0.0000000D+00\n";
  text.insert(text.find("$tacty"), node);
  expect_diagnostic(text, "L1014", 2, 2);
}

TEST(BodiesBroken, RigidBodyWithoutNode) {
  std::string text = kDisk;
  text.erase(text.find("$nodty"), text.find("$tacty") - text.find("$nodty"));
  expect_diagnostic(text, "L1012", 2, 2);
}

TEST(BodiesBroken, SectionsOutOfOrder) {
  const std::string text =
      "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1600000D-02  gyrd= 0.1131200D-02\n"
      "$tacty\n DISKx      1  color  BLEUx  byrd= 0.1600000D-02\n$nodty\n"
      " NO3xx      1                coo1= 0.5808000D-01  coo2= 0.4928000D-01  coo3= 0.0000000D+00\n$$$$$$\n";
  expect_diagnostic(text, "L1013", 7, 2);
}

TEST(BodiesBroken, ElementWithoutModelLine) {
  const std::string text =
      "$bdyty\n MAILx      1\n$blmty\n S2xxx      1  nodes      1      2\n$nodty\n"
      " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n"
      " NO2xx      2                coo1= 0.1000000D+01  coo2= 0.0000000D+00\n$$$$$$\n";
  expect_diagnostic(text, "L1012", 4, 2);
}

TEST(BodiesBroken, MalformedConnectivityInteger) {
  const std::string text =
      "$bdyty\n MAILx      1\n$blmty\n S2xxx      1  nodes      1    2.5\n"
      "               model  M2DNL  behav  Stee1\n$nodty\n"
      " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n$$$$$$\n";
  expect_diagnostic(text, "L1004", 4, 28);
}

TEST(BodiesBroken, PolyhedronWithoutItsCounts) {
  const std::string text =
      "$bdyty\n RBDY3      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.0000000D+00\n$nodty\n"
      " NO6xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
      "                             coo4= 0.0000000D+00  coo5= 0.0000000D+00  coo6= 0.0000000D+00\n$tacty\n"
      " POLYR      1  color  REDXx  nb_vertex=\n$$$$$$\n";
  expect_diagnostic(text, "L1015", 9, 40);
}

TEST(BodiesBroken, TextOutsideAnyBodyIsAWarningAndKeepsParsing) {
  const Parsed p = parse("stray text\n" + kDisk);
  ASSERT_FALSE(p.sink.items().empty());
  EXPECT_EQ(p.sink.items()[0].code, "L1019");
  EXPECT_EQ(p.sink.items()[0].severity, Severity::warning);
  EXPECT_EQ(p.file.bodies.size(), 1u);
}

}  // namespace
}  // namespace lmgc::grammar
