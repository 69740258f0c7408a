#pragma once
#include <string>

#include "grammar/gpv/ast.hpp"

namespace lmgc::grammar {

// GPV in LMGC90's layout (mod_MAILx write_out_gpv): header, per body '$bdyty', per element
// '$blmty', per model '$model' and the value lines (9D14.7), '$$$$$$' after a body, and one
// dashed line at the end.
std::string write_gpv(const GpvFile& file);

}  // namespace lmgc::grammar
