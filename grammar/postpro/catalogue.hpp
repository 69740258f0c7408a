#pragma once
// The POSTPRO.DAT commands LMGC90 knows (mod_postpro_2D: 40, mod_postpro_3D: 36), each with the
// layout of the argument lines that follow its STEP line. One table, used by the parser (what
// to read) and by tests and generators (what to build). docs/lmgc90-facts/datbox-inputs.md §8 table.
#include <span>
#include <string>
#include <string_view>

#include "grammar/postpro/ast.hpp"

namespace lmgc::grammar {

enum class PostproDimension { both, only_2d, only_3d };

// How many times the steps that follow a line are repeated.
enum class PostproRepeat {
  none,
  last_integer,     // the last integer of this line (a count, or a node count for MECAx sets)
  compacity_model,  // COMPACITY EVOLUTION: 4 ids for SMOOTH/ROUGH/CLUSTER BOX, 2 for COUETTE, 0 for SELECTION
};

// One argument line; when `repeat` is set, the next `body` steps are read that many times.
struct PostproStep {
  PostproLineFormat format;
  std::string_view what;  // for messages
  PostproRepeat repeat = PostproRepeat::none;
  int body = 0;
};

struct PostproCommandKind {
  std::string_view name;  // exact spelling, case-sensitive, at most 30 characters
  PostproDimension dimension;
  std::span<const PostproStep> layout_2d;
  std::span<const PostproStep> layout_3d;

  std::span<const PostproStep> layout(int dimension_of_run) const {
    // Dimension not known (0): the 2D layout, or the 3D one for a command only the 3D reader knows.
    const bool three =
        dimension_of_run == 3 || (dimension_of_run == 0 && dimension == PostproDimension::only_3d);
    return three ? layout_3d : layout_2d;
  }
  bool available_in(int dimension_of_run) const {
    if (dimension_of_run == 2) return dimension != PostproDimension::only_3d;
    if (dimension_of_run == 3) return dimension != PostproDimension::only_2d;
    return true;  // dimension not known: any command of either reader
  }
};

std::span<const PostproCommandKind> postpro_catalogue();
const PostproCommandKind* find_postpro_command(std::string_view name);

// Number of ids that COMPACITY EVOLUTION reads after its model word; -1 for a model LMGC90 rejects.
int postpro_compacity_ids(std::string_view model);

// The text of one argument line in the canonical layout (without padding): integers
// left-justified in their fields, reals as ES14.7, words as read.
std::string postpro_argument_text(const PostproArgument& argument);

}  // namespace lmgc::grammar
