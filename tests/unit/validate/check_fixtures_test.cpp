// Semantic-check fixtures: each row breaks one thing in a valid case folder and names the exact
// diagnostic validate::check_case must give for it (code, severity, file, line, column). The
// bases are the shipped default case reference_cases/disk_bounce_rst (a disk above a JONCx wall)
// and two small cases written here: three RBDY3 bodies (two spheres above a PLANx floor) and one
// MAILx body of two Q4xxx elements. BaseCasesAreClean checks that every base gives no diagnostic
// at all, so each diagnostic below comes from its row's mutation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/diagnostic_catalogue.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"
#include "validate/checks.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;
using grammar::Severity;

enum class Base { disk, spheres, mailx };

// ---- the two bases written here (the disk base is copied from reference_cases/) ---------------

const std::string kDofHeader =
    "! DOF\n$steps      0                time= 0.0000000D+00\n!" + std::string(71, '-') + "\n";
const std::string kVlocHeader =
    "! Vloc_Rloc\n$steps      0                time= 0.0000000D+00\n!" + std::string(71, '-') + "\n";
const std::string kGpvHeader =
    "! GPV\n$steps      0                time= 0.0000000D+00\n!" + std::string(71, '-') + "\n";
const std::string kDofty =
    "$dofty  numbr "
    "[CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]...*...[RAMPI.....+.....RAMP.*.time]\n";
std::string fixed_dof(int dof) {
  return " vlocy      " + std::to_string(dof) +
         "  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.0000000D+00  0.1000000D+01  0.0000000D+00\n";
}

// Two spheres (radius 0.1, centres 0.5 above the floor's top face) and a PLANx floor, in 3D.
std::string rbdy3(int number, const char* behav, const char* z, const char* x, const std::string& contactor) {
  return std::string("$bdyty\n RBDY3      ") + std::to_string(number) + "\n$blmty\n PLAIN      1  behav  " +
         behav + "  avrd= 0.0000000D+00\n$nodty\n NO6xx      1                coo1=" + x +
         "  coo2= 0.0000000D+00  coo3=" + z +
         "\n                             coo4= 0.0000000D+00  coo5= 0.0000000D+00  coo6= "
         "0.0000000D+00\n$tacty\n" +
         contactor + "\n$$$$$$\n";
}
const std::string kSphereBodies = rbdy3(1, "PLEXx", " 0.5000000D+00", " 0.0000000D+00",
                                        " SPHER      1  color  BLEUx  byrd= 0.1000000D+00") +  // 1-10
                                  rbdy3(2, "PLEXx", " 0.5000000D+00", " 0.5000000D+00",
                                        " SPHER      1  color  BLEUx  byrd= 0.1000000D+00") +  // 11-20
                                  rbdy3(3, "TDURx", "-0.5000000D-01", " 0.0000000D+00",
                                        " PLANx      1  color  VERTx  axe1= 0.1000000D+01  axe2= "
                                        "0.1000000D+01  axe3= 0.5000000D-01");  // 21-30
const std::string kSphereBulk =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2= 0.0000000D+00  grv3=-0.9810000D+01\n"
    "\n"
    "$behav  lawty\n"
    " PLEXx  RIGID                           Umas= 0.2500000D+04\n"  // line 5
    "\n"
    "$behav  lawty\n"
    " TDURx  RIGID                           Umas= 0.2500000D+04\n";
const std::string kSeeTitle = " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n";
const std::string kSphereTact =
    "$behav  lawty\n"
    " iqsc0  IQS_CLB                         fric= 0.3000000D+00\n"  // line 2
    "\n"
    "$seety\n" +
    kSeeTitle +
    " RBDY3  SPHER  BLEUx  iqsc0  RBDY3  SPHER  BLEUx       0.1000000D-01\n"  // line 6
    "\n"
    "$seety\n" +
    kSeeTitle + " RBDY3  SPHER  BLEUx  iqsc0  RBDY3  PLANx  VERTx       0.1000000D-01\n";  // line 10
const std::string kSphereDrv = "$bdyty\n RBDY3      3\n$nodty\n NO6xx      1\n" + kDofty + fixed_dof(1) +
                               fixed_dof(2) + fixed_dof(3) + fixed_dof(4) + fixed_dof(5) + fixed_dof(6) +
                               "$$$$$$\n";
// One MAILx body: two Q4xxx elements on nodes 1-6 (a 2 x 1 rectangle), a CLxxx and an ALpxx.
const std::string kMailxBodies =
    "$bdyty\n"
    " MAILx      1\n"
    "$blmty\n"
    " Q4xxx      1  nodes      1      2      5      4\n"  // line 4
    "               model  M2D_L  behav  stone\n"         // line 5
    " Q4xxx      2  nodes      2      3      6      5\n"
    "               model  M2D_L  behav  stone\n"
    "$nodty\n"
    " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n"  // line 9
    " NO2xx      2                coo1= 0.1000000D+01  coo2= 0.0000000D+00\n"
    " NO2xx      3                coo1= 0.2000000D+01  coo2= 0.0000000D+00\n"
    " NO2xx      4                coo1= 0.0000000D+00  coo2= 0.1000000D+01\n"
    " NO2xx      5                coo1= 0.1000000D+01  coo2= 0.1000000D+01\n"
    " NO2xx      6                coo1= 0.2000000D+01  coo2= 0.1000000D+01\n"
    "$tacty\n"
    " CLxxx      1  color  REDxx  noda=    4  nodb=    5  apab= 0.5000000D+00\n"  // line 16
    " ALpxx      1  color  BLUEx  noda=    3  nodb=    2\n"
    "$$$$$$\n";
const std::string kMailxModels =
    "$model  mdlty  finel  eleop  value\n"
    " M2D_L\n"
    "        MECAx  Q4xxx  isext  no___\n"  // line 3
    "                      kine_  small\n"  // line 4
    "                      mstrg  lump_\n";
const std::string kMailxBulk =
    "$gravy\n"
    "                   grv1= 0.0000000D+00  grv2=-0.9810000D+01  grv3= 0.0000000D+00\n"
    "\n"
    "$behav  lawty\n"
    " stone  ELAS                            Umas= 0.2300000D+04\n"  // line 5
    "                                        elas: standard\n"
    "                                        ani_: isotropic\n"
    "                                        EYng= 0.1600000D+11  EPss= 0.3000000D+00\n";  // line 8
const std::string kMailxTact =
    "$behav  lawty\n"
    " gapc0  GAP_SGR_CLB                     fric= 0.3000000D+00\n"
    "\n"
    "$seety\n" +
    kSeeTitle + " MAILx  CLxxx  REDxx  gapc0  MAILx  ALpxx  BLUEx       0.5000000D-01\n";  // line 6
const std::string kMailxDrv = "$bdyty\n MAILx      1\n$models\n MECAx\n$nodty\n NO2xx      1\n" + kDofty +
                              fixed_dof(1) + fixed_dof(2) + "$$$$$$\n";
const std::string kMailxPostpro =
    "NEW MECAx SETS                :\n"
    "STEP 1                        :\n"
    "      1\n"
    "      1\n"
    "      1       2\n"  // line 5
    "      1\n"
    "      3\n"  // line 7
    "END                           :\n";

// The text of a file of the default case.
std::string read_reference(const std::string& file) {
  return read_file(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "disk_bounce_rst" / "DATBOX" / file);
}

// A case folder with the files of a base.
fs::path write_base(Base base, const std::string& name) {
  const fs::path dir = scratch_dir("check_fixtures/" + name);
  const fs::path datbox = dir / "DATBOX";
  if (base == Base::disk) {
    fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "disk_bounce_rst" / "DATBOX", datbox,
             fs::copy_options::recursive);
    return dir;
  }
  fs::create_directories(datbox);
  auto put = [&](const char* file, const std::string& text) {
    std::ofstream(datbox / file, std::ios::binary) << text;
  };
  if (base == Base::spheres) {
    put("BODIES.DAT", kSphereBodies);
    put("BULK_BEHAV.DAT", kSphereBulk);
    put("TACT_BEHAV.DAT", kSphereTact);
    put("DRV_DOF.DAT", kSphereDrv);
    put("DOF.INI", kDofHeader);
    put("Vloc_Rloc.INI", kVlocHeader);
    put("COMMAND.DAT", read_reference("COMMAND.DAT"));
  } else {
    put("BODIES.DAT", kMailxBodies);
    put("MODELS.DAT", kMailxModels);
    put("BULK_BEHAV.DAT", kMailxBulk);
    put("TACT_BEHAV.DAT", kMailxTact);
    put("DRV_DOF.DAT", kMailxDrv);
    put("DOF.INI", kDofHeader);
    put("Vloc_Rloc.INI", kVlocHeader);
    put("GPV.INI", kGpvHeader);
    put("POSTPRO.DAT", kMailxPostpro);
  }
  return dir;
}

// ---- rows --------------------------------------------------------------------------------------

// One text edit of a DATBOX file: the first `from` becomes `to`. `from` empty: the file is
// written as `to` (created). `from` == kRemove: the file (or folder, "" = DATBOX/) is removed.
constexpr const char* kRemove = "<remove>";
struct Edit {
  std::string file, from, to;
};

struct Row {
  std::string name;
  Base base;
  std::vector<Edit> edits;
  std::string file;  // expected file name in DATBOX/ ("" for a diagnostic about the folder)
  std::string code;
  Severity severity;
  std::uint32_t line, column;  // 0, 0: the whole file
  // Applied to the loaded case before the checks, for what the readers do not let through.
  std::function<void(case_folder::CaseFiles&)> ast_edit = {};
};

void PrintTo(const Row& row, std::ostream* out) {
  *out << row.name;
}

// A value line of a law card: value at columns 46-59 (and 67-80).
const std::string kLawLine2 = "                                        ";

// What an edit fails with: it matches no expectation, so a stale edit shows as a failure.
constexpr const char* kEditFailed = "<edit failed: text not found>";

// `text` with the first `from` replaced by `to`.
std::string edit_text(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) return kEditFailed;
  return text.replace(at, from.size(), to);
}

// A law card replaced by another, on the default case's law line(s).
const std::string kRst08 =
    " rst08  RST_CLB                         rstn= 0.8000000D+00  rstt= 0.0000000D+00\n" + kLawLine2 +
    "fric= 0.0000000D+00\n";
const std::string kMac =
    " rst08  MAC_CZM                         dfrc= 0.3000000D+00  sfrc= 0.3000000D+00\n" + kLawLine2 +
    "cn  = 0.1000000D+10  ct  = 0.1000000D+10\n" + kLawLine2 + "visc= 0.0000000D+00  dupr= 0.1000000D+01\n";
const std::string kRepell =
    " rst08  ELASTIC_REPELL_CLB              F/gp= 0.1000000D+11\n" + kLawLine2 + "fric= 0.3000000D+00\n";

// A third disk beside the first (overlapping it) and the row that lets disks touch.
const std::string kThirdDisk =
    "$bdyty\n RBDY2      3\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00  gyrd= "
    "0.7071068D-01\n$nodty\n"
    " NO3xx      1                coo1= 0.1500000D+00  coo2= 0.1100000D+01  coo3= 0.0000000D+00\n$tacty\n"
    " DISKx      1  color  BLEUx  byrd= 0.1000000D+00\n$$$$$$\n";
const std::string kDiskDiskRow =
    "$seety\n" + kSeeTitle + " RBDY2  DISKx  BLEUx  rst08  RBDY2  DISKx  BLEUx       0.1000000D-01\n";
// An RBDY2 body appended to the 3D case.
const std::string kPlanarBody =
    "$bdyty\n RBDY2      1\n$blmty\n PLAIN      1  behav  PLEXx  avrd= 0.1000000D+00\n$nodty\n"
    " NO3xx      1                coo1= 0.5000000D+01\n$tacty\n DISKx      1  color  BLEUx  byrd= "
    "0.1000000D+00\n$$$$$$\n";
// An initial DKJCx interaction between the disk and the wall (lines 4-11 after the header).
const std::string kInteraction =
    "$icdan  DKJCx      1\n"
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj\n"
    " RBDY2      1  DISKx      1  rst08  RBDY2      2  JONCx      1  noctc      0\n"  // line 6
    "                             rlt/H 0.0000000D+00  rln/H 0.0000000D+00  rls/H 0.0000000D+00\n"
    "                             vlt = 0.0000000D+00  vln = 0.0000000D+00  vls = 0.0000000D+00\n"
    "                             gapTT 0.1000000D+01\n"
    "                             n(1)= 0.0000000D+00  n(2)= 0.1000000D+01  n(3)= 0.0000000D+00\n"
    "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n";
// Gauss points of element 3 of the MAILx body (lines 4-10 after the header).
const std::string kGaussPoints = "$bdyty\n MAILx      1\n$blmty\n Q4xxx      3\n$model\n MECAx\n$$$$$$\n";
// A DOF.INI block for RBDY2 9 (lines 4-9 after the header).
const std::string kNinthBodyState =
    "$bdyty\n RBDY2      9\n$nodty\n"
    " NO3xx      1                X(1)= 0.0000000D+00  X(2)= 0.0000000D+00  X(3)= 0.0000000D+00\n"
    "                             V(1)= 0.0000000D+00  V(2)= 0.0000000D+00  V(3)= 0.0000000D+00\n$$$$$$\n";
const std::string kElasBlock =
    "                                        elas: standard\n"
    "                                        ani_: isotropic\n"
    "                                        EYng= 0.1600000D+11  EPss= 0.3000000D+00\n";
const std::string kClockwiseTriangle =
    " POLYG      1  color  BLEUx  nb_vertex=      3\n"
    "                             coo1= 0.0000000D+00  coo2= 0.1000000D+00\n"
    "                             coo1= 0.1000000D+00  coo2= 0.0000000D+00\n"
    "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00\n";
// A tetrahedron surface with its fourth face missing, in place of the first sphere.
const std::string kOpenTetrahedron =
    " POLYR      1  color  BLEUx  nb_vertex=      4    nb_faces=      3\n"
    "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
    "                             coo1= 0.1000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"
    "                             coo1= 0.0000000D+00  coo2= 0.1000000D+00  coo3= 0.0000000D+00\n"
    "                             coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.1000000D+00\n"
    "                             ver1=      1         ver2=      3         ver3=      2\n"
    "                             ver1=      1         ver2=      2         ver3=      4\n"
    "                             ver1=      1         ver2=      4         ver3=      3\n";
const std::string kFirstSphere =
    " SPHER      1  color  BLEUx  byrd= 0.1000000D+00\n$$$$$$\n$bdyty\n RBDY3      2";

// The evolution reader reports a time that does not increase (L2016) and drops its point, so the
// check sees it only in an AST made otherwise (a script); this row swaps two loaded times.
void swap_evolution_times(case_folder::CaseFiles& files) {
  for (auto& [name, evolution] : files.evolutions)
    if (evolution.points.size() >= 3)
      std::swap(evolution.points[1].time.value, evolution.points[2].time.value);
}

// The TACT_BEHAV.DAT reader reports two rows giving different laws to one pair (L2015); the
// check covers an AST made otherwise: this row adds the second row (swapped sides, law 'iqsc0',
// line 13) to the loaded AST.
void add_conflicting_row(case_folder::CaseFiles& files) {
  grammar::SeeEntry row = files.tact_behav->sees.front();
  std::swap(row.candidate_body, row.antagonist_body);
  std::swap(row.candidate_contactor, row.antagonist_contactor);
  std::swap(row.candidate_colour, row.antagonist_colour);
  row.law_nickname = grammar::Word{"iqsc0", grammar::make_span(13, 23, 27)};
  files.tact_behav->sees.push_back(row);
}

std::vector<Row> rows() {
  using enum Base;
  const Severity error = Severity::error, warning = Severity::warning, note = Severity::note;
  const std::string evolution = " vlocy      2 evolution vy.dat\n";
  // clang-format off
  return {
    // ---- L2xxx: references and consistency
    {"BehaviourOfRigidBodyUndefined", disk, {{"BODIES.DAT", "behav  PLEXx", "behav  PLEXy"}}, "BODIES.DAT", "L2001", error, 5, 23},
    {"BehaviourOfElementUndefined", mailx, {{"BODIES.DAT", "behav  stone", "behav  stane"}}, "BODIES.DAT", "L2001", error, 5, 37},
    {"LawOfVisibilityRowUndefined", disk, {{"TACT_BEHAV.DAT", "rst08  RBDY2", "rst09  RBDY2"}}, "TACT_BEHAV.DAT", "L2002", error, 8, 23},
    {"DrivenBodyMissing", disk, {{"DRV_DOF.DAT", " RBDY2      2", " RBDY2      3"}}, "DRV_DOF.DAT", "L2003", error, 3, 9},
    {"TrackedBodyMissing", disk, {{"POSTPRO.DAT", "1                             :\nSOLVER", "7                             :\nSOLVER"}}, "POSTPRO.DAT", "L2003", error, 5, 1},
    {"InitialStateOfMissingBody", disk, {{"DOF.INI", "", kDofHeader + kNinthBodyState}}, "DOF.INI", "L2003", error, 5, 9},
    {"GaussPointsOfMissingBody", mailx, {{"GPV.INI", "", kGpvHeader + edit_text(kGaussPoints, " MAILx      1", " MAILx      2")}}, "GPV.INI", "L2003", error, 5, 7},
    {"ModelOfElementUndefined", mailx, {{"BODIES.DAT", "model  M2D_L", "model  M2D_X"}}, "BODIES.DAT", "L2004", error, 5, 23},
    {"ElementNamesMissingNode", mailx, {{"BODIES.DAT", "5      4\n", "5      9\n"}}, "BODIES.DAT", "L2005", error, 4, 42},
    {"ContactorNamesMissingNode", mailx, {{"BODIES.DAT", "noda=    3", "noda=   13"}}, "BODIES.DAT", "L2005", error, 17, 35},
    {"DrivenNodeMissing", mailx, {{"DRV_DOF.DAT", " NO2xx      1", " NO2xx      9"}}, "DRV_DOF.DAT", "L2006", error, 6, 7},
    {"GaussPointsOfMissingElement", mailx, {{"GPV.INI", "", kGpvHeader + kGaussPoints}}, "GPV.INI", "L2006", error, 7, 7},
    {"MecaSetNamesMissingNode", mailx, {{"POSTPRO.DAT", "      3\nEND", "      8\nEND"}}, "POSTPRO.DAT", "L2006", error, 7, 1},
    {"InteractionNamesMissingContactor", disk, {{"Vloc_Rloc.INI", "", kVlocHeader + edit_text(kInteraction, "DISKx      1", "DISKx      2")}}, "Vloc_Rloc.INI", "L2007", warning, 6, 23},
    {"InteractionNamesMissingBody", disk, {{"Vloc_Rloc.INI", "", kVlocHeader + edit_text(kInteraction, "RBDY2      2", "RBDY2      5")}}, "Vloc_Rloc.INI", "L2007", warning, 6, 44},
    {"InteractionNamesContactorOfAnotherType", disk, {{"Vloc_Rloc.INI", "", kVlocHeader + edit_text(kInteraction, "RBDY2      2", "RBDY2      1")}}, "Vloc_Rloc.INI", "L2007", warning, 6, 51},
    {"DrivenDofMissing", mailx, {{"DRV_DOF.DAT", " NO2xx      1", " NO3xx      1"}, {"DRV_DOF.DAT", " vlocy      2", " vlocy      3"}}, "DRV_DOF.DAT", "L2008", error, 9, 9},
    {"ElementOfAnotherShapeThanItsModel", mailx, {{"MODELS.DAT", "MECAx  Q4xxx", "MECAx  T3xxx"}}, "BODIES.DAT", "L2009", error, 5, 23},
    {"RowNeverMatches", disk, {{"TACT_BEHAV.DAT", "JONCx  WALLx", "JONCx  WALLy"}}, "TACT_BEHAV.DAT", "L2010", warning, 8, 37},
    {"ContactorsInNoRow", disk, {{"TACT_BEHAV.DAT", "JONCx  WALLx", "JONCx  WALLy"}}, "BODIES.DAT", "L2011", note, 0, 0},
    {"LawDefinedTwice", disk, {{"TACT_BEHAV.DAT", "\n$seety", "\n$behav  lawty\n rst08  IQS_CLB                         fric= 0.3000000D+00\n$seety"}}, "TACT_BEHAV.DAT", "L2012", warning, 7, 2},
    {"BulkBehaviourDefinedTwice", disk, {{"BULK_BEHAV.DAT", " TDURx  RIGID", " PLEXx  RIGID"}}, "BULK_BEHAV.DAT", "L2012", warning, 8, 2},
    {"ModelDefinedTwice", mailx, {{"MODELS.DAT", "", kMailxModels + kMailxModels}}, "MODELS.DAT", "L2012", warning, 7, 2},
    {"InitialStateGivenTwice", disk, {{"DOF.INI", "", kDofHeader + edit_text(kNinthBodyState, "RBDY2      9", "RBDY2      1") + edit_text(kNinthBodyState, "RBDY2      9", "RBDY2      1")}}, "DOF.INI", "L2012", warning, 11, 9},
    {"DofDrivenTwice", disk, {{"DRV_DOF.DAT", " vlocy      3", " vlocy      2"}}, "DRV_DOF.DAT", "L2012", warning, 9, 2},
    {"RigidBodyOfTheOtherDimension", spheres, {{"BODIES.DAT", "", kSphereBodies + kPlanarBody}}, "BODIES.DAT", "L2013", error, 32, 2},
    {"MeshNodeOfTheOtherDimension", mailx, {{"BODIES.DAT", " NO2xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00\n", " NO3xx      1                coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n"}}, "BODIES.DAT", "L2013", error, 10, 2},
    {"PairInTheWrongOrder", disk, {{"TACT_BEHAV.DAT", "DISKx  BLEUx  rst08  RBDY2  JONCx  WALLx", "JONCx  WALLx  rst08  RBDY2  DISKx  BLEUx"}}, "TACT_BEHAV.DAT", "L2014", warning, 8, 9},
    {"ConflictingRows", disk, {{"TACT_BEHAV.DAT", "\n$seety", "\n$behav  lawty\n iqsc0  IQS_CLB                         fric= 0.3000000D+00\n$seety"}}, "TACT_BEHAV.DAT", "L2015", error, 13, 23, add_conflicting_row},
    {"EvolutionGoesBackInTime", disk, {{"DRV_DOF.DAT", fixed_dof(2), evolution}, {"vy.dat", "", "0.0 0.0\n1.0 -1.0\n2.0 -1.0\n"}}, "vy.dat", "L2016", error, 3, 1, swap_evolution_times},
    {"BodyWrittenWithAnotherNumber", disk, {{"BODIES.DAT", " RBDY2      2", " RBDY2      5"}}, "BODIES.DAT", "L2017", note, 12, 9},
    {"GapCohesiveLawOnDiskAndWall", disk, {{"TACT_BEHAV.DAT", kRst08, kMac}}, "TACT_BEHAV.DAT", "L2018", error, 9, 23},
    {"LawWithoutThisDimension", disk, {{"TACT_BEHAV.DAT", kRst08, edit_text(kMac, "MAC_CZM       ", "MAC_CZM_nosldt") + kLawLine2 + "dt__= 0.1000000D+01\n"}}, "TACT_BEHAV.DAT", "L2018", error, 10, 23},
    {"GapCohesiveLawOnSpheres", spheres, {{"TACT_BEHAV.DAT", " iqsc0  IQS_CLB                         fric= 0.3000000D+00\n", edit_text(kMac, "rst08", "iqsc0")}}, "TACT_BEHAV.DAT", "L2018", error, 8, 23},
    {"NetworkNamesMissingPoint", spheres, {{"PTPT3_NETWORK.DAT", "", " 1 2 0 0 0 0.5\n"}}, "PTPT3_NETWORK.DAT", "L2021", error, 1, 2},
    {"NetworkLinksPointsOfOneBody", spheres, {{"BODIES.DAT", "0.1000000D+00\n$$$$$$\n$bdyty\n RBDY3      2", "0.1000000D+00\n" " PT3Dx      2  color  BLEUx  coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n" " PT3Dx      3  color  BLEUx  coo1= 0.1000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n$$$$$$\n$bdyty\n RBDY3      2"}, {"PTPT3_NETWORK.DAT", "", " 1 2 0 0 0 0.5\n"}}, "PTPT3_NETWORK.DAT", "L2022", error, 1, 4},
    {"NetworkLinkWithoutRow", spheres, {{"BODIES.DAT", "0.1000000D+00\n$$$$$$\n$bdyty\n RBDY3      2", "0.1000000D+00\n" " PT3Dx      2  color  BLEUx  coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n" "$$$$$$\n$bdyty\n RBDY3      2"}, {"BODIES.DAT", "0.1000000D+00\n$$$$$$\n$bdyty\n RBDY3      3", "0.1000000D+00\n" " PT3Dx      2  color  BLEUx  coo1= 0.0000000D+00  coo2= 0.0000000D+00  coo3= 0.0000000D+00\n" "$$$$$$\n$bdyty\n RBDY3      3"}, {"PTPT3_NETWORK.DAT", "", " 1 2 0 0 0 0.5\n"}}, "PTPT3_NETWORK.DAT", "L2022", error, 1, 2},
    {"LargeDeformationsInTotalForm", mailx, {{"MODELS.DAT", "kine_  small", "kine_  large\n                      form_  TotaL"}}, "MODELS.DAT", "L2019", error, 5, 30},
    {"UnknownKinematics", mailx, {{"MODELS.DAT", "kine_  small", "kine_  tiny_"}}, "MODELS.DAT", "L2019", error, 4, 30},
    {"ModelWithoutIsext", mailx, {{"MODELS.DAT", "isext  no___", "mstrg  lump_"}}, "MODELS.DAT", "L2019", error, 2, 2},
    {"ThermalModelWithoutFormulation", mailx, {{"MODELS.DAT", "MECAx  Q4xxx", "THERM  Q4xxx"}}, "MODELS.DAT", "L2019", error, 2, 2},
    {"ElementWithRigidBehaviour", mailx, {{"BULK_BEHAV.DAT", "stone  ELAS    ", "stone  RIGID   "}, {"BULK_BEHAV.DAT", kElasBlock, ""}}, "BODIES.DAT", "L2020", error, 5, 37},
    {"PlasticModelWithElasticBehaviour", mailx, {{"MODELS.DAT", "mstrg  lump_", "mstrg  lump_\n                      mater  J2iso"}}, "BODIES.DAT", "L2020", error, 5, 37},
    {"RigidBodyWithoutDensity", disk, {{"BULK_BEHAV.DAT", " TDURx  RIGID                           Umas= 0.1000000D+04", " TDURx  DISCRETE                        m1  = 0.1000000D+01  m2  = 0.1000000D+01\n" + kLawLine2 + "k1  = 0.1000000D+01  k2  = 0.1000000D+01\n" + kLawLine2 + "c1  = 0.1000000D+01  c2  = 0.1000000D+01"}}, "BODIES.DAT", "L2020", error, 14, 23},

    // ---- L3xxx: physical sanity
    {"NegativeRadius", disk, {{"BODIES.DAT", "byrd= 0.1000000D+00", "byrd=-0.1000000D+00"}}, "BODIES.DAT", "L3001", error, 9, 35},
    {"ZeroWallThickness", disk, {{"BODIES.DAT", "ax2 = 0.5000000D-01", "ax2 = 0.0000000D+00"}}, "BODIES.DAT", "L3001", error, 18, 56},
    {"NegativeEquivalentRadius", disk, {{"BODIES.DAT", "avrd= 0.1000000D+00  gyrd= 0.7", "avrd=-0.1000000D+00  gyrd= 0.7"}}, "BODIES.DAT", "L3001", error, 5, 35},
    {"SphereTooLargeForItsInertia", spheres, {{"BODIES.DAT", "byrd= 0.1000000D+00", "byrd= 0.1000000D+99"}}, "BODIES.DAT", "L1003", error, 9, 35},
    {"ZeroSphereRadius", spheres, {{"BODIES.DAT", "byrd= 0.1000000D+00", "byrd= 0.0000000D+00"}}, "BODIES.DAT", "L3001", error, 9, 35},
    {"ZeroDensityOfRigidBody", disk, {{"BULK_BEHAV.DAT", "Umas= 0.1000000D+04", "Umas= 0.0000000D+00"}}, "BULK_BEHAV.DAT", "L3002", error, 5, 46},
    {"NegativeDensityOfMesh", mailx, {{"BULK_BEHAV.DAT", "Umas= 0.2300000D+04", "Umas=-0.2300000D+04"}}, "BULK_BEHAV.DAT", "L3002", error, 5, 46},
    {"NegativeYoungModulus", mailx, {{"BULK_BEHAV.DAT", "EYng= 0.1600000D+11", "EYng=-0.1600000D+11"}}, "BULK_BEHAV.DAT", "L3003", error, 8, 46},
    {"NegativePenaltyStiffness", disk, {{"TACT_BEHAV.DAT", kRst08, edit_text(kRepell, "F/gp= 0.1", "F/gp=-0.1")}}, "TACT_BEHAV.DAT", "L3003", error, 3, 46},
    {"IncompressiblePoissonRatio", mailx, {{"BULK_BEHAV.DAT", "EPss= 0.3000000D+00", "EPss= 0.5000000D+00"}}, "BULK_BEHAV.DAT", "L3004", error, 8, 67},
    {"PoissonRatioBelowMinusOne", mailx, {{"BULK_BEHAV.DAT", "EPss= 0.3000000D+00", "EPss=-0.1500000D+01"}}, "BULK_BEHAV.DAT", "L3004", error, 8, 67},
    {"NegativeFriction", disk, {{"TACT_BEHAV.DAT", "fric= 0.0000000D+00", "fric=-0.3000000D+00"}}, "TACT_BEHAV.DAT", "L3005", error, 4, 46},
    {"RestitutionAboveOne", disk, {{"TACT_BEHAV.DAT", "rstn= 0.8000000D+00", "rstn= 0.1200000D+01"}}, "TACT_BEHAV.DAT", "L3006", error, 3, 46},
    {"NegativeTangentialRestitution", disk, {{"TACT_BEHAV.DAT", "rstt= 0.0000000D+00", "rstt=-0.1000000D+00"}}, "TACT_BEHAV.DAT", "L3006", error, 3, 67},
    {"ZeroAlert", disk, {{"TACT_BEHAV.DAT", "0.1000000D-01", "0.0000000D+00"}}, "TACT_BEHAV.DAT", "L3007", error, 8, 55},
    {"NegativeAlert", spheres, {{"TACT_BEHAV.DAT", "0.1000000D-01", "-.1000000D-01"}}, "TACT_BEHAV.DAT", "L3007", error, 6, 55},
    {"AlertLargerThanTheDisk", disk, {{"TACT_BEHAV.DAT", "0.1000000D-01", "0.5000000D+00"}}, "TACT_BEHAV.DAT", "L3008", warning, 8, 55},
    {"ClockwisePolygon", disk, {{"BODIES.DAT", " DISKx      1  color  BLEUx  byrd= 0.1000000D+00\n", kClockwiseTriangle}}, "BODIES.DAT", "L3009", error, 9, 2},
    {"OpenPolyhedron", spheres, {{"BODIES.DAT", kFirstSphere, edit_text(kFirstSphere, " SPHER      1  color  BLEUx  byrd= 0.1000000D+00\n", kOpenTetrahedron)}}, "BODIES.DAT", "L3010", error, 9, 2},
    {"InvertedElement", mailx, {{"BODIES.DAT", "1      2      5      4", "1      4      5      2"}}, "BODIES.DAT", "L3011", error, 4, 2},
    {"DiskSunkIntoTheWall", disk, {{"BODIES.DAT", "coo2= 0.1100000D+01", "coo2= 0.5000000D-01"}}, "BODIES.DAT", "L3012", warning, 9, 2},
    {"TwoDisksOverlapping", disk, {{"BODIES.DAT", "", read_reference("BODIES.DAT") + kThirdDisk}, {"TACT_BEHAV.DAT", "", read_reference("TACT_BEHAV.DAT") + kDiskDiskRow}}, "BODIES.DAT", "L3012", warning, 9, 2},
    {"SpheresOverlapping", spheres, {{"BODIES.DAT", "coo1= 0.5000000D+00", "coo1= 0.1500000D+00"}}, "BODIES.DAT", "L3012", warning, 9, 2},
    {"SphereSunkIntoTheFloor", spheres, {{"BODIES.DAT", "coo3= 0.5000000D+00", "coo3= 0.5000000D-01"}}, "BODIES.DAT", "L3012", warning, 9, 2},
    {"FallTooFastForTheAlert", disk, {{"TACT_BEHAV.DAT", "0.1000000D-01", "0.1000000D-03"}}, "COMMAND.DAT", "L3013", warning, 5, 1},
    {"SphereFallTooFastForTheAlert", spheres, {{"TACT_BEHAV.DAT", "VERTx       0.1000000D-01", "VERTx       0.1000000D-03"}}, "COMMAND.DAT", "L3013", warning, 5, 1},
    {"PenaltySpringNotResolved", disk, {{"TACT_BEHAV.DAT", kRst08, kRepell}}, "COMMAND.DAT", "L3013", warning, 5, 1},
    {"NothingMoves", disk, {{"BULK_BEHAV.DAT", "grv2=-0.9810000D+01", "grv2= 0.0000000D+00"}}, "BULK_BEHAV.DAT", "L3014", warning, 2, 46},
    {"DuplicateElement", mailx, {{"BODIES.DAT", "               model  M2D_L  behav  stone\n$nodty", "               model  M2D_L  behav  stone\n Q4xxx      3  nodes      2      5      4      1\n               model  M2D_L  behav  stone\n$nodty"}}, "BODIES.DAT", "L3017", warning, 8, 2},
    {"CandidatePointOnOneNode", mailx, {{"BODIES.DAT", "noda=    4  nodb=    5", "noda=    4  nodb=    4"}}, "BODIES.DAT", "L3018", error, 16, 47},
    {"CandidatePointOffItsEdge", mailx, {{"BODIES.DAT", "apab= 0.5000000D+00", "apab= 0.1500000D+01"}}, "BODIES.DAT", "L3018", error, 16, 59},
    {"DynamicAboveStaticFriction", disk, {{"TACT_BEHAV.DAT", kRst08, " rst08  IQS_DS_CLB                      dyfr= 0.5000000D+00  stfr= 0.3000000D+00\n"}}, "TACT_BEHAV.DAT", "L3016", warning, 3, 9},

    // ---- L4xxx: what the drivers ask of a run, against what lmgc-solve runs
    {"CommandNotRun", disk, {{"COMMAND.DAT", "COMPUTE MASS                  :\n", "COMPUTE MASS                  :\nGHOST TO INVISIBLE            :\n"}}, "COMMAND.DAT", "L4005", warning, 11, 1},
    {"DampingInsideTheTimeLoop", disk, {{"COMMAND.DAT", "COMPUTE Fext                  :\n", "COMPUTE Fext                  :\nFATAL DAMPING                 :\n"}}, "COMMAND.DAT", "L4005", warning, 15, 1},
    {"ScriptAsksForAnotherDetection", spheres, {{"../command.py", "", "from pylmgc90 import chipy\nchipy.PRPRx_UseNcDetection(1e-3)\n"}}, "command.py", "L4005", warning, 2, 7},
    {"ScriptShrinksCundallFaces", spheres, {{"../command.py", "", "from pylmgc90 import chipy\nchipy.PRPRx_UseCpCundallDetection(100, 0.1)\n"}}, "command.py", "L4005", warning, 2, 7},
    {"ScriptDrivesBodies", disk, {{"../command.py", "", "from pylmgc90 import chipy\nfor k in range(10):\n  chipy.RBDY2_PutBodyValue('Tempe', 1, v)\n"}}, "command.py", "L4005", warning, 3, 9},
    {"DisplayNotWritten", disk, {{"COMMAND.DAT", "COMPUTE MASS                  :\n", "COMPUTE MASS                  :\nDISPLAY TIMES                 :\n"}}, "COMMAND.DAT", "L4006", note, 11, 1},
    {"MultiPhysicsData", disk, {{"MP_DEM.DAT", "", "$model therm\n"}}, "MP_DEM.DAT", "L4007", warning, 0, 0},
    {"ScriptLoadsMultiPhysics", disk, {{"../command.py", "", "from pylmgc90.chipy import *\nReadMpBehaviours(0.)\n"}}, "command.py", "L4007", warning, 2, 1},
    {"UnknownChipyCall", disk, {{"../command.py", "", "from pylmgc90 import chipy\nchipy.RBDY2_Frobnicate(1)\n"}}, "command.py", "L4009", note, 2, 7},
    {"NonPositiveTimeStep", disk, {{"COMMAND.DAT", "1.D-3   ", "0.D0    "}}, "COMMAND.DAT", "L4010", error, 5, 1},
    {"ThetaBelowOneHalf", disk, {{"COMMAND.DAT", "0.5D0 ", "0.3D0 "}}, "COMMAND.DAT", "L4010", error, 7, 1},
    {"RelaxationAboveTwo", disk, {{"COMMAND.DAT", "    1.0D0                     : RELAX", "    5.0D0                     : RELAX"}}, "COMMAND.DAT", "L4010", error, 44, 1},
    {"ThermalBulkLawRunAsRigid", disk, {}, "BULK_BEHAV.DAT", "L4012", note, 5, 9, [](case_folder::CaseFiles& files) { files.bulk_behav->laws.front().law_type.value = "THERMO_RIGID"; }},

    // ---- restarts: the state files of one run, at one step
    {"VlocRlocOfAnotherStep", disk, {{"Vloc_Rloc.INI", "", edit_text(kVlocHeader, "$steps      0                time= 0.0000000D+00", "$steps     20                time= 0.2000000D-01")}}, "Vloc_Rloc.INI", "L1020", error, 2, 9},
    {"GaussPointsOfAnotherStep", mailx, {{"GPV.INI", "", edit_text(kGpvHeader, "$steps      0", "$steps      1")}}, "GPV.INI", "L1020", error, 2, 9},
    {"ExactStateOfAnotherStep", disk, {{"EXACT_STATE.INI", "", "lmgc exact state 1 dimension 2 step 20 time 0x1.47ae147ae147bp-6 bodies 2\n"}}, "EXACT_STATE.INI", "L1020", error, 1, 1},
    {"ExactStateNotWrittenByLmgc", disk, {{"EXACT_STATE.INI", "", "a note\n"}}, "EXACT_STATE.INI", "L1012", error, 0, 0},

    // ---- case loading (validate/case_files.cpp)
    {"FileNotReadByLmgc90", disk, {{"NOTES.TXT", "", "a note\n"}}, "NOTES.TXT", "L1021", note, 0, 0},
    {"EvolutionFileMissing", disk, {{"DRV_DOF.DAT", fixed_dof(2), evolution}}, "DRV_DOF.DAT", "L9001", error, 8, 25},
    {"ModelsFileMissing", mailx, {{"MODELS.DAT", kRemove, ""}}, "MODELS.DAT", "L9001", error, 0, 0},
    {"NoDatbox", disk, {{"", kRemove, ""}}, "", "L9002", error, 0, 0},
  };
  // clang-format on
}

// The case folder of a row: its base with its edits applied. False when an edit did not apply.
bool build_case(const Row& row, fs::path& dir) {
  dir = write_base(row.base, row.name);
  const fs::path datbox = dir / "DATBOX";
  for (const Edit& e : row.edits) {
    const fs::path path = e.file.empty() ? datbox : datbox / e.file;
    if (e.from == kRemove) {
      if (fs::remove_all(path) == 0) return false;
      continue;
    }
    std::string text = e.from.empty() ? e.to : edit_text(read_file(path), e.from, e.to);
    if (text.find(kEditFailed) != std::string::npos) return false;
    std::ofstream(path, std::ios::binary) << text;
  }
  return true;
}

std::vector<grammar::Diagnostic> check(const fs::path& dir,
                                       const std::function<void(case_folder::CaseFiles&)>& ast_edit = {}) {
  grammar::DiagnosticSink sink;
  if (auto files = case_folder::load_case(dir, sink)) {
    if (ast_edit) ast_edit(*files);
    validate::check_case(*files, sink);
  }
  return sink.items();
}

std::string describe(const std::vector<grammar::Diagnostic>& items) {
  std::string out;
  for (const auto& d : items)
    out += "  " + fs::path(d.where.file).filename().string() + ":" + std::to_string(d.where.span.line) + ":" +
           std::to_string(d.where.span.column) + ": " + std::string(grammar::severity_name(d.severity)) +
           "[" + d.code + "]: " + d.message + "\n";
  return out.empty() ? "  (no diagnostic)\n" : out;
}

class CheckFixture : public testing::TestWithParam<Row> {};

TEST_P(CheckFixture, GivesTheExactDiagnostic) {
  const Row& row = GetParam();
  fs::path dir;
  ASSERT_TRUE(build_case(row, dir)) << "an edit of the row did not apply";
  const std::vector<grammar::Diagnostic> items = check(dir, row.ast_edit);
  SCOPED_TRACE("diagnostics:\n" + describe(items));
  // The mutation is well formed: no reader diagnostic unless the row is about reading.
  if (row.code.rfind("L1", 0) != 0 && row.code.rfind("L9", 0) != 0) {
    for (const auto& d : items) {
      EXPECT_NE(d.code.substr(0, 2), "L1") << "the row's files do not read cleanly";
    }
  }
  const auto it = std::find_if(items.begin(), items.end(), [&](const auto& d) { return d.code == row.code; });
  ASSERT_NE(it, items.end()) << "no " << row.code;
  // One comparison of "severity[code] file:line:column" so a failure reads in one line.
  const auto summary = [](Severity severity, const std::string& code, const std::string& file,
                          std::uint32_t line, std::uint32_t column) {
    return std::string(grammar::severity_name(severity)) + "[" + code + "] " + file + ":" +
           std::to_string(line) + ":" + std::to_string(column);
  };
  const std::string file = it->where.file == dir.string() ? "" : fs::path(it->where.file).filename().string();
  EXPECT_EQ(summary(it->severity, it->code, file, it->where.span.line, it->where.span.column),
            summary(row.severity, row.code, row.file, row.line, row.column));
  const grammar::DiagnosticKind* kind = grammar::find_diagnostic_kind(row.code);
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->severity, row.severity) << "the row's severity is the catalogue's";
  EXPECT_FALSE(it->message.empty());
  EXPECT_LE(it->message.size(), 400u) << "a diagnostic is one line";
  EXPECT_NE(it->message.back(), '.') << "no final period";
}

INSTANTIATE_TEST_SUITE_P(Rows, CheckFixture, testing::ValuesIn(rows()),
                         [](const testing::TestParamInfo<Row>& info) { return info.param.name; });

// Each base gives no diagnostic at all: a row's diagnostic is due to its mutation.
TEST(CheckFixtureBases, BaseCasesAreClean) {
  for (Base base : {Base::disk, Base::spheres, Base::mailx}) {
    const std::vector<grammar::Diagnostic> items =
        check(write_base(base, "base" + std::to_string(int(base))));
    EXPECT_TRUE(items.empty()) << "base " << int(base) << "\n" << describe(items);
  }
}

// Every code that validate/ emits has a row, and there are at least 60 rows.
TEST(CheckFixtureRows, EveryCodeOfValidateHasARow) {
  const auto table = rows();
  EXPECT_GE(table.size(), 60u);
  std::set<std::string> covered, names;
  for (const Row& row : table) {
    covered.insert(row.code);
    EXPECT_TRUE(names.insert(row.name).second) << "two rows named " << row.name;
  }
  const std::regex code(R"re("(L[0-9]{4})")re");
  std::set<std::string> emitted;
  for (const auto& entry : fs::directory_iterator(fs::path(LMGC_SOURCE_DIR) / "validate")) {
    if (entry.path().extension() != ".cpp") continue;
    const std::string text = read_file(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), code); it != std::sregex_iterator(); ++it)
      emitted.insert((*it)[1]);
  }
  EXPECT_GE(emitted.size(), 30u);
  for (const std::string& c : emitted)
    EXPECT_TRUE(covered.count(c)) << c << " is emitted by validate/ but has no row";
}

}  // namespace
}  // namespace lmgc::test
