#pragma once
#include <string>

#include "grammar/vloc_rloc/ast.hpp"

namespace lmgc::grammar {

// Vloc_Rloc in LMGC90's layout: the common 6-line header, then each interaction block as its
// module writes it (interaction_catalogue.hpp, the xxl variant when `xxl` is set): '$icdan' line,
// title, data line, vector lines, '#' names line and internal variables, a one-blank line.
// docs/lmgc90-facts/state-and-outputs.md §1.2, §1.4.
std::string write_vloc_rloc(const VlocRlocFile& file);

// The header shared by LMGC90's state files (DOF, Vloc_Rloc, GPV), state-and-outputs.md §1.2.
void append_state_header(std::string& out, std::string_view title_line, std::string_view third_line,
                         std::int64_t step, double time);

}  // namespace lmgc::grammar
