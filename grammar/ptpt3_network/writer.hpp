#pragma once
#include <string>

#include "grammar/ptpt3_network/ast.hpp"

namespace lmgc::grammar {

// PTPT3_NETWORK.DAT in a layout LMGC90's list-directed read accepts: one record per link, the
// integers as such and the reals with 17 significant digits (parse(write(f)) == f). LMGC90
// writes no such file; pre-processors and scripts do, each in their own layout. In the parameter
// form a link without surf or mass (the parser always sets both) is written with 0.
std::string write_ptpt3_network(const Ptpt3NetworkFile& file);

}  // namespace lmgc::grammar
