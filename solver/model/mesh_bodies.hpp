#pragma once
// The MAILx bodies of a case as linear elastic meshes (solver/fem/linear_body.hpp): elements from
// BODIES.DAT with the finite element of their MODELS.DAT model, materials from the ELAS laws of
// BULK_BEHAV.DAT (Umas, EYng, EPss), lumped or consistent mass from the model's 'mstrg'. What lmgc
// does not run yet (large strain, another material, an anisotropic law, a thermal model, an
// element outside the catalogue) is refused with L4003 at the model's line: never replaced by
// another model. docs/lmgc90-facts/mailx-2d.md §1-§3.
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "solver/fem/linear_body.hpp"

namespace lmgc::solver {

struct MeshBodies {
  std::vector<fem::MeshBody> bodies;
  // The model options that change outputs, per body: MatLib's GPV layout ('isext MatL_').
  std::vector<bool> matlib;
};

// `hypothesis`: SetDimension(2, mhyp)'s (plane strain 1, plane stress 2, axisymmetric 3), or 3D.
bool build_mesh_bodies(const case_folder::CaseFiles& files, fem::Hypothesis hypothesis, MeshBodies& out,
                       grammar::DiagnosticSink& sink);

}  // namespace lmgc::solver
