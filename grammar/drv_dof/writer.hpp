#pragma once
#include <string>

#include "grammar/drv_dof/ast.hpp"

namespace lmgc::grammar {

// What LMGC90's DRV_DOF.OUT echo depends on beyond DRV_DOF.DAT: which modules of the run write
// a section (docs/lmgc90-facts/datbox-inputs.md §5 "Echo DRV_DOF.OUT"). A 2D run always has the RBDY2 module
// (it writes its dashed line even with no driven body), a 3D run the RBDY3 module (no dashed
// line); each MAILx module that holds bodies writes its driven bodies and a dashed line.
struct DrvDofEchoSetup {
  int dimension = 2;        // 2: RBDY2 module, 3: RBDY3 module
  bool meca_mailx = false;  // the run has mecaMAILx bodies
  bool ther_mailx = false;  // the run has therMAILx bodies
  bool poro_mailx = false;  // the run has poroMAILx bodies
  // LMGC90 writes a MAILx node type from the mesh (`NO2xx` in 2D, `NO3xx` in 3D), not from
  // DRV_DOF.DAT (a thermal `NO1xx` is echoed `NO2xx` in 2D). When true the echo does the same.
  bool node_type_from_mesh = false;
};

// The setup that DRV_DOF.DAT alone implies: dimension from the rigid bodies (RBDY3 → 3) or else
// from mechanical MAILx node types (NO3xx → 3), MAILx modules present where the file drives them,
// node types as written in the file.
DrvDofEchoSetup drv_dof_echo_setup_of(const DrvDofFile& file);

// DRV_DOF.OUT as LMGC90 echoes it: header, then per module the bodies with driven dofs sorted by
// rank, their nodes sorted by number, their dofs sorted by dof number (vlocy/temp before
// force/flux), the evolution-file lines as `(1X,A5,2X,I5,1X,'evolution',1X,A40)`.
std::string write_drv_dof(const DrvDofFile& file, const DrvDofEchoSetup& setup);
std::string write_drv_dof(const DrvDofFile& file);  // with drv_dof_echo_setup_of(file)

// Canonical evolution layout (lmgc's own; LMGC90's list-directed output depends on the compiler):
// one pair per line, each value as 1X followed by a 24-column `±d.ddddddddddddddddE±ddd`
// (17 significant digits, so every double reads back exactly; blank sign for positives).
std::string write_evolution(const EvolutionFile& file);

}  // namespace lmgc::grammar
