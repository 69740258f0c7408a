#include "grammar/bodies/contactor_catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using L = ContactorLayout;
constexpr unsigned kRigid2 = kOnRbdy2;
constexpr unsigned kRigid3 = kOnRbdy3;
constexpr unsigned kMailx = kOnMailx;

// keyword, bodies, layout, first-line labels, count, offset labels, count, patch nodes, dim, guide
constexpr ContactorKind kContactors[] = {
    {"DISKx", kRigid2, L::values, {"byrd="}, 1, {}, 0, 0, 2, ""},
    {"xKSID", kRigid2, L::values, {"byrd="}, 1, {}, 0, 0, 2, ""},
    {"DISKb", kRigid2, L::values_offset, {"byrd="}, 1, {"coo1=", "coo2="}, 2, 0, 2, ""},
    {"DISPx",
     kRigid2,
     L::values,
     {"byrd="},
     1,
     {},
     0,
     0,
     2,
     "'DISPx' (pneumatic disk, in the 2012 user's guide) was removed from LMGC90: its RBDY2 reader stops on "
     "it"},
    {"xPSID",
     kRigid2,
     L::values,
     {"byrd="},
     1,
     {},
     0,
     0,
     2,
     "'xPSID' (hollow pneumatic disk, in the 2012 user's guide) was removed from LMGC90: its RBDY2 reader "
     "stops "
     "on it"},
    {"JONCx", kRigid2, L::values, {"ax1 =", "ax2 ="}, 2, {}, 0, 0, 2, ""},
    {"POLYG", kRigid2, L::polygon, {}, 0, {"coo1=", "coo2="}, 2, 0, 2, ""},
    {"PT2Dx", kRigid2, L::values, {"coo1=", "coo2="}, 2, {}, 0, 0, 2, ""},
    {"SPHER", kRigid3, L::values, {"byrd="}, 1, {}, 0, 0, 3, ""},
    {"SPHEb", kRigid3, L::values_offset, {"byrd="}, 1, {"coo1=", "coo2=", "coo3="}, 3, 0, 3, ""},
    {"CYLND", kRigid3, L::values_frame, {"High=", "byrd="}, 2, {}, 0, 0, 3, ""},
    {"DNLYC", kRigid3, L::values, {"High=", "byrd="}, 2, {}, 0, 0, 3, ""},
    {"PLANx", kRigid3, L::values_frame, {"axe1=", "axe2=", "axe3="}, 3, {}, 0, 0, 3, ""},
    {"PT3Dx", kRigid3, L::values, {"coo1=", "coo2=", "coo3="}, 3, {}, 0, 0, 3, ""},
    {"POLYR", kRigid3, L::polyhedron, {}, 0, {"coo1=", "coo2=", "coo3="}, 3, 0, 3, ""},
    {"POLYF", kRigid3, L::polyhedron_patches, {}, 0, {"coo1=", "coo2=", "coo3="}, 3, 0, 3, ""},
    {"CLxxx", kMailx, L::node_point, {"noda=", "nodb=", "apab="}, 1, {}, 0, 0, 2, ""},
    {"ALpxx", kMailx, L::node_polyline, {"noda=", "nodb="}, 0, {}, 0, 0, 2, ""},
    {"PT2DL", kMailx, L::node_point, {"noda=", "nodb=", "apab="}, 1, {}, 0, 0, 2, ""},
    {"PT2TL", kMailx, L::node_point, {"noda=", "nodb=", "apab="}, 1, {}, 0, 0, 2, ""},
    {"DISKL", kMailx, L::node_point, {"noda=", "nodb=", "apab=", "bdyr=", "brpm="}, 3, {}, 0, 0, 2, ""},
    {"CSpxx", kMailx, L::node_patch, {}, 0, {}, 0, 0, 3, ""},
    {"CSpx0", kMailx, L::node_patch, {}, 0, {}, 0, 0, 3, ""},
    {"CSpx1", kMailx, L::node_patch, {}, 0, {}, 0, 0, 3, ""},
    {"CSpx2", kMailx, L::node_patch, {}, 0, {}, 0, 0, 3, ""},
    {"ASpxx", kMailx, L::node_patch, {}, 0, {}, 0, 0, 3, ""},
    {"CSxx3",
     kMailx,
     L::node_patch,
     {},
     0,
     {},
     0,
     3,
     3,
     "'CSxx3' is the pre-processor's name; LMGC90's BODIES.DAT reader expects 'CSpxx'"},
    {"CSxx4",
     kMailx,
     L::node_patch,
     {},
     0,
     {},
     0,
     4,
     3,
     "'CSxx4' is the pre-processor's name; LMGC90's BODIES.DAT reader expects 'CSpxx'"},
    {"CSpx3", kMailx, L::node_patch, {}, 0, {}, 0, 3, 3, "'CSpx3' is read only by LMGC90's v2.0 format"},
    {"CSpx4", kMailx, L::node_patch, {}, 0, {}, 0, 4, 3, "'CSpx4' is read only by LMGC90's v2.0 format"},
    {"CSpx6", kMailx, L::node_patch, {}, 0, {}, 0, 6, 3, "'CSpx6' is read only by LMGC90's v2.0 format"},
    {"CSpx8", kMailx, L::node_patch, {}, 0, {}, 0, 8, 3, "'CSpx8' is read only by LMGC90's v2.0 format"},
    {"ASpx3", kMailx, L::node_patch, {}, 0, {}, 0, 3, 3, "'ASpx3' is read only by LMGC90's v2.0 format"},
    {"ASpx4", kMailx, L::node_patch, {}, 0, {}, 0, 4, 3, "'ASpx4' is read only by LMGC90's v2.0 format"},
    {"ASpx6", kMailx, L::node_patch, {}, 0, {}, 0, 6, 3, "'ASpx6' is read only by LMGC90's v2.0 format"},
    {"ASpx8", kMailx, L::node_patch, {}, 0, {}, 0, 8, 3, "'ASpx8' is read only by LMGC90's v2.0 format"},
    {"POLYD", kMailx, L::deformable_polyhedron, {}, 0, {}, 0, 0, 3, ""},
};

constexpr ElementKind kElements[] = {
    {"S2xxx", 2}, {"S3xxx", 3},  {"T3xxx", 3}, {"T6xxx", 6},  {"Q4xxx", 4}, {"Q8xxx", 8},
    {"H8xxx", 8}, {"H20xx", 20}, {"TE4xx", 4}, {"TE10x", 10}, {"PRI6x", 6}, {"PRI15", 15},
};

}  // namespace

std::span<const ContactorKind> contactor_catalogue() {
  return kContactors;
}

const ContactorKind* find_contactor_kind(std::string_view keyword) {
  auto it = std::find_if(std::begin(kContactors), std::end(kContactors),
                         [&](const ContactorKind& k) { return k.keyword == keyword; });
  return it == std::end(kContactors) ? nullptr : &*it;
}

std::span<const ElementKind> element_catalogue() {
  return kElements;
}

const ElementKind* find_element_kind(std::string_view keyword) {
  auto it = std::find_if(std::begin(kElements), std::end(kElements),
                         [&](const ElementKind& k) { return k.keyword == keyword; });
  return it == std::end(kElements) ? nullptr : &*it;
}

}  // namespace lmgc::grammar
