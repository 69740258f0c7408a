#pragma once
// The contactor pairs of LMGC90, in one table: the candidate and antagonist contactors a '$seety'
// row names, the interaction module (its keyword in Vloc_Rloc files, whose layout is in
// grammar/vloc_rloc/interaction_catalogue.hpp) and the dimension; and the names BODIES.DAT
// contactors go by in '$seety' rows (DISKb is a DISKx, ...). lmgc-check's visibility checks and the
// solver's pair families read them here. docs/lmgc90-facts/contact-laws.md §1.2,
// state-and-outputs.md §1.4.1-1.4.2.
#include <span>
#include <string_view>

namespace lmgc::grammar {

struct ContactorPair {
  std::string_view candidate, antagonist;  // as '$seety' rows name them
  std::string_view interaction;            // the module: DKDKx, SPSPx, ...
  int dimension;
  // The '$icdan' type of its Vloc_Rloc blocks when LMGC90 writes another than the module's name
  // (mod_CSASp writes CSASx); empty: the module's.
  std::string_view vloc_rloc_other = {};
  std::string_view vloc_rloc_type() const { return vloc_rloc_other.empty() ? interaction : vloc_rloc_other; }
};

std::span<const ContactorPair> contactor_pairs();

// The pair a (candidate, antagonist) of '$seety' names forms, or nullptr.
const ContactorPair* find_contactor_pair(std::string_view candidate, std::string_view antagonist);
// The pair of an interaction module, or nullptr.
const ContactorPair* find_interaction_pair(std::string_view interaction);

// The name a BODIES.DAT contactor type goes by in '$seety' rows: DISKb is DISKx, SPHEb is SPHER,
// POLYF is POLYR, PT2TL is PT2DL, MAILx surfaces CSxxx and ASpxx; the others their own.
std::string_view see_name(std::string_view contactor_type);

}  // namespace lmgc::grammar
