#pragma once
// Generated LMGC90 files of a given size, shared by benchmarks and tests.
#include <cstddef>
#include <string>

namespace lmgc::bench {

// BODIES.DAT text with `bodies` RBDY2 bodies: disks and pentagons alternately, on a grid.
std::string generated_bodies_dat(std::size_t bodies);

// Vloc_Rloc.INI text with `interactions` 2D interaction blocks in LMGC90's layout (written by
// grammar::write_vloc_rloc, so the text is canonical). The modules come in LMGC90's writing order,
// each numbered from 1: DKDKx (50 %), DKJCx (10 %), PLJCx (10 %), PLPLx (30 %, in vertex pairs, half
// of the pairs under a cohesive law with 5 named internal variables). Values are deterministic
// pseudo-random numbers of realistic magnitude; body numbers stay below 100 000 (I5 fields).
std::string generated_vloc_rloc_ini(std::size_t interactions);

}  // namespace lmgc::bench
