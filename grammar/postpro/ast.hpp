#pragma once
// POSTPRO.DAT: the post-processing commands of a run. spec: datbox-inputs.md §8.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// One argument line of a command, as its format reads it (an I7, an A5, a list of integers...).
struct PostproArgument {
  std::vector<Integer> integers;
  std::vector<Real> reals;
  Word word;
  friend bool operator==(const PostproArgument&, const PostproArgument&) = default;
};

struct PostproCommand {
  Word name;        // columns 1-30, trailing blanks removed
  Integer period;   // 'STEP n': the command runs when Nstep mod n == 0
  std::vector<PostproArgument> arguments;
  friend bool operator==(const PostproCommand&, const PostproCommand&) = default;
};

struct PostproFile {
  std::vector<PostproCommand> commands;
  friend bool operator==(const PostproFile&, const PostproFile&) = default;
};

}  // namespace lmgc::grammar
