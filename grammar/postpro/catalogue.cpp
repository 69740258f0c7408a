#include "grammar/postpro/catalogue.hpp"

#include <algorithm>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

using F = PostproLineFormat;
using R = PostproRepeat;

// Argument layouts, from the READ statements of reading_data (mod_postpro_2D.f90:833-1999,
// mod_postpro_3D.f90:735-1813). docs/lmgc90-facts/datbox-inputs.md §8.
constexpr PostproStep kColour[] = {{F::a5, "the colour"}};
constexpr PostproStep kSpecies[] = {{F::i5, "the number of species", R::last_integer, 1},
                                    {F::a5, "a species nickname"}};
constexpr PostproStep kSectors2d[] = {{F::i5, "the number of sectors"}};
constexpr PostproStep kClasses2d[] = {{F::i5, "the number of classes"}};
constexpr PostproStep kClasses3d[] = {{F::list_integer, "the number of classes"}};
constexpr PostproStep kBodyList[] = {{F::i7, "the number of bodies", R::last_integer, 1},
                                     {F::i7, "a body number"}};
constexpr PostproStep kMpTracking[] = {{F::i7, "the number of bodies", R::last_integer, 1},
                                       {F::i7_x_i3, "a body and contactor"}};
constexpr PostproStep kDenseSample[] = {{F::dense_sample, "the 'INTER' line (or any line)"}};
constexpr PostproStep kDoublet[] = {
    {F::a5, "the interaction type"}, {F::i7, "the first body"}, {F::i7, "the second body"}};
constexpr PostproStep kExtrusion[] = {{F::list_real, "the depth"}, {F::list_real, "the factor"}};
constexpr PostproStep kFraction2d[] = {{F::es14_7, "the fraction"}};
constexpr PostproStep kFraction3d[] = {{F::list_real, "the fraction"}};
constexpr PostproStep kMecaSets[] = {{F::i7, "the number of sets", R::last_integer, 3},
                                     {F::i7, "the number of members", R::last_integer, 2},
                                     {F::i7_x_i7, "a body and its node count", R::last_integer, 1},
                                     {F::i7, "a node number"}};
constexpr PostproStep kDistSets[] = {{F::i7, "the number of sets", R::last_integer, 1},
                                     {F::list_integer_quad, "a body-node-body-node line"}};
constexpr PostproStep kRigidSets[] = {{F::i7, "the number of sets", R::last_integer, 2},
                                      {F::i7, "the set size", R::last_integer, 1},
                                      {F::i7, "a body number"}};
constexpr PostproStep kBoundedSets[] = {
    {F::i7, "the number of sets", R::last_integer, 2}, {F::i7, "idmin"}, {F::i7, "idmax"}};
constexpr PostproStep kCompacity[] = {{F::a5, "the bulk behaviour"},
                                      {F::a12, "the model", R::compacity_model, 1},
                                      {F::i7, "a wall body number"}};
constexpr PostproStep kPairs[] = {{F::list_integer, "the number of pairs", R::last_integer, 1},
                                  {F::list_integer_pair, "a pair"}};
constexpr PostproStep kTriaxial[] = {{F::i5, "xmin wall"}, {F::i5, "xmax wall"}, {F::i5, "ymin wall"},
                                     {F::i5, "ymax wall"}, {F::i5, "zmin wall"}, {F::i5, "zmax wall"}};

constexpr std::span<const PostproStep> kEmpty{};

using D = PostproDimension;
constexpr PostproCommandKind kCommands[] = {
    // Order of mod_postpro_2D.f90 (its 40 names), then the 5 names only mod_postpro_3D knows.
    {"AVERAGE VELOCITY EVOLUTION", D::both, kColour, kColour},
    {"SPECIES KINETIC ENERGY", D::both, kSpecies, kSpecies},
    {"SNAPSHOT SAMPLE", D::both, kEmpty, kEmpty},
    {"MP SNAPSHOT SAMPLE", D::both, kEmpty, kEmpty},
    {"NORMAL CONTACT DISTRIBUTION", D::both, kSectors2d, kEmpty},
    {"CONTACT FORCE DISTRIBUTION", D::both, kClasses2d, kClasses3d},
    {"COORDINATION NUMBER", D::both, kEmpty, kEmpty},
    {"BODY TRACKING", D::both, kBodyList, kBodyList},
    {"MP VALUE TRACKING", D::both, kMpTracking, kMpTracking},
    {"TORQUE EVOLUTION", D::both, kBodyList, kBodyList},
    {"DENSE SAMPLE COMPACITY", D::only_2d, kDenseSample, kEmpty},
    {"DOUBLET INTERACTIONS", D::both, kDoublet, kDoublet},
    {"3D EXTRUSION", D::only_2d, kExtrusion, kEmpty},
    {"QUASI SLIDING CONTACT", D::both, kFraction2d, kFraction3d},
    {"NEW MECAx SETS", D::both, kMecaSets, kMecaSets},
    {"Fint EVOLUTION", D::both, kEmpty, kEmpty},
    {"Dep EVOLUTION", D::both, kEmpty, kEmpty},
    {"NEW DIST SETS", D::both, kDistSets, kDistSets},
    {"MAILx DIST", D::both, kEmpty, kEmpty},
    {"NEW RIGID SETS", D::both, kRigidSets, kRigidSets},
    {"NEW BOUNDED SETS", D::both, kBoundedSets, kBoundedSets},
    {"DISSIPATED ENERGY", D::both, kEmpty, kEmpty},
    {"SOLVER INFORMATIONS", D::both, kEmpty, kEmpty},
    {"DRY CONTACT NATURE", D::both, kEmpty, kEmpty},
    {"WET CONTACT NATURE", D::both, kEmpty, kEmpty},
    {"KINETIC ENERGY", D::both, kEmpty, kEmpty},
    {"VIOLATION EVOLUTION", D::both, kEmpty, kEmpty},
    {"PLPLx ANALYSIS", D::only_2d, kEmpty, kEmpty},
    {"THERMAL EVOLUTION", D::both, kEmpty, kEmpty},
    {"NETWORK EVOLUTION", D::both, kEmpty, kEmpty},
    {"CREATE TEXT DATA", D::only_2d, kEmpty, kEmpty},
    {"ELECTRO EVOLUTION", D::both, kEmpty, kEmpty},
    {"CLOUD ANALYSIS", D::both, kEmpty, kEmpty},
    {"DISPLAY TENSORS", D::both, kEmpty, kEmpty},
    {"COMPACITY EVOLUTION", D::only_2d, kCompacity, kEmpty},
    {"HEAT BOUND PROFILE", D::both, kEmpty, kEmpty},
    {"CLxxx ANALYSIS", D::only_2d, kPairs, kEmpty},
    {"SURFACE ENERGIE SECTOR", D::only_2d, kEmpty, kEmpty},
    {"CZM ENERGY EVOLUTION", D::only_2d, kEmpty, kEmpty},
    {"ENERGY SNAPSHOT SAMPLE", D::only_2d, kEmpty, kEmpty},
    {"TRIAXIAL COMPACITY", D::only_3d, kEmpty, kTriaxial},
    {"INTER ANALYSIS", D::only_3d, kEmpty, kEmpty},
    {"VISIBILITY STATE", D::only_3d, kEmpty, kEmpty},
    {"PRxxx DETECTION", D::only_3d, kEmpty, kEmpty},
    {"DOUBLETS TORQUE EVOLUTION", D::only_3d, kEmpty, kPairs},
};

void append_left(std::string& out, std::int64_t value, int width) {
  append_fortran_a(out, std::to_string(value), width);
}

}  // namespace

std::span<const PostproCommandKind> postpro_catalogue() {
  return kCommands;
}

const PostproCommandKind* find_postpro_command(std::string_view name) {
  auto it = std::find_if(std::begin(kCommands), std::end(kCommands),
                         [&](const PostproCommandKind& k) { return k.name == name; });
  return it == std::end(kCommands) ? nullptr : &*it;
}

int postpro_compacity_ids(std::string_view model) {
  // mod_postpro_2D.f90 reading_data, COMPACITY EVOLUTION: SELECT CASE on the A12 model.
  if (model == "SMOOTH BOX" || model == "ROUGH BOX" || model == "CLUSTER BOX") return 4;
  if (model == "COUETTE") return 2;
  if (model == "SELECTION") return 0;
  return -1;  // 'DENSE SAMPLE' ("not yet available") and anything else: fatal in LMGC90
}

std::string postpro_argument_text(const PostproArgument& a) {
  std::string text;
  auto integer = [&](std::size_t k) { return k < a.integers.size() ? a.integers[k].value : 0; };
  auto real = [&](std::size_t k) { return k < a.reals.size() ? a.reals[k].value : 0.0; };
  switch (a.format) {
    case F::i5:
    case F::i7:
    case F::list_integer:
      text = std::to_string(integer(0));
      break;
    case F::a5:
    case F::a12:
    case F::dense_sample:
      text = a.word.value;
      break;
    case F::i7_x_i3:
    case F::i7_x_i7:
      // Blanks are ignored inside I fields: each value left-justified in its columns.
      append_left(text, integer(0), 7);
      text += ' ';
      text += std::to_string(integer(1));
      break;
    case F::list_integer_pair:
    case F::list_integer_quad:
      for (std::size_t k = 0; k < a.integers.size(); ++k)
        text += (k ? " " : "") + std::to_string(a.integers[k].value);
      break;
    case F::list_real:
    case F::es14_7:
      append_fortran_es(text, real(0), 14, 7);
      break;
  }
  return text;
}

}  // namespace lmgc::grammar
