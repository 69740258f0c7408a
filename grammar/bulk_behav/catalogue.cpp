// The bulk law catalogue. docs/lmgc90-facts/datbox-inputs.md §2; formats and labels are those of LMGC90's
// read_*/write_* sub-block routines of mod_bulk_behav (file-format facts, not code).
#include "grammar/bulk_behav/catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using L = BulkValueLayout;
using C = BulkOptionCase;
using S = BulkStep;
using K = BulkBlockKind;

// --- value lines ---------------------------------------------------------------------------
constexpr L kElasIsotropic[] = {{{"EYng=", "EPss="}, 2, true}};
constexpr L kViscoIsotropic[] = {{{"EYng=", "EPss="}, 2, false}};
constexpr L kOrthotropic[] = {
    {{"EY11=", "EY22=", "EY33="}, 3}, {{"EP12=", "EP13=", "EP23="}, 3}, {{"G12_=", "G13_=", "G23_="}, 3}};
// Anisotropic: 7 lines of 3 values, written with blank labels.
constexpr L kAnisotropic[] = {{{"     ", "     ", "     "}, 3}, {{"     ", "     ", "     "}, 3},
                              {{"     ", "     ", "     "}, 3}, {{"     ", "     ", "     "}, 3},
                              {{"     ", "     ", "     "}, 3}, {{"     ", "     ", "     "}, 3},
                              {{"     ", "     ", "     "}, 3}};
constexpr L kDilaIsotropic[] = {{{"Dila="}, 1, true}};
constexpr L kDilaOrthotropic[] = {{{"Dil1=", "Dil2=", "Dil3="}, 3}};
constexpr L kTref[] = {{{"Tref="}, 1}};
constexpr L kTherm[] = {{{"SPHV="}, 1, true}, {{"COCO="}, 1, true}};
constexpr L kVaria[] = {{{"Trth=", "Tith="}, 2}};
constexpr L kSwift[] = {{{"C0__=", "EPS0=", "n___="}, 3}};
constexpr L kIsohLinear[] = {{{"SIG0=", "K___="}, 2}};
constexpr L kHollomon[] = {{{"K___=", "n___="}, 2}};
constexpr L kCinhLinear[] = {{{"K___="}, 1}};
constexpr L kPowerLaw[] = {{{"Sref=", "Dref=", "n___="}, 3}};
constexpr L kThermIso[] = {{{"TCnd="}, 1}};
constexpr L kThermAni[] = {{{"PrTC=", "ScTC="}, 2}, {{"PDnx=", "PDny="}, 2}};
constexpr L kThermTail[] = {{{"Hspe="}, 1}, {{"Eeq_=", "NUeq="}, 2}};
constexpr L kElec[] = {{{"ECnd="}, 1}, {{"Eel_=", "NUel="}, 2}};
constexpr L kLmm05[] = {{{"WS__=", "WSvr="}, 2}, {{"TMlt=", "Tvar="}, 2}};
constexpr L kRen[] = {{{"WSmx=", "WSmn="}, 2}, {{"CtTi="}, 1}};
constexpr L kNhu14[] = {{{"WSmx=", "WSmn="}, 2}, {{"CtTi=", "AcTi="}, 2}};
constexpr L kBiot[] = {{{"BIOT="}, 1, true}};
constexpr L kDiscrete[] = {{{"k1  =", "k2  =", "k3  ="}, 3, false, true},
                           {{"c1  =", "c2  =", "c3  ="}, 3, false, true}};
constexpr L kJointMc[] = {{{"kncc=", "ec  ="}, 2}, {{"ftrc="}, 1}, {{"phi =", "C   =", "zmu ="}, 3}};
constexpr L kJointFczm[] = {{{"kncc=", "ec  ="}, 2},
                            {{"phi =", "zmu ="}, 2},
                            {{"pf  =", "pd  ="}, 2},
                            {{"ct  =", "s2  =", "G2  ="}, 3},
                            {{"cn  =", "s1  =", "G1  ="}, 3}};

// --- option cases --------------------------------------------------------------------------
// Only 'standard' elasticity is implemented; the other names are read, then LMGC90 stops.
constexpr C kElasModels[] = {{"standard"},
                             {"MooneyRivlin", {}, false, false},
                             {"HartSmith", {}, false, false},
                             {"Signorini", {}, false, false}};
constexpr C kElasAnisotropy[] = {
    {"isotropic", kElasIsotropic}, {"orthotropic", kOrthotropic}, {"anisotropic", kAnisotropic}};
constexpr C kViscoAnisotropy[] = {
    {"isotropic", kViscoIsotropic}, {"orthotropic", kOrthotropic}, {"anisotropic", kAnisotropic}};
constexpr C kDilatation[] = {{"isotropic", kDilaIsotropic}, {"orthotropic", kDilaOrthotropic}};
constexpr C kCriterion[] = {{"none", {}, true}, {"Von-Mises"}};
constexpr C kIsotropicHardening[] = {
    {"none"}, {"Swift", kSwift}, {"linear", kIsohLinear}, {"Hollomon", kHollomon}};
constexpr C kKinematicHardening[] = {{"none"}, {"linear", kCinhLinear}};
constexpr C kViscoPlasticity[] = {{"none"}, {"power_law", kPowerLaw}};
constexpr C kViscoModels[] = {{"none"}, {"KelvinVoigt"}};
constexpr C kThermModels[] = {{"iso", kThermIso}, {"ani", kThermAni}};
constexpr C kWsLaws[] = {{"LMM05", kLmm05}, {"REN12", kRen}, {"REN13", kRen}, {"NHU14", kNhu14}};

// --- sub-blocks ----------------------------------------------------------------------------
constexpr S kElasSteps[] = {
    {BulkStepKind::option, "elas:", "elas:", 47, 59, BulkOptionStyle::labelled13, kElasModels},
    {BulkStepKind::option, "ani_:", "ani_:", 47, 59, BulkOptionStyle::labelled13, kElasAnisotropy}};
constexpr S kCpltSteps[] = {
    {BulkStepKind::marker, "cplt:", "cplt"},
    {BulkStepKind::anisotropy_values, "", "", 0, 0, BulkOptionStyle::labelled13, kDilatation},
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kTref}};
constexpr S kThermSteps[] = {{BulkStepKind::marker, "ther:", "ther"},
                             {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kTherm}};
constexpr S kVariaSteps[] = {{BulkStepKind::marker, "varf:", "varf"},
                             {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kVaria}};
// PLAS labels are not checked by LMGC90 (only the words at 47-59 are).
constexpr S kPlasSteps[] = {
    {BulkStepKind::option, "crit:", "", 47, 59, BulkOptionStyle::labelled13, kCriterion},
    {BulkStepKind::option, "isoh:", "", 47, 59, BulkOptionStyle::labelled13, kIsotropicHardening},
    {BulkStepKind::option, "cinh:", "", 47, 59, BulkOptionStyle::labelled13, kKinematicHardening},
    {BulkStepKind::option, "vpla:", "", 47, 59, BulkOptionStyle::labelled13, kViscoPlasticity}};
constexpr S kViscoSteps[] = {
    {BulkStepKind::option, "visc:", "visc:", 47, 59, BulkOptionStyle::labelled13, kViscoModels},
    {BulkStepKind::option, "ani_:", "ani_:", 47, 59, BulkOptionStyle::labelled13, kViscoAnisotropy}};
constexpr S kRigidThermSteps[] = {
    {BulkStepKind::option, "", "", 41, 43, BulkOptionStyle::colon3, kThermModels},
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kThermTail}};
constexpr S kRigidElecSteps[] = {
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kElec}};
constexpr S kWsSteps[] = {{BulkStepKind::option, "WSlw=", "", 47, 51, BulkOptionStyle::labelled5, kWsLaws}};
constexpr S kUmatSteps[] = {{BulkStepKind::file_name}};
constexpr S kBiotSteps[] = {{BulkStepKind::marker, "cpl_:", "cpl_"},
                            {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kBiot}};
constexpr S kDiscreteSteps[] = {
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kDiscrete}};
constexpr S kJointMcSteps[] = {
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kJointMc}};
constexpr S kJointFczmSteps[] = {
    {BulkStepKind::values, "", "", 0, 0, BulkOptionStyle::labelled13, {}, kJointFczm}};

// Indexed by BulkBlockKind.
constexpr BulkBlockInfo kBlocks[] = {
    {K::elas, "ELAS", kElasSteps, true},
    {K::cplt, "CPLT", kCpltSteps, true},
    {K::therm, "THERM", kThermSteps, true},
    {K::varia, "VARIA", kVariaSteps, true},
    {K::plas, "PLAS", kPlasSteps, true},
    {K::visco, "VISCO", kViscoSteps, true},
    {K::rigid_therm, "RIGID_THERM", kRigidThermSteps, false},
    {K::rigid_elec, "RIGID_ELEC", kRigidElecSteps, false},
    {K::ws, "WS", kWsSteps, true},
    {K::umat, "UMAT", kUmatSteps, false},
    {K::biot, "BIOT", kBiotSteps, true},
    {K::discrete, "DISCRETE", kDiscreteSteps, false},
    {K::joint_mc, "JOINT_MC", kJointMcSteps, false},
    {K::joint_fczm, "JOINT_FCZM", kJointFczmSteps, false},
};

// --- law types (datbox-inputs.md §2 table) -------------------------------------------------
constexpr K kElasOnly[] = {K::elas};
constexpr K kElasDila[] = {K::elas, K::cplt};
constexpr K kViscoElas[] = {K::elas, K::visco};
constexpr K kElasPlas[] = {K::elas, K::plas};
constexpr K kThermoElas[] = {K::elas, K::cplt, K::therm};
constexpr K kThermoElasVaria[] = {K::elas, K::cplt, K::therm, K::varia};
constexpr K kPoroElas[] = {K::elas, K::therm, K::biot};
constexpr K kUserMat[] = {K::umat};
constexpr K kThermoRigid[] = {K::rigid_therm};
constexpr K kChemicalRigid[] = {K::ws};
constexpr K kThermoChemicalRigid[] = {K::rigid_therm, K::ws};
constexpr K kElectroRigid[] = {K::rigid_elec};
constexpr K kThermoElectroRigid[] = {K::rigid_therm, K::rigid_elec, K::ws};
constexpr K kDiscreteBlocks[] = {K::discrete};
constexpr K kJointMcBlocks[] = {K::joint_mc};
constexpr K kJointFczmBlocks[] = {K::joint_fczm};

constexpr L kNoValues{};
constexpr L kMasses{{"m1  =", "m2  =", "m3  ="}, 3, false, true};
constexpr L kJointFirst{{"kt  =", "knc =", "knt ="}, 3};

constexpr BulkLawKind kKinds[] = {
    {"RIGID", BulkFirstLine::umas, kNoValues, {}},
    {"MATERIAL_POINT", BulkFirstLine::umas, kNoValues, {}},
    {"THERMO_RIGID", BulkFirstLine::umas, kNoValues, kThermoRigid},
    {"CHEMICAL_RIGID", BulkFirstLine::umas, kNoValues, kChemicalRigid},
    {"THERMO_CHEMICAL_RIGID", BulkFirstLine::umas, kNoValues, kThermoChemicalRigid},
    {"ELECTRO_RIGID", BulkFirstLine::umas, kNoValues, kElectroRigid},
    {"THERMO_ELECTRO_RIGID", BulkFirstLine::umas, kNoValues, kThermoElectroRigid},
    {"ELAS", BulkFirstLine::umas, kNoValues, kElasOnly},
    {"ELAS_DILA", BulkFirstLine::umas, kNoValues, kElasDila},
    {"VISCO_ELAS", BulkFirstLine::umas, kNoValues, kViscoElas},
    {"ELAS_PLAS", BulkFirstLine::umas, kNoValues, kElasPlas},
    {"THERMO_ELAS", BulkFirstLine::umas, kNoValues, kThermoElas},
    {"THERMO_ELAS_VARIA", BulkFirstLine::umas, kNoValues, kThermoElasVaria},
    {"PORO_ELAS", BulkFirstLine::umas, kNoValues, kPoroElas},
    {"USER_MAT", BulkFirstLine::umas, kNoValues, kUserMat},
    {"DISCRETE", BulkFirstLine::values, kMasses, kDiscreteBlocks},
    {"JOINT_ELAS", BulkFirstLine::values, kJointFirst, {}},
    {"JOINT_MC", BulkFirstLine::values, kJointFirst, kJointMcBlocks},
    {"JOINT_FCZM", BulkFirstLine::values, kJointFirst, kJointFczmBlocks},
};

}  // namespace

std::span<const BulkLawKind> bulk_law_catalogue() {
  return kKinds;
}

const BulkLawKind* find_bulk_law_kind(std::string_view law_type) {
  auto it = std::find_if(std::begin(kKinds), std::end(kKinds),
                         [&](const BulkLawKind& k) { return k.law_type == law_type; });
  return it == std::end(kKinds) ? nullptr : &*it;
}

const BulkBlockInfo& bulk_block_info(BulkBlockKind kind) {
  return kBlocks[static_cast<std::size_t>(kind)];
}

}  // namespace lmgc::grammar
