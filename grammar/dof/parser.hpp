#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/dof/ast.hpp"

namespace lmgc::grammar {

// Reads DOF.INI, DOF.OUT.n and DOF.LAST (one format; docs/lmgc90-facts/state-and-outputs.md §1.2-1.3,
// datbox-inputs.md §6). A missing `$steps` header is L1012. Never throws.
DofFile parse_dof(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
