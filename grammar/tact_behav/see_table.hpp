#pragma once
// What LMGC90 does to the `$seety` entries once read (close_see_ll): merge duplicates, then
// sort. The result is the order of LMGC90's `see` array: the order of TACT_BEHAV.OUT and the
// search order of get_isee. docs/lmgc90-facts/contact-laws.md §1.2.
#include <cstddef>
#include <string_view>
#include <vector>

#include "grammar/tact_behav/ast.hpp"

namespace lmgc::grammar {

// LMGC90's integer id of a contactor type name as used in `$seety` (DISKx = 1 ... CSxxx = 17),
// -99 for any other name (mod_parameters.f90 contactor_type).
int see_contactor_id(std::string_view name);

// True when two entries name the same pair (same or swapped candidate/antagonist), compared as
// LMGC90 does: contactor types by id (so two unknown names compare equal), colours and body
// names as 5-character words.
bool same_see_pair(const SeeEntry& a, const SeeEntry& b);

// For each entry, the index of the earlier entry it duplicates (npos when it is the first).
inline constexpr std::size_t kNoDuplicate = static_cast<std::size_t>(-1);
std::vector<std::size_t> see_duplicate_of(const std::vector<SeeEntry>& entries);

// The entries in LMGC90's order: later duplicates removed, then LMGC90's insertion sort on
// (antagonist contactor id, antagonist colour, "candidate == antagonist" first), including its
// use of a stale comparison flag for ties (verified against the 19 reference echoes).
std::vector<SeeEntry> lmgc90_see_order(const std::vector<SeeEntry>& entries);

}  // namespace lmgc::grammar
