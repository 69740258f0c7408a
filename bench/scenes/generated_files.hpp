#pragma once
// Generated LMGC90 files of a given size, shared by benchmarks and tests.
#include <cstddef>
#include <string>

namespace lmgc::bench {

// BODIES.DAT text with `bodies` RBDY2 bodies: disks and pentagons alternately, on a grid.
std::string generated_bodies_dat(std::size_t bodies);

}  // namespace lmgc::bench
