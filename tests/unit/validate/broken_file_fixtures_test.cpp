// Broken-file fixtures for every grammar reader and for case loading: each row is one broken input
// and the exact first diagnostic it must give (code, severity, line, column), with the number of
// diagnostics in all. Bad input never crashes and never hangs (rows with a 10 MB line run in
// milliseconds). The bases are valid files (from reference_cases/disk_bounce_rst and the readers'
// unit tests), checked clean by BaseFilesAreClean, so each diagnostic comes from the breakage alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/bodies/parser.hpp"
#include "grammar/bulk_behav/parser.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/dof/parser.hpp"
#include "grammar/drv_dof/parser.hpp"
#include "grammar/gpv/parser.hpp"
#include "grammar/models/parser.hpp"
#include "grammar/postpro/parser.hpp"
#include "grammar/ptpt3_network/parser.hpp"
#include "grammar/tact_behav/parser.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "tests/support/run_tool.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;
using grammar::DiagnosticSink;
using grammar::Severity;
using grammar::SourceText;

// What reads the fixture: one grammar reader, or load_case on a scratch case folder.
enum class Reader {
  bodies,
  bulk_behav,
  tact_behav,
  models,
  drv_dof,
  evolution,
  ptpt3_network,
  dof,
  vloc_rloc,
  gpv,
  postpro,
  command,
  case_folder
};

// reference_cases/disk_bounce_rst/DATBOX/BODIES.DAT, lines 1-19.
const std::string kBodies =
    "! A disk of radius 0.1 m dropped from 1 m (centre height 1.1 m) on a fixed JONCx wall.\n"
    "$bdyty\n"
    " RBDY2      1\n"
    "$blmty\n"
    " PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00  gyrd= 0.7071068D-01\n"
    "$nodty\n"
    " NO3xx      1                coo1= 0.0000000D+00  coo2= 0.1100000D+01  coo3= 0.0000000D+00\n"
    "$tacty\n"
    " DISKx      1  color  BLEUx  byrd= 0.1000000D+00\n"  // line 9
    "$$$$$$\n"
    "$bdyty\n"
    " RBDY2      2\n"
    "$blmty\n"
    " PLAIN      1  behav  TDURx  avrd= 0.1000000D+00  gyrd= 0.1000000D+00\n"
    "$nodty\n"
    " NO3xx      1                coo1= 0.0000000D+00  coo2=-0.5000000D-01  coo3= 0.0000000D+00\n"
    "$tacty\n"
    " JONCx      1  color  WALLx  ax1 = 0.1000000D+01  ax2 = 0.5000000D-01\n"  // line 18, 69 columns
    "$$$$$$\n";

// reference_cases/disk_bounce_rst/DATBOX/BULK_BEHAV.DAT, lines 1-9.
const std::string kBulkBehav =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n"
    "\n"
    "$behav  lawty\n"
    " PLEXx  RIGID                           Umas= 0.1000000D+04\n"  // line 5
    "\n"
    "$behav  lawty\n"
    " TDURx  RIGID                           Umas= 0.1000000D+04\n"
    "\n";

// reference_cases/disk_bounce_rst/DATBOX/TACT_BEHAV.DAT, lines 1-9.
const std::string kTactBehav =
    "! Restitution 0.8 in the normal direction, frictionless: bounce heights follow e^(2n) h.\n"
    "$behav  lawty\n"
    " rst08  RST_CLB                         rstn= 0.8000000D+00  rstt= 0.0000000D+00\n"  // line 3, 80
                                                                                          // columns
    "                                        fric= 0.0000000D+00\n"
    "\n"
    "$seety\n"
    " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
    " RBDY2  DISKx  BLEUx  rst08  RBDY2  JONCx  WALLx       0.1000000D-01\n"  // line 8
    "\n";

// tests/unit/grammar/models: lines 1-5.
const std::string kModels =
    "$model  mdlty  finel  eleop  value\n"
    " M2DNL\n"
    "        MECAx  Q4xxx  isext  MatL_\n"
    "                      kine_  large\n"
    "                      extvf  temperature                        3\n";  // size I5 at 61-65

// reference_cases/disk_bounce_rst/DATBOX/DRV_DOF.DAT, lines 1-10.
const std::string kDrvDof =
    "! The wall is fixed: its three velocities are imposed to zero.\n"
    "$bdyty\n"
    " RBDY2      2\n"
    "$nodty\n"
    " NO3xx      1\n"
    "$dofty  numbr "
    "[CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]...*...[RAMPI.....+.....RAMP.*.time]\n"
    " vlocy      1  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  "
    "0.0000000D+00\n"
    " vlocy      2  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  "
    "0.0000000D+00\n"
    " vlocy      3  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  "
    "0.0000000D+00\n"
    "$$$$$$\n";

// An evolution file: one list-directed 't v' pair per line.
const std::string kEvolution =
    "0.0000000D+00 0.0000000D+00\n0.1000000D+01 0.5000000D+00\n0.2000000D+01 0.5000000D+00\n";

// A PTPT3 network: two links, one across the x period with iloop = 1.
const std::string kPtpt3Network = " 1 3 0 0 0 0.1000000D+01\n 4 2 1 0 1 0.1000000D+01\n";

// A DOF file holding the default case's disk (layout of tests/unit/grammar/dof), lines 1-14.
const std::string kDashes = "!" + std::string(71, '-') + "\n";
const std::string kDof =
    "     \n! DOF\n     \n$steps        0              time= 0.1000000D+01\n \n" + kDashes +
    "$bdyty\n"
    " RBDY2        1\n"
    "$nodty\n"
    " NO3xx      1              "
    "  X(1)= 0.0000000D+00  X(2)= 0.1100000D+01  X(3)= 0.0000000D+00\n"  // line 10
    "                           "
    "  V(1)= 0.0000000D+00  V(2)=-0.9810000D+01  V(3)= 0.0000000D+00\n"  // line 11, 90 columns
    "$$$$$$\n"
    "      \n" +
    kDashes;

// tests/unit/grammar/vloc_rloc: header lines 1-6, one DKDKx block lines 7-15.
const std::string kVlocRloc =
    "     \n! Vloc_Rloc\n      \n$steps      300              time= 0.6000000D-01\n \n" + kDashes +
    "$icdan  DKDKx      642\n"
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj\n"
    " RBDY2      2  DISKx      1  iqsc1  RBDY2    844  DISKx      1  stick    844\n"  // line 9, 76 columns
    "                             rlt/H-0.4336294D-01  rln/H 0.1146651D+00  rls/H 0.0000000D+00\n"
    "                             vlt =-0.6938894D-17  vln =-0.1258967D-07  vls = 0.0000000D+00\n"
    "                             gapTT 0.0000000D+00\n"
    "                             n(1)= 0.8987325D+00  n(2)= 0.4384974D+00  n(3)= 0.0000000D+00\n"
    "                             coo1= 0.8982992D-01  coo2= 0.9350228D-03  coo3= 0.0000000D+00\n"
    " \n";

// tests/unit/grammar/gpv: lines 1-16.
const std::string kGpv =
    "     \n! Gauss Point Values\n      \n$steps      100              time= 0.1000000D+00\n \n" + kDashes +
    "$bdyty\n MAILx      1\n$blmty\n Q4xxx      1\n$model\n THERM\n"
    " 0.2930000D+03\n"                              // line 13
    " 0.1853783D+03-0.3637979D-11 0.0000000D+00\n"  // line 14, 42 columns
    "$$$$$$\n" +
    kDashes;

// tests/unit/grammar/postpro: lines 1-9.
const std::string kPostpro =
    "#23456789012345678901234567890:\n"
    "BODY TRACKING                 :\n"
    "STEP 1                        :\n"
    "2                             :\n"
    "54                            :\n"
    "1025                          :\n"  // line 6
    "SOLVER INFORMATIONS           :\n"
    "STEP 10                       :\n"
    "END                           :\n";

// A short legacy COMMAND.DAT (keywords of tests/unit/grammar/command), lines 1-17.
const std::string kCommand =
    "#23456789012345678901234567890:\n"
    "ECHO OFF                      :\n"
    "TIME STEP                     :\n"
    "1.D-03                        : the step\n"  // line 4
    "COMPUTE BOX                   :\n"
    "COMPUTE MASS                  :\n"
    "loading step                  : label of the loop\n"
    "INCREMENT STEP                :\n"
    "NB BULK ITER MAX              :\n"
    "10                            :\n"  // line 10
    "WRITE OUT DOF STEP 10         :\n"
    "REPETE 2 FOIS                 :\n"
    "DEPUIS loading step           :\n"
    "FIN DU PROGRAMME\n"
    "#-----------------------------:\n"
    "FIN DU FICHIER\n";

// The base text `edit` fails with: it matches no expectation, so a stale edit shows as a failure.
constexpr const char* kEditFailed = "<edit failed: text not found>";

// `text` with the first `from` replaced by `to`.
std::string edit(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) return kEditFailed;
  return text.replace(at, from.size(), to);
}

// `text` with every "\n" written "\r\n".
std::string crlf(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return out;
}

// `record` padded with blanks to column 180, the last column LMGC90 reads.
std::string to_column_180(std::string record) {
  record.resize(180, ' ');
  return record;
}

struct Fixture {
  std::string name;  // test name suffix
  Reader reader;
  std::string text;  // file content; for Reader::case_folder the path to delete from the case
  std::string code;  // expected first diagnostic; empty: the input is accepted without any diagnostic
  Severity severity = Severity::error;
  std::uint32_t line = 0;  // 0 for a whole-file diagnostic
  std::uint32_t column = 0;
  std::size_t count = 1;  // diagnostics in all
  // When set, this line is lengthened to 10 MB with `long_fill` when the test runs (not when the
  // table is built: every test process builds the whole table).
  std::uint32_t long_line = 0;
  char long_fill = 'x';
};

constexpr std::size_t kLongLineSize = std::size_t{10} << 20;

// `text` with line `number` (1-based) lengthened to kLongLineSize bytes with `fill`.
std::string lengthen_line(std::string text, std::uint32_t number, char fill) {
  std::size_t begin = 0;
  for (std::uint32_t n = 1; n < number; ++n) begin = text.find('\n', begin) + 1;  // rows name a real line
  const std::size_t end = std::min(text.find('\n', begin), text.size());
  text.insert(end, kLongLineSize - (end - begin), fill);
  return text;
}

// gtest prints a failing parameter: the name, not a 10 MB text.
void PrintTo(const Fixture& f, std::ostream* out) {
  *out << f.name;
}

std::vector<Fixture> fixtures() {
  using enum Reader;
  const Severity error = Severity::error, warning = Severity::warning;
  return {
      // ---- BODIES.DAT
      {"BodiesTruncatedBlock", bodies, kBodies.substr(0, kBodies.rfind("$$$$$$")), "L1005", error, 18, 70},
      {"BodiesMissingEndBetweenBlocks", bodies, edit(kBodies, "$$$$$$\n$bdyty", "$bdyty"), "L1005", error, 10,
       1},
      {"BodiesUnknownBodyType", bodies, edit(kBodies, " RBDY2      1", " RBDY9      1"), "L1001", error, 3,
       2},
      {"BodiesUnknownContactor", bodies, edit(kBodies, " DISKx", " DISCx"), "L1001", error, 9, 2},
      {"BodiesUnknownBulkElement", bodies,
       edit(kBodies, " PLAIN      1  behav  PLEXx", " PLAIX      1  behav  PLEXx"), "L1001", error, 5, 2, 2},
      {"BodiesMalformedReal", bodies, edit(kBodies, "byrd= 0.1000000D+00", "byrd= 0.10OOOOOD+00"), "L1002",
       error, 9, 35},
      {"BodiesRealOverflow", bodies, edit(kBodies, "byrd= 0.1000000D+00", "byrd= 0.100000D+999"), "L1003",
       error, 9, 35},
      {"BodiesValueShiftedRight", bodies, edit(kBodies, "byrd= 0.1000000D+00", "byrd=  0.1000000D+00"),
       "L1011", warning, 9, 35},
      {"BodiesTabInField", bodies, edit(kBodies, "byrd= 0.1000000D+00", "byrd=\t0.1000000D+00"), "L1007",
       warning, 9, 35},
      // "BLÉx" keeps the 5 columns of "BLEUx": the byte 0xC3 is in column 25.
      {"BodiesNonAsciiColour", bodies, edit(kBodies, "BLEUx", "BL\xC3\x89x"), "L1008", error, 9, 25},
      {"BodiesCrlfAccepted", bodies, crlf(kBodies), ""},
      {"BodiesEmptyFile", bodies, "", "L1009", error, 0, 0},
      {"BodiesOnlyComments", bodies, "! nothing here\n\n# nor here\n", "L1009", error, 0, 0},
      {.name = "BodiesTenMegabyteLine",
       .reader = bodies,
       .text = edit(kBodies, " DISKx      1  color  BLEUx  byrd= 0.1000000D+00",
                    to_column_180(" DISKx      1  color  BLEUx  byrd= 0.1000000D+00")),
       .code = "L1010",
       .severity = warning,
       .line = 9,
       .column = 181,
       .long_line = 9},
      {"BodiesPolygonCutShort", bodies,
       "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00\n$nodty\n"
       " NO3xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n$tacty\n"
       " POLYG      1  color  BLEUx  nb_vertex=      4\n"
       "                             coo1= 0.1000000D+01  coo2= 0.0000000D+00\n",
       "L1006", error, 9, 70, 2},
      // A polygon announcing 4 vertices with one given: the '$$$$$$' line ends it (LMGC90 would read
      // it, '$bdyty' and ' RBDY2 2' as vertices); the next body reads normally.
      {"BodiesPolygonSwallowsEndOfBlock", bodies,
       "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00\n$nodty\n"
       " NO3xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n$tacty\n"
       " POLYG      1  color  BLEUx  nb_vertex=      4\n"
       "                             coo1= 0.1000000D+01  coo2= 0.0000000D+00\n$$$$$$\n" +
           kBodies.substr(kBodies.find("$bdyty")),
       "L1013", error, 10, 1},
      // The same guard for the faces of a polyhedron (RBDY3 POLYR announcing 2 faces, one given).
      {"BodiesPolyhedronFacesCutByEndOfBlock", bodies,
       "$bdyty\n RBDY3      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00\n$nodty\n"
       " NO6xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
       "                             coo4= 0.0000000D+00  coo5= 0.0000000D+00  coo6= 0.0000000D+00\n$tacty\n"
       " POLYR      1  color  BLEUx  nb_vertex=      3    nb_faces=      2\n"
       "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
       "                             coo1= 0.1000000D+01  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
       "                             coo1= 0.0000000D+00  coo2= 0.1000000D+01  coo3= 0.0000000D+00\n"
       "                             ver1=      1         ver2=      2         ver3=      3\n"
       "$$$$$$\n",
       "L1013", error, 14, 1},

      // ---- BULK_BEHAV.DAT
      {"BulkBehavUnknownLaw", bulk_behav, edit(kBulkBehav, "PLEXx  RIGID ", "PLEXx  RIGIX "), "L1001", error,
       5, 9},
      {"BulkBehavMalformedDensity", bulk_behav,
       edit(kBulkBehav, "Umas= 0.1000000D+04", "Umas= 0.10000O0D+04"), "L1002", error, 5, 46},
      {"BulkBehavGravityOutOfRange", bulk_behav,
       edit(kBulkBehav, "grv2=-0.9810000D+01", "grv2=-0.981000D+999"), "L1003", error, 2, 46},
      {"BulkBehavTruncatedLaw", bulk_behav, kBulkBehav.substr(0, kBulkBehav.find(" PLEXx")), "L1006", error,
       4, 14},
      {"BulkBehavMissingGravy", bulk_behav, kBulkBehav.substr(kBulkBehav.find("$behav")), "L1012", error, 6,
       1},

      // ---- TACT_BEHAV.DAT
      {"TactBehavUnknownLaw", tact_behav, edit(kTactBehav, "RST_CLB", "RST_CLX"), "L1001", error, 3, 9},
      {"TactBehavTruncatedLaw", tact_behav, kTactBehav.substr(0, kTactBehav.find("\n      ") + 1), "L1006",
       error, 3, 81},
      {"TactBehavMalformedAlert", tact_behav, edit(kTactBehav, "0.1000000D-01", "0.10000OOD-01"), "L1002",
       error, 8, 55},
      {"TactBehavMissingSeetyTitle", tact_behav,
       edit(kTactBehav, " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n", ""), "L1012", error,
       7, 2},
      // A value followed by digits up to 10 MB: the L1011 message quotes the value only up to column 180.
      {.name = "TactBehavTenMegabyteValue",
       .reader = tact_behav,
       .text = kTactBehav,
       .code = "L1010",
       .severity = warning,
       .line = 3,
       .column = 181,
       .count = 2,
       .long_line = 3,
       .long_fill = '7'},
      {"TactBehavCrlfAccepted", tact_behav, crlf(kTactBehav), ""},
      {"TactBehavTabInAlert", tact_behav, edit(kTactBehav, "WALLx       0.1", "WALLx      \t0.1"), "L1007",
       warning, 8, 55},

      // ---- MODELS.DAT
      {"ModelsTruncatedAfterModel", models, "$model  mdlty\n", "L1006", error, 1, 14},
      {"ModelsMalformedFieldSize", models,
       edit(kModels, "                        3\n", "                        x\n"), "L1004", error, 5, 61},
      {"ModelsTabInFieldSize", models,
       edit(kModels, "                        3\n", "                     \t  3\n"), "L1007", warning, 5, 62},
      {"ModelsNonAscii", models, edit(kModels, "large", "l\xC3\xA0rge"), "L1008", error, 4, 31},
      {"ModelsUnknownModelType", models, edit(kModels, "MECAx  Q4xxx", "MECAy  Q4xxx"), "L1001", error, 3, 9},
      {"ModelsUnknownElement", models, edit(kModels, "MECAx  Q4xxx", "MECAx  Q5xxx"), "L1001", error, 3, 16},

      // ---- DRV_DOF.DAT
      {"DrvDofTruncatedBlock", drv_dof, kDrvDof.substr(0, kDrvDof.rfind("$$$$$$")), "L1005", error, 9, 104},
      {"DrvDofMissingEndBetweenBlocks", drv_dof,
       edit(kDrvDof, "$$$$$$\n", "") + kDrvDof.substr(kDrvDof.find("$bdyty")), "L1005", error, 10, 1},
      // LMGC90 stops at the unknown line (its dof list ends there, then 'nodty vlocx unknown'); the
      // valid dof line after it is read on, not reported as a second unknown keyword.
      {"DrvDofUnknownDofKeyword", drv_dof, edit(kDrvDof, " vlocy      2", " vlocx      2"), "L1001", error, 8,
       2},
      {"DrvDofMalformedParameter", drv_dof, edit(kDrvDof, "1  0.0000000D+00", "1  0.0000000D+OO"), "L1002",
       error, 7, 15},
      {"DrvDofDofOutOfRange", drv_dof, edit(kDrvDof, " vlocy      3", " vlocy      4"), "L1003", error, 9, 9},
      // The dof number written in column 8, outside columns 9-13: LMGC90 reads dof 0.
      {"DrvDofNumberOutsideItsColumns", drv_dof, edit(kDrvDof, " vlocy      3", " vlocy 3     "), "L1011",
       warning, 9, 8},
      {"DrvDofParameterOverflow", drv_dof, edit(kDrvDof, "1  0.0000000D+00", "1  0.100000D+999"), "L1003",
       error, 7, 15},
      {"DrvDofCrlfAccepted", drv_dof, crlf(kDrvDof), ""},
      {"DrvDofParameterShiftedRight", drv_dof, edit(kDrvDof, "1  0.0000000D+00  ", "1   0.0000000D+00 "),
       "L1011", warning, 7, 15},

      // ---- evolution files
      {"EvolutionMalformedTime", evolution, edit(kEvolution, "0.1000000D+01", "0.1O00000D+01"), "L1002",
       error, 2, 1},
      {"EvolutionValueOutOfRange", evolution, edit(kEvolution, "0.5000000D+00\n", "0.5000000D+999\n"),
       "L1003", error, 2, 15},
      {"EvolutionMissingValue", evolution, edit(kEvolution, " 0.5000000D+00\n0.2", "\n0.2"), "L1015", error,
       2, 14},
      {"EvolutionEmptyFile", evolution, "", "L1009", error, 0, 0},
      {.name = "EvolutionTenMegabyteLine",
       .reader = evolution,
       .text = edit(kEvolution, "0.2000000D+01 0.5000000D+00", to_column_180("0.2000000D+01 0.5000000D+00")),
       .code = "L1010",
       .severity = warning,
       .line = 3,
       .column = 181,
       .long_line = 3},

      // ---- PTPT3_NETWORK.DAT
      {"Ptpt3NetworkAccepted", ptpt3_network, kPtpt3Network, ""},
      {"Ptpt3NetworkRealPoint", ptpt3_network, edit(kPtpt3Network, " 4 2 ", " 4.0 2 "), "L1004", error, 2, 2},
      {"Ptpt3NetworkMalformedLength", ptpt3_network,
       edit(kPtpt3Network, "1 0.1000000D+01", "1 0.1O00000D+01"), "L1002", error, 2, 12},
      {"Ptpt3NetworkMissingLength", ptpt3_network, edit(kPtpt3Network, " 1 0.1000000D+01\n", " 1\n"), "L1015",
       error, 2, 11},
      {"Ptpt3NetworkTrailingText", ptpt3_network,
       edit(kPtpt3Network, " 0.1000000D+01\n 4", " 0.1000000D+01 x\n 4"), "L1019", warning, 1, 26},
      {"Ptpt3NetworkEmptyFileIsNoLink", ptpt3_network, "", ""},

      // ---- DOF.INI
      {"DofTruncatedBlock", dof, kDof.substr(0, kDof.find("$$$$$$")), "L1005", error, 11, 91},
      {"DofUnknownNodeType", dof, edit(kDof, " NO3xx", " NO7xx"), "L1001", error, 10, 2},
      {"DofMissingSteps", dof, edit(kDof, "$steps        0              time= 0.1000000D+01\n", ""), "L1012",
       error, 6, 1},
      {"DofMalformedVelocity", dof, edit(kDof, "-0.9810000D+01", "-0.98l0000D+01"), "L1002", error, 11, 56},
      {"DofMissingEndBetweenBlocks", dof, edit(kDof, "$$$$$$\n", "") + kDof.substr(kDof.find("$bdyty")),
       "L1005", error, 14, 1},
      {"DofTimeShiftedRight", dof, edit(kDof, "time= 0.1000000D+01", "time=  0.1000000D+01"), "L1011",
       warning, 4, 35},

      // ---- Vloc_Rloc.INI
      {"VlocRlocUnknownModule", vloc_rloc, edit(kVlocRloc, "DKDKx", "DKDKz"), "L1001", error, 7, 9},
      {"VlocRlocNumberOverflow", vloc_rloc, edit(kVlocRloc, "DKDKx      642", "DKDKx  9999999999"), "L1003",
       error, 7, 16},
      {"VlocRlocTruncatedBlock", vloc_rloc,
       kVlocRloc.substr(0, kVlocRloc.find("                             rlt")), "L1006", error, 9, 77},
      {"VlocRlocMissingSteps", vloc_rloc,
       edit(kVlocRloc, "$steps      300              time= 0.6000000D-01\n", ""), "L1012", error, 6, 2},
      // "stïck" keeps the 5 columns of "stick" (65-69): the byte 0xC3 is in column 67.
      {"VlocRlocNonAsciiStatus", vloc_rloc, edit(kVlocRloc, "stick", "st\xC3\xAFk"), "L1008", error, 9, 67},
      {"VlocRlocMalformedReaction", vloc_rloc, edit(kVlocRloc, "0.1146651D+00", "0.11466S1D+00"), "L1002",
       error, 10, 56},

      // ---- GPV.INI
      {"GpvTruncatedBlock", gpv, kGpv.substr(0, kGpv.find("$$$$$$")), "L1005", error, 14, 43},
      {"GpvUnknownElement", gpv, edit(kGpv, " Q4xxx", " Q5xxx"), "L1001", error, 10, 2},
      {"GpvMalformedValue", gpv, edit(kGpv, "-0.3637979D-11", "-0.36379x9D-11"), "L1002", error, 14, 15},
      {"GpvCrlfAccepted", gpv, crlf(kGpv), ""},
      {.name = "GpvTenMegabyteLine",
       .reader = gpv,
       .text = edit(kGpv, " 0.2930000D+03\n", to_column_180(" 0.2930000D+03") + "\n"),
       .code = "L1010",
       .severity = warning,
       .line = 13,
       .column = 181,
       .long_line = 13},
      {"GpvTabInValue", gpv, edit(kGpv, " 0.2930000D+03", "\t0.2930000D+03"), "L1007", warning, 13, 1},
      {"GpvMissingEndBetweenBlocks", gpv, edit(kGpv, "$$$$$$\n", "") + kGpv.substr(kGpv.find("$bdyty")),
       "L1005", error, 16, 1},

      // ---- POSTPRO.DAT
      {"PostproUnknownCommand", postpro, edit(kPostpro, "SOLVER INFORMATIONS", "SOLVER INFORMATION "),
       "L1001", error, 7, 1},
      // LMGC90 stops at an unknown command: its STEP and argument lines are skipped, not reported.
      {"PostproUnknownCommandWithArguments", postpro, edit(kPostpro, "BODY TRACKING ", "BODY TRAKING  "),
       "L1001", error, 2, 1},
      {"PostproMissingEnd", postpro, kPostpro.substr(0, kPostpro.find("END")), "L1012", error, 8, 32},
      // LMGC90 reads columns 1-7 of the I7 line, i.e. body 1025000.
      {"PostproBodyNumberSpillsOutOfI7", postpro, edit(kPostpro, "1025    ", "10250000"), "L1011", warning, 6,
       1},
      // A list-directed body-node-body-node line (line 12) whose last item overflows 32 bits.
      {"PostproListedIntegerOverflow", postpro,
       edit(kPostpro, "END", "NEW DIST SETS\nSTEP 1\n1\n1, 2 3 99999999999\nEND"), "L1003", error, 12, 8},
      {.name = "PostproTenMegabyteLine",
       .reader = postpro,
       .text = edit(kPostpro, "54                            :", to_column_180("54")),
       .code = "L1010",
       .severity = warning,
       .line = 5,
       .column = 181,
       .long_line = 5},

      // ---- COMMAND.DAT (CHIC ignores unknown lines: a warning, not an error)
      {"CommandUnknownKeyword", command, edit(kCommand, "INCREMENT STEP", "INCRMENT STEP "), "L1019", warning,
       8, 1},
      {"CommandMalformedReal", command, edit(kCommand, "1.D-03 ", "1.D-O3 "), "L1002", error, 4, 1},
      {"CommandIntegerOverflow", command, edit(kCommand, "10          ", "99999999999 "), "L1003", error, 10,
       1},
      {"CommandMissingEndOfProgram", command, kCommand.substr(0, kCommand.find("FIN DU PROGRAMME")), "L1012",
       error, 13, 32},
      {"CommandCrlfAccepted", command, crlf(kCommand), ""},
      {"CommandEmptyFile", command, "", "L1009", error, 0, 0},
      {.name = "CommandTenMegabyteLine",
       .reader = command,
       .text = edit(kCommand, "COMPUTE BOX                   :", to_column_180("COMPUTE BOX")),
       .code = "L1010",
       .severity = warning,
       .line = 5,
       .column = 181,
       .long_line = 5},

      // ---- case folders (load_case)
      {"CaseMissingBodiesFile", case_folder, "DATBOX/BODIES.DAT", "L9001", error, 0, 0},
      {"CaseWithoutDatbox", case_folder, "DATBOX", "L9002", error, 0, 0},
  };
}

// Vloc_Rloc.INI at DOF.INI's step and time, with no interaction.
const std::string kNoInteraction =
    "! Vloc_Rloc\n$steps        0              time= 0.1000000D+01\n" + kDashes;

// A scratch case folder holding the bases above, without `without` (a path in the case folder;
// nothing when empty). Built from the bases, not copied from reference_cases/, so that the
// fixtures do not change when the default case does.
fs::path write_case(const std::string& name, const std::string& without) {
  const fs::path dir = scratch_dir(name);
  fs::create_directories(dir / "DATBOX");
  const std::pair<const char*, const std::string*> files[] = {{"BODIES.DAT", &kBodies},
                                                              {"BULK_BEHAV.DAT", &kBulkBehav},
                                                              {"TACT_BEHAV.DAT", &kTactBehav},
                                                              {"DRV_DOF.DAT", &kDrvDof},
                                                              {"DOF.INI", &kDof},
                                                              {"Vloc_Rloc.INI", &kNoInteraction}};
  for (const auto& [file, text] : files) std::ofstream(dir / "DATBOX" / file, std::ios::binary) << *text;
  if (!without.empty()) fs::remove_all(dir / without);
  return dir;
}

std::vector<grammar::Diagnostic> read_fixture(const Fixture& f) {
  DiagnosticSink sink;
  const SourceText source("FILE", f.long_line ? lengthen_line(f.text, f.long_line, f.long_fill) : f.text);
  switch (f.reader) {
    case Reader::bodies:
      grammar::parse_bodies(source, sink);
      break;
    case Reader::bulk_behav:
      grammar::parse_bulk_behav(source, sink);
      break;
    case Reader::tact_behav:
      grammar::parse_tact_behav(source, sink);
      break;
    case Reader::models:
      grammar::parse_models(source, sink);
      break;
    case Reader::drv_dof:
      grammar::parse_drv_dof(source, sink);
      break;
    case Reader::evolution:
      grammar::parse_evolution(source, sink);
      break;
    case Reader::ptpt3_network:
      grammar::parse_ptpt3_network(source, sink);
      break;
    case Reader::dof:
      grammar::parse_dof(source, sink);
      break;
    case Reader::vloc_rloc:
      grammar::parse_vloc_rloc(source, sink);
      break;
    case Reader::gpv:
      grammar::parse_gpv(source, sink);
      break;
    case Reader::postpro:
      grammar::parse_postpro(source, sink, 2);
      break;
    case Reader::command:
      grammar::parse_command(source, sink);
      break;
    case Reader::case_folder:
      case_folder::load_case(write_case("broken_file_fixtures_" + f.name, f.text), sink);
      break;
  }
  return sink.items();
}

std::string describe(const std::vector<grammar::Diagnostic>& items) {
  std::string out;
  for (const auto& d : items)
    out += "  " + std::to_string(d.where.span.line) + ":" + std::to_string(d.where.span.column) + ": " +
           std::string(grammar::severity_name(d.severity)) + "[" + d.code + "]: " + d.message + "\n";
  return out.empty() ? "  (no diagnostic)\n" : out;
}

class BrokenFile : public testing::TestWithParam<Fixture> {};

TEST_P(BrokenFile, GivesTheExactDiagnostic) {
  const Fixture& f = GetParam();
  ASSERT_EQ(f.text.find(kEditFailed), std::string::npos) << "the fixture's edit did not apply";
  const std::vector<grammar::Diagnostic> items = read_fixture(f);
  SCOPED_TRACE("diagnostics:\n" + describe(items));
  if (f.code.empty()) {
    EXPECT_TRUE(items.empty());
    return;
  }
  // One comparison of "severity[code] line:column, count" so a failure reads in one line.
  const auto summary = [](Severity severity, const std::string& code, std::uint32_t line,
                          std::uint32_t column, std::size_t count) {
    return std::string(grammar::severity_name(severity)) + "[" + code + "] " + std::to_string(line) + ":" +
           std::to_string(column) + ", " + std::to_string(count) + " diagnostic(s)";
  };
  ASSERT_FALSE(items.empty());
  for (const grammar::Diagnostic& d : items)
    EXPECT_LE(d.message.size(), 1000u) << "a diagnostic is one short line";
  const grammar::Diagnostic& first = items[0];
  EXPECT_EQ(summary(first.severity, first.code, first.where.span.line, first.where.span.column, items.size()),
            summary(f.severity, f.code, f.line, f.column, f.count));
}

const auto kFixtureName = [](const testing::TestParamInfo<Fixture>& info) { return info.param.name; };
INSTANTIATE_TEST_SUITE_P(Fixtures, BrokenFile, testing::ValuesIn(fixtures()), kFixtureName);

// The bases read without any diagnostic, so a fixture's diagnostic is due to its breakage.
TEST(BrokenFileBases, BaseFilesAreClean) {
  const std::vector<std::pair<Reader, std::string>> bases = {
      {Reader::bodies, kBodies},   {Reader::bulk_behav, kBulkBehav}, {Reader::tact_behav, kTactBehav},
      {Reader::models, kModels},   {Reader::drv_dof, kDrvDof},       {Reader::evolution, kEvolution},
      {Reader::dof, kDof},         {Reader::vloc_rloc, kVlocRloc},   {Reader::gpv, kGpv},
      {Reader::postpro, kPostpro}, {Reader::command, kCommand}};
  for (const auto& [reader, text] : bases) {
    const std::vector<grammar::Diagnostic> items = read_fixture(Fixture{"base", reader, text, ""});
    EXPECT_TRUE(items.empty()) << text.substr(0, 40) << "\n" << describe(items);
  }
  DiagnosticSink sink;
  EXPECT_TRUE(case_folder::load_case(write_case("broken_file_fixtures_base", ""), sink).has_value());
  EXPECT_TRUE(sink.items().empty()) << describe(sink.items());
}

}  // namespace
}  // namespace lmgc::test
