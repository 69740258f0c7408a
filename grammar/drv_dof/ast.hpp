#pragma once
// DRV_DOF.DAT (driven degrees of freedom) and the evolution files it names.
// docs/lmgc90-facts/datbox-inputs.md §5.
#include <array>
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One dof line: ` vlocy      1  CT AMP OMEGA PHI RAMPI RAMP` or ` force      2 evolution f.DAT`.
// Value: v(t) = (CT + AMP cos(OMEGA t + PHI)) min(1, RAMPI + RAMP t) (spec §5).
struct DrivenDof {
  Word kind;                         // cols 2-6: vlocy, force (mechanical), temp, flux (thermal)
  Integer dof;                       // cols 9-13, 1..number of dofs of the node
  bool uses_evolution = false;       // 'evolution' in cols 15-23
  Word evolution_file;               // cols 25-64, trimmed (only when uses_evolution)
  std::array<Real, 6> parameters{};  // CT AMP OMEGA PHI RAMPI RAMP at 15-28 ... 90-103 (zeros with evolution)
  bool operator==(const DrivenDof&) const = default;
};

// One `$nodty` group: node line and the dofs of its `$dofty` list.
struct DrvDofNode {
  Word node_type;  // cols 2-6: NO3xx (RBDY2), NO6xx (RBDY3), NO1xx..NO3xx (MAILx)
  Integer number;  // rigid: cols 9-13 (must be 1); MAILx: cols 7-13
  std::vector<DrivenDof> dofs;
  bool operator==(const DrvDofNode&) const = default;
};

// One `$bdyty` ... `$$$$$$` block.
struct DrvDofBody {
  Word body_type;  // RBDY2, RBDY3 or MAILx (cols 2-6)
  Integer rank;    // rigid: cols 9-15; MAILx: cols 7-13
  Word model;      // MAILx only: MECAx, THERM or POROx (line after `$model`); empty for rigid bodies
  std::vector<DrvDofNode> nodes;  // rigid bodies: exactly one
  bool operator==(const DrvDofBody&) const = default;
};

struct DrvDofFile {
  std::vector<DrvDofBody> bodies;  // in file order
  bool operator==(const DrvDofFile&) const = default;
};

// An evolution file: list-directed `t v` pairs, one per record, t strictly increasing.
// docs/lmgc90-facts/datbox-inputs.md §5 "Evolution file".
struct EvolutionPoint {
  Real time;
  Real value;
  bool operator==(const EvolutionPoint&) const = default;
};

struct EvolutionFile {
  std::vector<EvolutionPoint> points;  // at least two
  bool operator==(const EvolutionFile&) const = default;
};

}  // namespace lmgc::grammar
