#pragma once
// Builds a rigid 2D Scene from the checked ASTs of a case (BODIES, TACT_BEHAV, DRV_DOF, DOF.INI,
// evolution files) and the bulk data it needs (densities, gravity).
#include <map>
#include <string>
#include <vector>

#include "grammar/bodies/ast.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/dof/ast.hpp"
#include "grammar/drv_dof/ast.hpp"
#include "grammar/tact_behav/ast.hpp"
#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

struct SceneInput2D {
  const grammar::BodiesFile* bodies = nullptr;
  const grammar::TactBehavFile* tact_behav = nullptr;
  const grammar::DrvDofFile* drv_dof = nullptr;  // may be null
  const grammar::DofFile* dof_ini = nullptr;     // may be null
  const std::map<std::string, grammar::EvolutionFile>* evolutions = nullptr;
  std::map<std::string, double> densities;  // bulk behaviour nickname -> Umas [kg/m²]
  Eigen::Vector2d gravity = Eigen::Vector2d(0.0, -9.81);
  std::string bodies_path, tact_behav_path, drv_dof_path;  // for diagnostics
};

// The RBDY2 contactor kinds the rigid 2D scene is built with; any other is reported (L4001) and the
// case refused. docs/support.md is generated from this and the catalogues.
bool runs_contactor_2d(std::string_view type);

// Returns false (with diagnostics) when the case uses something the rigid 2D solver does not
// provide (a law it does not solve, a contactor of another dimension, ...).
bool build_scene_2d(const SceneInput2D& input, Scene2D& scene, grammar::DiagnosticSink& sink);

// The contact law of a TACT_BEHAV.DAT card, if the 2D solver provides it.
bool contact_law_of(const grammar::TactLaw& card, ContactLaw& law);

}  // namespace lmgc::solver
