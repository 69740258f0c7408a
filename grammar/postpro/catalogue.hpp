#pragma once
// The POSTPRO.DAT commands LMGC90 knows (mod_postpro_2D / mod_postpro_3D), each with the shape
// of the argument lines that follow its STEP line. spec: datbox-inputs.md §8 table.
#include <span>
#include <string_view>

namespace lmgc::grammar {

enum class PostproArguments {
  none,
  colour,               // one A5 line
  species,              // n (I5), then n A5 lines
  sectors_2d,           // 2D: one I5 line; 3D: none
  classes,              // one integer line (I5 in 2D, list-directed in 3D)
  body_list,            // n (I7), then n I7 lines
  mp_tracking,          // n (I7), then n lines (I7,1X,I3)
  dense_sample,         // always one line: 'INTER' + body at 7-13, or anything else
  doublet,              // A5, I7, I7 lines
  extrusion,            // two list-directed reals, one per line
  fraction,             // one real line
  meca_sets,            // nsets; per set n; per member (I7,1X,I7) body, count, then count I7 lines
  dist_sets,            // nsets; per set one list-directed line of 4 integers
  rigid_sets,           // nsets; per set size, then size I7 lines
  bounded_sets,         // nsets; per set idmin, idmax (I7 lines)
  compacity,            // A5 behav, A12 model, + 4 ids (CLUSTER BOX) or 2 (COUETTE)
  clxxx,                // n (list-directed), then n lines "a b"
  triaxial,             // 6 I5 lines
  pairs,                // n, then n lines "a b" (list-directed)
};

enum class PostproDimension { both, only_2d, only_3d };

struct PostproCommandKind {
  std::string_view name;
  PostproArguments arguments;
  PostproDimension dimension;
};

std::span<const PostproCommandKind> postpro_catalogue();
const PostproCommandKind* find_postpro_command(std::string_view name);

}  // namespace lmgc::grammar
