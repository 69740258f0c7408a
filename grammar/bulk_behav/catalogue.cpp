#include "grammar/bulk_behav/catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using V = std::string_view;
constexpr V kNone[] = {""};
constexpr V kElas[] = {"ELAS"};
constexpr V kElasCplt[] = {"ELAS", "CPLT"};
constexpr V kElasVisco[] = {"ELAS", "VISCO"};
constexpr V kElasPlas[] = {"ELAS", "PLAS"};
constexpr V kThermoElas[] = {"ELAS", "CPLT", "THERM"};
constexpr V kThermoElasVaria[] = {"ELAS", "CPLT", "THERM", "VARIA"};
constexpr V kPoroElas[] = {"ELAS", "THERM", "BIOT"};
constexpr V kUserMat[] = {"UMAT"};
constexpr V kRigidTherm[] = {"RIGID_THERM"};
constexpr V kRigidWs[] = {"WS"};
constexpr V kRigidThermWs[] = {"RIGID_THERM", "WS"};
constexpr V kRigidElec[] = {"RIGID_ELEC"};
constexpr V kRigidThermElecWs[] = {"RIGID_THERM", "RIGID_ELEC", "WS"};
constexpr V kDiscrete[] = {"DISCRETE"};
constexpr V kJoint[] = {"JOINT"};

constexpr std::span<const V> none() { return std::span<const V>(kNone, 0); }

constexpr BulkLawKind kKinds[] = {
    {"RIGID", BulkFirstLine::umas, none(), 0},
    {"MATERIAL_POINT", BulkFirstLine::umas, none(), 0},
    {"THERMO_RIGID", BulkFirstLine::umas, kRigidTherm, 0},
    {"CHEMICAL_RIGID", BulkFirstLine::umas, kRigidWs, 0},
    {"THERMO_CHEMICAL_RIGID", BulkFirstLine::umas, kRigidThermWs, 0},
    {"ELECTRO_RIGID", BulkFirstLine::umas, kRigidElec, 0},
    {"THERMO_ELECTRO_RIGID", BulkFirstLine::umas, kRigidThermElecWs, 0},
    {"ELAS", BulkFirstLine::umas, kElas, 0},
    {"ELAS_DILA", BulkFirstLine::umas, kElasCplt, 0},
    {"VISCO_ELAS", BulkFirstLine::umas, kElasVisco, 0},
    {"ELAS_PLAS", BulkFirstLine::umas, kElasPlas, 0},
    {"THERMO_ELAS", BulkFirstLine::umas, kThermoElas, 0},
    {"THERMO_ELAS_VARIA", BulkFirstLine::umas, kThermoElasVaria, 0},
    {"PORO_ELAS", BulkFirstLine::umas, kPoroElas, 0},
    {"USER_MAT", BulkFirstLine::umas, kUserMat, 0},
    {"DISCRETE", BulkFirstLine::values3, kDiscrete, 0},
    {"JOINT_ELAS", BulkFirstLine::joint3, kJoint, 0},
    {"JOINT_MC", BulkFirstLine::joint3, kJoint, 6},
    {"JOINT_FCZM", BulkFirstLine::joint3, kJoint, 12},
};

}  // namespace

std::span<const BulkLawKind> bulk_law_catalogue() { return kKinds; }

const BulkLawKind* find_bulk_law_kind(std::string_view law_type) {
  auto it = std::find_if(std::begin(kKinds), std::end(kKinds), [&](const BulkLawKind& k) { return k.law_type == law_type; });
  return it == std::end(kKinds) ? nullptr : &*it;
}

}  // namespace lmgc::grammar
