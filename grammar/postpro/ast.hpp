#pragma once
// POSTPRO.DAT: the post-processing commands of a run. docs/lmgc90-facts/datbox-inputs.md §8.
#include <vector>

#include "grammar/common/field.hpp"

namespace lmgc::grammar {

// How one argument line is read (the Fortran format of its READ). docs/lmgc90-facts/datbox-inputs.md §8
// table.
enum class PostproLineFormat {
  i5,                 // one integer, columns 1-5
  i7,                 // one integer, columns 1-7
  a5,                 // one word, columns 1-5
  a12,                // one word, columns 1-12
  i7_x_i3,            // (I7,1X,I3): columns 1-7 and 9-11
  i7_x_i7,            // (I7,1X,I7): columns 1-7 and 9-15
  list_integer,       // one list-directed integer
  list_integer_pair,  // two list-directed integers
  list_integer_quad,  // four list-directed integers
  list_real,          // one list-directed real
  es14_7,             // one real, columns 1-14
  dense_sample,       // A30: any text; 'INTER' in columns 1-5 adds an I7 body id from columns 7-13
};

// One argument line of a command, as its format reads it.
struct PostproArgument {
  PostproLineFormat format = PostproLineFormat::i7;
  std::vector<Integer> integers;
  std::vector<Real> reals;
  Word word;  // a5/a12: the word; dense_sample: the whole line (columns 1-30, trailing blanks removed)
  friend bool operator==(const PostproArgument&, const PostproArgument&) = default;
};

struct PostproCommand {
  Word name;                               // columns 1-30, trailing blanks removed (LMGC90's spelling)
  Integer period;                          // 'STEP n': the command runs when Nstep mod n == 0
  std::vector<PostproArgument> arguments;  // one per argument line, in file order
  friend bool operator==(const PostproCommand&, const PostproCommand&) = default;
};

struct PostproFile {
  std::vector<PostproCommand> commands;
  friend bool operator==(const PostproFile&, const PostproFile&) = default;
};

}  // namespace lmgc::grammar
