#include "grammar/vloc_rloc/interaction_catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using L = VectorLineKind;
using I = InternalLayout2D;

// Vector lines (docs/lmgc90-facts/state-and-outputs.md §1.4).
constexpr L kRlTns{{"rlt/H", "rln/H", "rls/H"}, 3};
constexpr L kRlTnsBlank{{"rlt/H", "rln/H", "rls ="}, 3};
constexpr L kRlStn{{"rls/H", "rlt/H", "rln/H"}, 3};
constexpr L kVlTns{{"vlt =", "vln =", "vls ="}, 3};
constexpr L kVlStn{{"vls =", "vlt =", "vln ="}, 3};
constexpr L kGapTT{{"gapTT", "", ""}, 1};
constexpr L kGapEq{{"gap =", "", ""}, 1};
constexpr L kGtt{{"gTT =", "", ""}, 1};
constexpr L kN{{"n(1)=", "n(2)=", "n(3)="}, 3};
constexpr L kT{{"t(1)=", "t(2)=", "t(3)="}, 3};
constexpr L kS{{"s(1)=", "s(2)=", "s(3)="}, 3};
constexpr L kCoo{{"coo1=", "coo2=", "coo3="}, 3};

constexpr L k2D[] = {kRlTns, kVlTns, kGapTT, kN, kCoo};
constexpr L k2DRls[] = {kRlTnsBlank, kVlTns, kGapTT, kN, kCoo};
constexpr L k2DGap[] = {kRlTns, kVlTns, kGapEq, kN, kCoo};
constexpr L kPRPR[] = {kRlTns, kVlTns, kGapTT, kCoo, kT, kN, kS};
constexpr L kPRPL[] = {kRlStn, kVlStn, kGapTT, kCoo, kT, kN, kS};
constexpr L kSPSP[] = {kRlStn, kVlStn, kGtt, kS, kT, kN, kCoo};
constexpr L kSPCD[] = {kRlStn, kVlStn, kGtt, kT, kN, kS, kCoo};
constexpr L kPTPT3[] = {kRlTns, kVlTns, kGapTT, kN, kCoo};

constexpr std::string_view kTitle2D =
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj";
constexpr std::string_view kTitleSegment =
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  segmt  sttus   iadj";
constexpr std::string_view kTitleDKALp =
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr                sttus iadj ";
constexpr std::string_view kTitleDKPLx =
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  vertx  numbr                sttus iadj ";
constexpr std::string_view kTitleVertex =
    " cdbdy  numbr  cdtac  numbr  vertx  numbr  behav  anbdy  numbr  antac  numbr                sttus iadj ";
constexpr std::string_view kTitlePLPLx =
    " cdbdy  numbr  cdtac  numbr  vertx  numbr  behav  anbdy  numbr  antac  numbr  segmt  numbr";
constexpr std::string_view kTitle3D =
    " cdbdy  numbr  cdtac  numbr  CDVER  behav  anbdy  numbr  antac  numbr  sttus";
constexpr std::string_view kTitle3DShort =
    " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus";

constexpr std::string_view kData2D = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataCLALp =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataDKALp =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 9X A5 1X I5";
constexpr std::string_view kDataDKPLx =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5 16X A5 1X I5";
constexpr std::string_view kDataPLJCx =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 16X A5 1X I5";
constexpr std::string_view kDataPLALp =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 9X A5 1X I5";
constexpr std::string_view kDataPLPLx =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 1X I5";
constexpr std::string_view kDataPRPRx = "1X A5 2X I5 2X A5 2X I5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5";
constexpr std::string_view kDataSPSPx = "1X A5 2X I5 2X A5 2X I5 9X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataCDPLx = "1X A5 2X I5 2X A5 2X I5 9X A5 2X A5 2X I5 2X A5 2X I5 2X A5";
constexpr std::string_view kData3DShort = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5";

// "xxl" variants (state-and-outputs.md §1.4.1 and §1.4.2): wider body numbers, wider titles.
constexpr std::string_view kTitle2DXxl =
    " cdbdy       numbr  cdtac  numbr  behav  anbdy       numbr  antac  numbr  sttus   iadj";
constexpr std::string_view kTitleSPSPxXxl =
    " cdbdy    numbr  cdtac    numbr  CDVER  behav  anbdy    numbr  antac    numbr  sttus";
// CSPRx writes the 69-character title with A76: Fortran right-justifies it behind 7 blanks.
constexpr std::string_view kTitleCSPRx =
    "        cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus";
constexpr std::string_view kData2DXxl = "1X A5 2X I10 2X A5 2X I5 2X A5 2X A5 2X I10 2X A5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataSPSPxXxl =
    "1X A5 2X I7 2X A5 2X I7 9X A5 2X A5 2X I7 2X A5 2X I7 2X A5 2X I7";

constexpr InteractionKind kKinds[] = {
    // 2D (src/Core/contact_2D/mod_*.f90, write_out_Vloc_Rloc). The normal layout of a module comes
    // before its xxl variant: find_interaction_kind(type) returns the first match.
    {"DKDKx", 2, kTitle2D, kData2D, k2D, I::per_line_6, false, 7},
    {"DKDKx", 2, kTitle2DXxl, kData2DXxl, k2D, I::one_line_with_comment, true, 10},
    {"DKJCx", 2, kTitle2D, kData2D, k2D, I::per_line_5, false, 7},
    {"DKJCx", 2, kTitle2DXxl, kData2DXxl, k2D, I::one_line_with_comment, true, 10},
    {"DKKDx", 2, kTitle2D, kData2D, k2DRls, I::one_line_with_comment, false, 7},
    {"DKDKL", 2, kTitle2D, kData2D, k2DRls, I::one_line_with_comment, false, 7},
    {"CLJCx", 2, kTitle2D, kData2D, k2D, I::one_line_with_comment, false, 7},
    {"PTPT2", 2, kTitle2D, kData2D, k2D, I::one_line_with_comment, false, 7},
    {"P2P2L", 2, kTitle2D, kData2D, k2DGap, I::one_line_with_comment, false, 7},
    {"CLALp", 2, kTitleSegment, kDataCLALp, k2D, I::one_line_with_comment, false, 7},
    {"DKALp", 2, kTitleDKALp, kDataDKALp, k2D, I::one_line_with_comment, false, 7},
    {"DKPLx", 2, kTitleDKPLx, kDataDKPLx, k2D, I::one_line_with_comment, false, 7},
    {"PLJCx", 2, kTitleVertex, kDataPLJCx, k2D, I::one_line_with_comment, false, 7},
    {"PLPLx", 2, kTitlePLPLx, kDataPLPLx, k2D, I::one_line_with_comment, false, 7},
    {"PLALp", 2, kTitleVertex, kDataPLALp, k2D, I::one_line_with_comment, false, 7},
    // 3D (src/Core/contact_3D/mod_*.f90)
    {"PRPRx", 3, kTitle3D, kDataPRPRx, kPRPR, I::one_line_with_comment, false, 7},
    {"PRPLx", 3, kTitle3D, kDataPRPRx, kPRPL, I::one_line_with_comment, false, 7},
    {"PRASp", 3, kTitle3D, kDataPRPRx, kPRPL, I::one_line_with_comment, false, 7},
    {"SPSPx", 3, kTitle3D, kDataSPSPx, kSPSP, I::one_line_with_comment, false, 7},
    {"SPSPx", 3, kTitleSPSPxXxl, kDataSPSPxXxl, kSPSP, I::one_line_with_comment, true, 7},
    // SPPLx: the reference files have no trailing iantac (newer sources write one).
    {"SPPLx", 3, kTitle3D, kDataCDPLx, kSPSP, I::one_line_with_comment, false, 7},
    // CDCDx's format ends with 2X,I5 but no item is given for it: nothing is written there
    // (mod_CDCDx.f90 write_out_Vloc_Rloc).
    {"CDCDx", 3, kTitle3D, kDataCDPLx, kSPSP, I::one_line_with_comment, false, 7},
    {"CDPLx", 3, kTitle3D, kDataCDPLx, kSPSP, I::one_line_with_comment, false, 7},
    {"SPCDx", 3, kTitle3D, kDataSPSPx, kSPCD, I::one_line_with_comment, false, 7},
    {"SPDCx", 3, kTitle3D, kDataSPSPx, kSPCD, I::one_line_with_comment, false, 7},
    {"SPPRx", 3, kTitle3DShort, kData3DShort, kPRPR, I::one_line_with_comment, false, 7},
    // Module CSASp writes (and reads back) its blocks under the name CSASx.
    {"CSASx", 3, kTitle3DShort, kData3DShort, kPRPL, I::one_line_with_comment, false, 7},
    {"CSPRx", 3, kTitleCSPRx, kData3DShort, kPRPL, I::one_line_with_comment, false, 7},
    {"PTPT3", 3, kTitle2D, kData2D, kPTPT3, I::one_line_with_comment, false, 7},
};

}  // namespace

std::span<const InteractionKind> interaction_catalogue() {
  return kKinds;
}

const InteractionKind* find_interaction_kind(std::string_view type) {
  auto it = std::find_if(std::begin(kKinds), std::end(kKinds),
                         [&](const InteractionKind& k) { return k.type == type; });
  return it == std::end(kKinds) ? nullptr : &*it;
}

const InteractionKind* find_interaction_kind(std::string_view type, bool xxl) {
  if (xxl)
    for (const InteractionKind& kind : kKinds)
      if (kind.xxl && kind.type == type) return &kind;
  return find_interaction_kind(type);
}

std::vector<DataItem> data_items(std::string_view data_format) {
  std::vector<DataItem> items;
  while (!data_format.empty()) {
    const std::size_t end = data_format.find(' ');
    const std::string_view item = data_format.substr(0, end);
    data_format = end == std::string_view::npos ? std::string_view() : data_format.substr(end + 1);
    if (item.empty()) continue;
    // "nX" (blanks), "Aw" (word) or "Iw" (integer); the table holds only these.
    const bool skip = item.back() == 'X';
    const std::string_view digits = skip ? item.substr(0, item.size() - 1) : item.substr(1);
    int width = 0;
    for (char c : digits)
      if (c >= '0' && c <= '9') width = width * 10 + (c - '0');
    items.push_back(DataItem{skip ? 'X' : item[0], width});
  }
  return items;
}

}  // namespace lmgc::grammar
