#include "grammar/tact_behav/see_table.hpp"

#include <array>
#include <string>

namespace lmgc::grammar {
namespace {

// mod_parameters.f90 `contactor_type`, in id order.
constexpr std::array<std::string_view, 17> kContactorTypes = {
    "DISKx", "xKSID", "POLYG", "JONCx", "PT2Dx", "SPHER", "CYLND", "DNLYC", "POLYR",
    "PLANx", "PT3Dx", "ALpxx", "CLxxx", "DISKL", "PT2DL", "ASpxx", "CSxxx"};

// A word as the Fortran CHARACTER(5) it was read into: blank-padded to 5 characters.
std::string padded(const Word& word) {
  std::string text = word.value.substr(0, 5);
  text.resize(5, ' ');
  return text;
}

}  // namespace

int see_contactor_id(std::string_view name) {
  // get_index_from_string compares trimmed names.
  while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
  for (std::size_t i = 0; i < kContactorTypes.size(); ++i)
    if (kContactorTypes[i] == name) return static_cast<int>(i) + 1;
  return -99;
}

bool same_see_pair(const SeeEntry& a, const SeeEntry& b) {
  const int a_cd = see_contactor_id(a.candidate_contactor.value),
            a_an = see_contactor_id(a.antagonist_contactor.value);
  const int b_cd = see_contactor_id(b.candidate_contactor.value),
            b_an = see_contactor_id(b.antagonist_contactor.value);
  // docs/lmgc90-facts/contact-laws.md §1.2 (remove_bad_see_links): same pair, or the same pair swapped.
  const bool same = a_an == b_an && a_cd == b_cd &&
                    padded(a.antagonist_colour) == padded(b.antagonist_colour) &&
                    padded(a.candidate_colour) == padded(b.candidate_colour) &&
                    padded(a.antagonist_body) == padded(b.antagonist_body) &&
                    padded(a.candidate_body) == padded(b.candidate_body);
  const bool swapped = a_an == b_cd && a_cd == b_an &&
                       padded(a.antagonist_colour) == padded(b.candidate_colour) &&
                       padded(a.candidate_colour) == padded(b.antagonist_colour) &&
                       padded(a.antagonist_body) == padded(b.candidate_body) &&
                       padded(a.candidate_body) == padded(b.antagonist_body);
  return same || swapped;
}

std::vector<std::size_t> see_duplicate_of(const std::vector<SeeEntry>& entries) {
  std::vector<std::size_t> duplicate_of(entries.size(), kNoDuplicate);
  // LMGC90 compares each kept entry with every later one and removes the later matches.
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (duplicate_of[i] != kNoDuplicate) continue;
    for (std::size_t j = i + 1; j < entries.size(); ++j)
      if (duplicate_of[j] == kNoDuplicate && same_see_pair(entries[i], entries[j])) duplicate_of[j] = i;
  }
  return duplicate_of;
}

std::vector<SeeEntry> lmgc90_see_order(const std::vector<SeeEntry>& entries) {
  if (entries.size() <= 1) return entries;  // close_see_ll merges and sorts only when > 1
  std::vector<SeeEntry> list;
  const std::vector<std::size_t> duplicate_of = see_duplicate_of(entries);
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (duplicate_of[i] == kNoDuplicate) list.push_back(entries[i]);

  // sort_see_ll: each cell, from the second, is compared with the cells before it, from the
  // head; it is moved in front of the first one for which `move` is true. On a tie of
  // antagonist id and colour, `move` is set only when the cell's candidate equals its
  // antagonist (colour and contactor id); otherwise the flag keeps its previous value (an
  // uninitialised Fortran local). Starting it at true reproduces all 19 reference echoes
  // (e.g. BouncingBallsDK reversed, Bridge_PR and BridgePL_GroundJC partly reordered).
  bool move = true;
  for (std::size_t k = 1; k < list.size(); ++k) {
    const SeeEntry& ordering = list[k];
    const int ordering_an = see_contactor_id(ordering.antagonist_contactor.value);
    const int ordering_cd = see_contactor_id(ordering.candidate_contactor.value);
    const std::string ordering_ancol = padded(ordering.antagonist_colour);
    for (std::size_t t = 0; t < k; ++t) {
      const int testing_an = see_contactor_id(list[t].antagonist_contactor.value);
      const std::string testing_ancol = padded(list[t].antagonist_colour);
      if (ordering_an < testing_an) {
        move = true;
      } else if (ordering_an > testing_an) {
        move = false;
      } else if (ordering_ancol < testing_ancol) {
        move = true;
      } else if (ordering_ancol > testing_ancol) {
        move = false;
      } else if (ordering_ancol == padded(ordering.candidate_colour) && ordering_an == ordering_cd) {
        move = true;
      }
      if (move) {
        SeeEntry moved = list[k];
        list.erase(list.begin() + static_cast<std::ptrdiff_t>(k));
        list.insert(list.begin() + static_cast<std::ptrdiff_t>(t), std::move(moved));
        break;
      }
    }
  }
  return list;
}

}  // namespace lmgc::grammar
