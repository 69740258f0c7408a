#include "grammar/postpro/catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using A = PostproArguments;
using D = PostproDimension;

constexpr PostproCommandKind kCommands[] = {
    {"SOLVER INFORMATIONS", A::none, D::both},
    {"VIOLATION EVOLUTION", A::none, D::both},
    {"KINETIC ENERGY", A::none, D::both},
    {"DISSIPATED ENERGY", A::none, D::both},
    {"DRY CONTACT NATURE", A::none, D::both},
    {"WET CONTACT NATURE", A::none, D::both},
    {"COORDINATION NUMBER", A::none, D::both},
    {"NETWORK EVOLUTION", A::none, D::both},
    {"DISPLAY TENSORS", A::none, D::both},
    {"SNAPSHOT SAMPLE", A::none, D::both},
    {"MP SNAPSHOT SAMPLE", A::none, D::both},
    {"PLPLx ANALYSIS", A::none, D::only_2d},
    {"THERMAL EVOLUTION", A::none, D::both},
    {"ELECTRO EVOLUTION", A::none, D::both},
    {"CLOUD ANALYSIS", A::none, D::both},
    {"CREATE TEXT DATA", A::none, D::both},
    {"HEAT BOUND PROFILE", A::none, D::both},
    {"Fint EVOLUTION", A::none, D::both},
    {"Dep EVOLUTION", A::none, D::both},
    {"MAILx DIST", A::none, D::both},
    {"SURFACE ENERGIE SECTOR", A::none, D::both},
    {"CZM ENERGY EVOLUTION", A::none, D::both},
    {"ENERGY SNAPSHOT SAMPLE", A::none, D::both},
    {"INTER ANALYSIS", A::none, D::only_3d},
    {"VISIBILITY STATE", A::none, D::only_3d},
    {"PRxxx DETECTION", A::none, D::only_3d},
    {"AVERAGE VELOCITY EVOLUTION", A::colour, D::both},
    {"SPECIES KINETIC ENERGY", A::species, D::both},
    {"NORMAL CONTACT DISTRIBUTION", A::sectors_2d, D::both},
    {"CONTACT FORCE DISTRIBUTION", A::classes, D::both},
    {"BODY TRACKING", A::body_list, D::both},
    {"TORQUE EVOLUTION", A::body_list, D::both},
    {"MP VALUE TRACKING", A::mp_tracking, D::both},
    {"DENSE SAMPLE COMPACITY", A::dense_sample, D::both},
    {"DOUBLET INTERACTIONS", A::doublet, D::both},
    {"3D EXTRUSION", A::extrusion, D::both},
    {"QUASI SLIDING CONTACT", A::fraction, D::both},
    {"NEW MECAx SETS", A::meca_sets, D::both},
    {"NEW DIST SETS", A::dist_sets, D::both},
    {"NEW RIGID SETS", A::rigid_sets, D::both},
    {"NEW BOUNDED SETS", A::bounded_sets, D::both},
    {"COMPACITY EVOLUTION", A::compacity, D::both},
    {"CLxxx ANALYSIS", A::clxxx, D::both},
    {"TRIAXIAL COMPACITY", A::triaxial, D::only_3d},
    {"DOUBLETS TORQUE EVOLUTION", A::pairs, D::only_3d},
};

}  // namespace

std::span<const PostproCommandKind> postpro_catalogue() { return kCommands; }

const PostproCommandKind* find_postpro_command(std::string_view name) {
  auto it = std::find_if(std::begin(kCommands), std::end(kCommands),
                         [&](const PostproCommandKind& k) { return k.name == name; });
  return it == std::end(kCommands) ? nullptr : &*it;
}

}  // namespace lmgc::grammar
