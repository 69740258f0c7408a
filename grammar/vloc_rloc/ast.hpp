#pragma once
// Vloc_Rloc.INI / .LAST / .OUT.n: the interactions of a step (local reactions, velocities, gaps,
// frames, internal variables). spec: state-and-outputs.md §1.2, §1.4; datbox-inputs.md §7.
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
  std::string title;  // the title line, verbatim (it depends on the module)
  // The data line, split by the module's format (interaction_catalogue.cpp): its A5 words
  // (body models, contactor types, law, status, CDVER/ANSEG markers) and I5 integers (body and
  // contactor numbers, vertex/segment, iadj), each in order of appearance.
  std::vector<Word> words;
  std::vector<Integer> integers;
  std::vector<VlocRlocVector> vectors;          // rl, vl, gap, n/t/s, coo lines, as written
  std::string internal_comment;                 // '#' line naming the internal variables, or empty
  std::vector<std::vector<Real>> internal_lines;  // internal variable values, line by line
  friend bool operator==(const VlocRlocInteraction&, const VlocRlocInteraction&) = default;
};

struct VlocRlocFile {
  Integer step;  // '$steps' columns 9-15
  Real time;     // '$steps' columns 35-48
  std::vector<VlocRlocInteraction> interactions;
  friend bool operator==(const VlocRlocFile&, const VlocRlocFile&) = default;
};

}  // namespace lmgc::grammar
