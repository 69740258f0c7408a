#pragma once
// Vloc_Rloc.INI / .LAST / .OUT.n: the interactions of a step (local reactions, velocities, gaps,
// frames, internal variables). docs/lmgc90-facts/state-and-outputs.md §1.2, §1.4; datbox-inputs.md §7.
#include <string>
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One line of labelled values after the data line ("rlt/H ... rln/H ... rls/H ...").
struct VlocRlocVector {
  std::vector<std::string> labels;  // 5 characters each, as written
  std::vector<Real> values;
  friend bool operator==(const VlocRlocVector&, const VlocRlocVector&) = default;
};

struct VlocRlocInteraction {
  Word type;       // interaction module: DKDKx, PLPLx, PRPRx, ... (columns 9-13 of '$icdan')
  Integer number;  // icdan
  // The "xxl" layout (DKDKx, DKJCx, SPSPx with more than 99999 verlet contacts: wider number
  // fields), recognised by its title line. docs/lmgc90-facts/state-and-outputs.md §1.4.1, §1.4.2.
  bool xxl = false;
  std::string title;  // the title line, verbatim (LMGC90 skips it on reading; it depends on the module)
  // The data line, split by the module's format (interaction_catalogue.cpp): its A5 words
  // (body models, contactor types, law, status, CDVER/ANSEG markers) and I5 integers (body and
  // contactor numbers, vertex/segment, iadj), each in order of appearance.
  std::vector<Word> words;
  std::vector<Integer> integers;
  std::vector<VlocRlocVector> vectors;  // rl, vl, gap, n/t/s, coo lines, as written
  // Internal variables of the law (state-and-outputs.md §1.4.4): their count depends on the law.
  // The '#' line naming them is kept verbatim (padded with blanks to 285 columns by LMGC90), the
  // values line by line as written ((1X,D14.7) each: 6 or 5 per line for DKDKx/DKJCx, all on one
  // line otherwise, interaction_catalogue.hpp); vloc_rloc_internal_values() gives them as one vector.
  std::string internal_comment;                   // '#' line naming the internal variables, or empty
  std::vector<std::vector<Real>> internal_lines;  // internal variable values, line by line
  friend bool operator==(const VlocRlocInteraction&, const VlocRlocInteraction&) = default;
};

// The internal variables of an interaction as one vector, in order.
inline std::vector<Real> vloc_rloc_internal_values(const VlocRlocInteraction& interaction) {
  std::vector<Real> values;
  for (const auto& line : interaction.internal_lines) values.insert(values.end(), line.begin(), line.end());
  return values;
}

struct VlocRlocFile {
  Integer step;  // '$steps' columns 9-15
  Real time;     // '$steps' columns 35-48
  std::vector<VlocRlocInteraction> interactions;
  friend bool operator==(const VlocRlocFile&, const VlocRlocFile&) = default;
};

}  // namespace lmgc::grammar
