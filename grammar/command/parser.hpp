#pragma once
#include "grammar/command/ast.hpp"
#include "grammar/command/expand.hpp"  // compile/expand/run parameters, with the parser as before
#include "grammar/command/writer.hpp"  // write_command, declared here before
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"

namespace lmgc::grammar {

// Reads COMMAND.DAT as LMGC90's CHIC interpreter does (state-and-outputs.md §2.1): columns 1-30
// of each line, leading blanks stripped, keywords by prefix, arguments on the following lines.
// Reports what CHIC stops on (missing FIN DU PROGRAMME / FIN DU FICHIER, APPELLE of a missing
// SUB, a DEPUIS label not found, more than 1000 commands or 50 loops, COMPUTE BOX / COMPUTE MASS
// missing without NO CHECK CHIC COMMAND, malformed arguments) as errors, and lines that match
// no keyword and are no jump target as warnings (L1019): CHIC ignores them.
CommandFile parse_command(const SourceText& source, DiagnosticSink& sink);

}  // namespace lmgc::grammar
