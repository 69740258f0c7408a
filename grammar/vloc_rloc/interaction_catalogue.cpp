#include "grammar/vloc_rloc/interaction_catalogue.hpp"

#include <algorithm>

namespace lmgc::grammar {
namespace {

using L = VectorLineKind;
using I = InternalLayout2D;

// Vector lines (spec: state-and-outputs.md §1.4).
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

constexpr std::string_view kTitle2D = " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus   iadj";
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
constexpr std::string_view kTitle3D = " cdbdy  numbr  cdtac  numbr  CDVER  behav  anbdy  numbr  antac  numbr  sttus";
constexpr std::string_view kTitle3DShort = " cdbdy  numbr  cdtac  numbr  behav  anbdy  numbr  antac  numbr  sttus";

constexpr std::string_view kData2D = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataCLALp = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataDKALp = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 9X A5 1X I5";
constexpr std::string_view kDataDKPLx = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5 16X A5 1X I5";
constexpr std::string_view kDataPLJCx = "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 16X A5 1X I5";
constexpr std::string_view kDataPLALp = "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X I5 9X A5 1X I5";
constexpr std::string_view kDataPLPLx =
    "1X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5 2X A5 1X I5";
constexpr std::string_view kDataPRPRx = "1X A5 2X I5 2X A5 2X I5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5";
constexpr std::string_view kDataSPSPx = "1X A5 2X I5 2X A5 2X I5 9X A5 2X A5 2X I5 2X A5 2X I5 2X A5 2X I5";
constexpr std::string_view kDataCDPLx = "1X A5 2X I5 2X A5 2X I5 9X A5 2X A5 2X I5 2X A5 2X I5 2X A5";
constexpr std::string_view kData3DShort = "1X A5 2X I5 2X A5 2X I5 2X A5 2X A5 2X I5 2X A5 2X I5 2X A5";

constexpr InteractionKind kKinds[] = {
    // 2D (mod_*.f90 write_out_Vloc_Rloc of contact_2D)
    {"DKDKx", 2, kTitle2D, kData2D, k2D, I::per_line_6},
    {"DKJCx", 2, kTitle2D, kData2D, k2D, I::per_line_5},
    {"DKKDx", 2, kTitle2D, kData2D, k2DRls, I::one_line_with_comment},
    {"DKDKL", 2, kTitle2D, kData2D, k2DRls, I::one_line_with_comment},
    {"CLJCx", 2, kTitle2D, kData2D, k2D, I::one_line_with_comment},
    {"PTPT2", 2, kTitle2D, kData2D, k2D, I::one_line_with_comment},
    {"P2P2L", 2, kTitle2D, kData2D, k2DGap, I::one_line_with_comment},
    {"CLALp", 2, kTitleSegment, kDataCLALp, k2D, I::one_line_with_comment},
    {"DKALp", 2, kTitleDKALp, kDataDKALp, k2D, I::one_line_with_comment},
    {"DKPLx", 2, kTitleDKPLx, kDataDKPLx, k2D, I::one_line_with_comment},
    {"PLJCx", 2, kTitleVertex, kDataPLJCx, k2D, I::one_line_with_comment},
    {"PLPLx", 2, kTitlePLPLx, kDataPLPLx, k2D, I::one_line_with_comment},
    {"PLALp", 2, kTitleVertex, kDataPLALp, k2D, I::one_line_with_comment},
    // 3D (contact_3D)
    {"PRPRx", 3, kTitle3D, kDataPRPRx, kPRPR, I::one_line_with_comment},
    {"PRPLx", 3, kTitle3D, kDataPRPRx, kPRPL, I::one_line_with_comment},
    {"PRASp", 3, kTitle3D, kDataPRPRx, kPRPL, I::one_line_with_comment},
    {"SPSPx", 3, kTitle3D, kDataSPSPx, kSPSP, I::one_line_with_comment},
    {"SPPLx", 3, kTitle3D, kDataCDPLx, kSPSP, I::one_line_with_comment},  // no trailing iantac (reference files)
    {"CDCDx", 3, kTitle3D, kDataSPSPx, kSPSP, I::one_line_with_comment},
    {"CDPLx", 3, kTitle3D, kDataCDPLx, kSPSP, I::one_line_with_comment},
    {"SPCDx", 3, kTitle3D, kDataSPSPx, kSPCD, I::one_line_with_comment},
    {"SPDCx", 3, kTitle3D, kDataSPSPx, kSPCD, I::one_line_with_comment},
    {"SPPRx", 3, kTitle3DShort, kData3DShort, kPRPR, I::one_line_with_comment},
    {"CSASx", 3, kTitle3DShort, kData3DShort, kPRPL, I::one_line_with_comment},
    {"CSPRx", 3, kTitle3DShort, kData3DShort, kPRPL, I::one_line_with_comment},
    {"PTPT3", 3, kTitle2D, kData2D, kPTPT3, I::one_line_with_comment},
};

}  // namespace

std::span<const InteractionKind> interaction_catalogue() { return kKinds; }

const InteractionKind* find_interaction_kind(std::string_view type) {
  auto it = std::find_if(std::begin(kKinds), std::end(kKinds), [&](const InteractionKind& k) { return k.type == type; });
  return it == std::end(kKinds) ? nullptr : &*it;
}

}  // namespace lmgc::grammar
