#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/drv_dof/ast.hpp"

namespace lmgc::grammar {

// Reads DRV_DOF.DAT (docs/lmgc90-facts/datbox-inputs.md §5): RBDY2/RBDY3 and MAILx (MECAx, THERM, POROx)
// blocks. Accepts the user's guide `$dofyty` + template line (note L1018). Never throws.
DrvDofFile parse_drv_dof(const SourceText& source, DiagnosticSink& sink);

// Reads an evolution file (docs/lmgc90-facts/datbox-inputs.md §5 "Evolution file"): one list-directed
// `t v` pair per record, at least two pairs, strictly increasing t. Never throws.
EvolutionFile parse_evolution(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
