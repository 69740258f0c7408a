#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/models/ast.hpp"

namespace lmgc::grammar {

// Reads MODELS.DAT (docs/lmgc90-facts/datbox-inputs.md §4). Never throws; problems go to `sink`.
ModelsFile parse_models(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
