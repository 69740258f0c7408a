// Physical sanity of BULK_BEHAV.DAT and of what loads a case: densities, elastic constants,
// gravity and driven dofs. docs/lmgc90-facts/datbox-inputs.md §2 (laws, ELAS block), §5 (driven dofs).
#include <fmt/format.h>

#include <unordered_map>

#include "validate/case_index.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

using grammar::Location;

// Young's moduli, shear moduli and Poisson ratios of an ELAS block (isotropic: EYng EPss;
// orthotropic: EY11 EY22 EY33 / EP12 EP13 EP23 / G12 G13 G23, datbox-inputs.md §2).
void check_elasticity(const grammar::BulkLaw& law, const std::string& path, grammar::DiagnosticSink& sink) {
  const grammar::BulkBlock* elas = find_bulk_block(law, grammar::BulkBlockKind::elas);
  if (!elas || elas->options.size() < 2) return;
  const std::string& anisotropy = elas->options[1].value;
  auto positive = [&](const grammar::Real& value, std::string_view name) {
    if (!(value.value > 0.0))
      sink.report("L3003", Location{path, value.span},
                  fmt::format("{} of bulk behaviour '{}' is {}; it must be > 0", name, law.nickname.value,
                              value.value));
  };
  if (anisotropy == "isotropic") {
    if (elas->lines.empty() || elas->lines[0].field || elas->lines[0].values.size() < 2) return;
    const grammar::Real& young = elas->lines[0].values[0];
    const grammar::Real& poisson = elas->lines[0].values[1];
    positive(young, "Young's modulus 'EYng'");
    if (!(poisson.value > -1.0 && poisson.value < 0.5))
      sink.report(
          "L3004", Location{path, poisson.span},
          fmt::format("Poisson ratio 'EPss' of bulk behaviour '{}' is {}; an isotropic material needs "
                      "-1 < nu < 0.5",
                      law.nickname.value, poisson.value),
          poisson.value >= 0.5 ? "0.5 is incompressible: the elastic matrix is singular" : "");
  } else if (anisotropy == "orthotropic") {
    constexpr std::string_view kYoung[] = {"EY11", "EY22", "EY33"};
    constexpr std::string_view kShear[] = {"G12", "G13", "G23"};
    if (elas->lines.size() > 0)
      for (std::size_t k = 0; k < 3 && k < elas->lines[0].values.size(); ++k)
        positive(elas->lines[0].values[k], fmt::format("Young's modulus '{}'", kYoung[k]));
    if (elas->lines.size() > 2)
      for (std::size_t k = 0; k < 3 && k < elas->lines[2].values.size(); ++k)
        positive(elas->lines[2].values[k], fmt::format("shear modulus '{}'", kShear[k]));
  }
}

// True when a driven dof imposes something other than zero: an evolution file, or
// (CT + AMP cos(OMEGA t + PHI)) min(1, RAMPI + RAMP t) not identically zero (datbox-inputs.md §5).
bool drives_something(const grammar::DrivenDof& dof) {
  if (dof.uses_evolution) return true;
  const auto& p = dof.parameters;
  return (p[0].value != 0.0 || p[1].value != 0.0) && (p[4].value != 0.0 || p[5].value != 0.0);
}

}  // namespace

void check_materials(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.bulk_behav) return;
  const std::string path = datbox_path(files, "BULK_BEHAV.DAT");
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");

  // The first rigid body using each behaviour: its mass is density x volume (or area in 2D).
  std::unordered_map<std::string, std::pair<const grammar::Body*, std::size_t>> rigid_user;
  if (files.bodies) {
    const BodyIndex index(*files.bodies);
    for (const auto& body : files.bodies->bodies)
      if (body.rigid_bulk)
        rigid_user.emplace(body.rigid_bulk->behav.value, std::make_pair(&body, index.rank_of(body)));
  }
  for (const auto& law : files.bulk_behav->laws) {
    check_elasticity(law, path, sink);
    const grammar::BulkLawKind* kind = grammar::find_bulk_law_kind(law.law_type.value);
    if (law.density_field || !kind || kind->first_line != grammar::BulkFirstLine::umas) continue;
    auto user = rigid_user.find(law.nickname.value);
    if (user != rigid_user.end() && !(law.density.value > 0.0)) {
      const grammar::Body& body = *user->second.first;
      report_related(
          sink, "L3002", Location{path, law.density.span},
          fmt::format("density 'Umas' of bulk behaviour '{}' is {}; {} uses it and a rigid body needs a "
                      "positive mass",
                      law.nickname.value, law.density.value, body_name(body, user->second.second)),
          {{Location{bodies_path, body.rigid_bulk->behav.span}, "used here"}});
    } else if (law.density.value < 0.0) {
      sink.report("L3002", Location{path, law.density.span},
                  fmt::format("density 'Umas' of bulk behaviour '{}' is {}; it must be >= 0",
                              law.nickname.value, law.density.value));
    }
  }

  // Something must set the case in motion: gravity, a driven dof or an initial velocity.
  if (!files.bodies || files.bodies->bodies.empty() || !files.bulk_behav->has_gravity) return;
  const int dimension = case_dimension(files);
  for (int k = 0; k < dimension; ++k)
    if (files.bulk_behav->gravity[static_cast<std::size_t>(k)].value != 0.0) return;
  if (files.drv_dof)
    for (const auto& body : files.drv_dof->bodies)
      for (const auto& node : body.nodes)
        for (const auto& dof : node.dofs)
          if (drives_something(dof)) return;
  if (InitialDisplacements(files).any_velocity) return;
  sink.report(
      "L3014", Location{path, files.bulk_behav->gravity[1].span},
      fmt::format("gravity is zero{}, no driven dof imposes a non-zero value and DOF.INI gives no body a "
                  "velocity: nothing moves in this case",
                  dimension == 2 && files.bulk_behav->gravity[2].value != 0.0
                      ? " in the plane (a 2D case ignores 'grv3')"
                      : ""),
      "set the gravity ('grv2= -0.9810000D+01') or drive a dof");
}

}  // namespace lmgc::validate
