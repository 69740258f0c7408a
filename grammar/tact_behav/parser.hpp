#pragma once
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/tact_behav/ast.hpp"

namespace lmgc::grammar {

// Reads TACT_BEHAV.DAT as LMGC90 does (docs/lmgc90-facts/contact-laws.md §1.1-1.2, datbox-inputs.md §3):
// one pass for `$behav` cards, an independent pass for `$seety` blocks. Continuation lines are
// the next significant lines whatever they hold (a `$behav` line can be swallowed as data, as
// LMGC90 does). Never throws.
TactBehavFile parse_tact_behav(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
