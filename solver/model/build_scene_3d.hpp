#pragma once
// Builds a rigid 3D Scene from the checked ASTs of a case (BODIES, TACT_BEHAV, DRV_DOF, DOF.INI,
// evolution files) and the bulk data it needs (densities, gravity). docs/lmgc90-facts/numerics.md §1.2.
#include <map>
#include <string>

#include "grammar/bodies/ast.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/dof/ast.hpp"
#include "grammar/drv_dof/ast.hpp"
#include "grammar/tact_behav/ast.hpp"
#include "solver/bodies/rigid_3d_properties.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

struct SceneInput3D {
  const grammar::BodiesFile* bodies = nullptr;
  const grammar::TactBehavFile* tact_behav = nullptr;
  const grammar::DrvDofFile* drv_dof = nullptr;  // may be null
  const grammar::DofFile* dof_ini = nullptr;     // may be null
  const std::map<std::string, grammar::EvolutionFile>* evolutions = nullptr;
  std::map<std::string, double> densities;  // bulk behaviour nickname -> Umas [kg/m³]
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  std::string bodies_path, tact_behav_path, drv_dof_path;
};

// The geometry of one RBDY3 contactor as BODIES.DAT gives it (SPHER, SPHEb, PLANx, POLYR; other
// types keep only their type), for the mass-property computation and the BODIES.OUT echo.
Rigid3DContactorShape rigid_3d_shape(const grammar::Contactor& contactor);

// The RBDY3 contactor kinds the rigid 3D scene is built with; any other is reported (L4001) and the
// case refused.
bool runs_contactor_3d(std::string_view type);

// Returns false (with diagnostics) when the case uses something the rigid 3D solver does not
// provide yet (a contactor other than SPHER/SPHEb/PLANx/POLYR, a law it does not solve).
bool build_scene_3d(const SceneInput3D& input, Scene3D& scene, grammar::DiagnosticSink& sink);

}  // namespace lmgc::solver
