#pragma once
#include <string>

#include "grammar/models/ast.hpp"

namespace lmgc::grammar {

// MODELS.OUT as LMGC90 writes it (write_models): no header, per model the title line, the
// nickname line, then one line per option (FORMAT(1x,5x,2x,A5,2x,A5,2x,A5,2x,A30)).
std::string write_models(const ModelsFile& file);

}  // namespace lmgc::grammar
