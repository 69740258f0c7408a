#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/gpv/ast.hpp"

namespace lmgc::grammar {

// Reads GPV.INI / .LAST / .OUT.n. Never throws; problems go to `sink`.
GpvFile parse_gpv(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
