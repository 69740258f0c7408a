#pragma once
#include "grammar/bodies/ast.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::grammar {

// Reads BODIES.DAT (docs/lmgc90-facts/datbox-inputs.md §1). Never throws; problems go to `sink`.
BodiesFile parse_bodies(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
