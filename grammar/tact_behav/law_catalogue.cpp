#include "grammar/tact_behav/law_catalogue.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace lmgc::grammar {
namespace {

// Rows transcribed from LMGC90's reader (read_xxx_tact_behav), writer (write_xxx_tact_behav)
// and info table (tact_behav_info_by_id), src/Core/shared/mod_tact_behav.f90; ids from
// mod_parameters.f90. docs/lmgc90-facts/contact-laws.md §0. Parameter names keep their 5 columns
// ("cn   "), internal names their 14 (or 11) columns, as LMGC90 prints them.
// Quirks reproduced on purpose (see each row's `quirk` text):
//   PERIO_DOF        reads the same field three times (reads {0,1,0},{0,1,1},{0,1,2});
//   ELASTIC_WET_NT   reads the 3rd pair from the 2nd line again;
//   LJ_POTENTIAL     reads the 4th pair from the 3rd line again;
//   IQS_BW_CLB       reads 7 values for 6 allocated (LMGC90 then stops on the count);
//   IQS_SGR_CLB_WEAR reads 4 values for 3 allocated (LMGC90 loses the 4th).
// 1 IQS_CLB
constexpr std::string_view kIQSCLBParameters[] = {"sfric"};
constexpr LawField kIQSCLBReads[] = {{0, 1, 0}};
constexpr LawField kIQSCLBWrites[] = {{0, 1, 0}};
// 2 IQS_CLB_nosldt
constexpr std::string_view kIQSCLBNosldtParameters[] = {"sfric", "dt___"};
constexpr LawField kIQSCLBNosldtReads[] = {{0, 2, 0}};
constexpr LawField kIQSCLBNosldtWrites[] = {{0, 2, 0}};
constexpr InternalSlot kIQSCLBNosldtInternals2D[] = {{2, "saut_de_ut    "}};
constexpr InternalSlot kIQSCLBNosldtInternals3D[] = {{2, "saut_de_ut    "}};
// 3 IQS_CLB_noslds
constexpr std::string_view kIQSCLBNosldsParameters[] = {"sfric", "ds___"};
constexpr LawField kIQSCLBNosldsReads[] = {{0, 2, 0}};
constexpr LawField kIQSCLBNosldsWrites[] = {{0, 2, 0}};
constexpr InternalSlot kIQSCLBNosldsInternals2D[] = {{2, "saut_de_us    "}};
constexpr InternalSlot kIQSCLBNosldsInternals3D[] = {{2, "saut_de_us    "}};
// 4 IQS_CLB_RGR
constexpr std::string_view kIQSCLBRGRParameters[] = {"T/H  ", "gTot ", "sfric"};
constexpr LawField kIQSCLBRGRReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kIQSCLBRGRWrites[] = {{0, 2, 0}, {1, 1, 2}};
// 5 IQS_DS_CLB
constexpr std::string_view kIQSDSCLBParameters[] = {"dfric", "sfric"};
constexpr LawField kIQSDSCLBReads[] = {{0, 2, 0}};
constexpr LawField kIQSDSCLBWrites[] = {{0, 2, 0}};
// 6 IQS_WET_DS_CLB
constexpr std::string_view kIQSWETDSCLBParameters[] = {"cohen", "cohet", "Wethk", "dfric", "sfric"};
constexpr LawField kIQSWETDSCLBReads[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
constexpr LawField kIQSWETDSCLBWrites[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
// 7 postGAP_IQS_MAC_CZM
constexpr std::string_view kPostGAPIQSMACCZMParameters[] = {"dfric", "sfric", "cn   ",
                                                            "ct   ", "visco", "dupre"};
constexpr LawField kPostGAPIQSMACCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kPostGAPIQSMACCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kPostGAPIQSMACCZMInternals2D[] = {
    {2, "taille_ele    "}, {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "beta          "}};
// 8 PLASTIC_COUPLED_DOF
constexpr std::string_view kPLASTICCOUPLEDDOFParameters[] = {"sfric"};
constexpr LawField kPLASTICCOUPLEDDOFReads[] = {{0, 1, 0}};
constexpr LawField kPLASTICCOUPLEDDOFWrites[] = {{0, 1, 0}};
// 9 xQS_WET_DS_CLB
constexpr std::string_view kXQSWETDSCLBParameters[] = {"cohen", "cohet", "Wethk", "dfric", "sfric"};
constexpr LawField kXQSWETDSCLBReads[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
constexpr LawField kXQSWETDSCLBWrites[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
// 10 TEX_SOL
constexpr std::string_view kTEXSOLParameters[] = {"sfric"};
constexpr LawField kTEXSOLReads[] = {{0, 1, 0}};
constexpr LawField kTEXSOLWrites[] = {{0, 1, 0}};
// 11 TEX_SOL_UNILAT
constexpr std::span<const std::string_view> kTEXSOLUNILATParameters;
constexpr std::span<const LawField> kTEXSOLUNILATReads;
constexpr std::span<const LawField> kTEXSOLUNILATWrites;
constexpr InternalSlot kTEXSOLUNILATInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kTEXSOLUNILATInternals3D[] = {{2, "gapREF        "}};
// 12 GAP_SGR_CLB
constexpr std::string_view kGAPSGRCLBParameters[] = {"sfric"};
constexpr LawField kGAPSGRCLBReads[] = {{0, 1, 0}};
constexpr LawField kGAPSGRCLBWrites[] = {{0, 1, 0}};
constexpr InternalSlot kGAPSGRCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kGAPSGRCLBInternals3D[] = {{2, "taille_ele    "}};
// 13 VEL_SGR_CLB
constexpr std::string_view kVELSGRCLBParameters[] = {"sfric"};
constexpr LawField kVELSGRCLBReads[] = {{0, 1, 0}};
constexpr LawField kVELSGRCLBWrites[] = {{0, 1, 0}};
constexpr InternalSlot kVELSGRCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kVELSGRCLBInternals3D[] = {{2, "taille_ele    "}};
// 14 GAP_WET_DS_CLB
constexpr std::string_view kGAPWETDSCLBParameters[] = {"cohen", "cohet", "Wethk", "dfric", "sfric"};
constexpr LawField kGAPWETDSCLBReads[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
constexpr LawField kGAPWETDSCLBWrites[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}};
constexpr InternalSlot kGAPWETDSCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kGAPWETDSCLBInternals3D[] = {{2, "taille_ele    "}};
// 15 MSMP_CZM
constexpr std::string_view kMSMPCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "visco", "dupre"};
constexpr LawField kMSMPCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kMSMPCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kMSMPCZMInternals2D[] = {{2, "taille_ele    "},
                                                {17, "saut_de_ut    "},
                                                {32, "saut_de_un    "},
                                                {47, "beta          "},
                                                {62, "TPSini        "}};
// 16 GAP_SGR_DS_CLB
constexpr std::string_view kGAPSGRDSCLBParameters[] = {"dfric", "sfric"};
constexpr LawField kGAPSGRDSCLBReads[] = {{0, 2, 0}};
constexpr LawField kGAPSGRDSCLBWrites[] = {{0, 2, 0}};
constexpr InternalSlot kGAPSGRDSCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kGAPSGRDSCLBInternals3D[] = {{2, "taille_ele    "}};
// 17 VEL_SGR_DS_CLB
constexpr std::string_view kVELSGRDSCLBParameters[] = {"dfric", "sfric"};
constexpr LawField kVELSGRDSCLBReads[] = {{0, 2, 0}};
constexpr LawField kVELSGRDSCLBWrites[] = {{0, 2, 0}};
constexpr InternalSlot kVELSGRDSCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kVELSGRDSCLBInternals3D[] = {{2, "taille_ele    "}};
// 18 RST_CLB
constexpr std::string_view kRSTCLBParameters[] = {"restn", "restt", "sfric"};
constexpr LawField kRSTCLBReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kRSTCLBWrites[] = {{0, 2, 0}, {1, 1, 2}};
// 19 RST_DS_CLB
constexpr std::string_view kRSTDSCLBParameters[] = {"restn", "restt", "dfric", "sfric"};
constexpr LawField kRSTDSCLBReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kRSTDSCLBWrites[] = {{0, 2, 0}, {1, 2, 2}};
// 20 IQS_MOHR_DS_CLB
constexpr std::string_view kIQSMOHRDSCLBParameters[] = {"cohen", "cohet", "dfric", "sfric"};
constexpr LawField kIQSMOHRDSCLBReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kIQSMOHRDSCLBWrites[] = {{0, 2, 0}, {1, 2, 2}};
// 21 MAL_CZM
constexpr std::string_view kMALCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                  "S1   ", "S2   ", "G1   ", "G2   "};
constexpr LawField kMALCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr LawField kMALCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr InternalSlot kMALCZMInternals2D[] = {{2, "taille_ele    "},
                                               {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "},
                                               {47, "beta          "},
                                               {62, "TPSini        "}};
constexpr InternalSlot kMALCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                               {62, "beta          "}, {77, "TPSini        "}};
// 22 ELASTIC_REPELL_CLB
constexpr std::string_view kELASTICREPELLCLBParameters[] = {"F/gap", "sfric"};
constexpr LawField kELASTICREPELLCLBReads[] = {{0, 1, 0}, {1, 1, 1}};
constexpr LawField kELASTICREPELLCLBWrites[] = {{0, 1, 0}, {1, 1, 1}};
// 23 CRITICAL_VOIGT_CLB
constexpr std::string_view kCRITICALVOIGTCLBParameters[] = {"T/H  ", "v/cv ", "sfric"};
constexpr LawField kCRITICALVOIGTCLBReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kCRITICALVOIGTCLBWrites[] = {{0, 2, 0}, {1, 1, 2}};
constexpr InternalSlot kCRITICALVOIGTCLBInternals2D[] = {
    {2, "lagT          "}, {17, "CVC on = 2    "}, {32, "lagS          "}};
constexpr InternalSlot kCRITICALVOIGTCLBInternals3D[] = {
    {2, "lagT          "}, {17, "CVC on = 2    "}, {32, "lagS          "}};
// 24 ELASTIC_REPELL_WET_CLB
constexpr std::string_view kELASTICREPELLWETCLBParameters[] = {"F/gap", "cohen", "Wethk", "sfric"};
constexpr LawField kELASTICREPELLWETCLBReads[] = {{0, 1, 0}, {1, 2, 1}, {2, 1, 3}};
constexpr LawField kELASTICREPELLWETCLBWrites[] = {{0, 1, 0}, {1, 2, 1}, {2, 1, 3}};
// 25 ELASTIC_ROD
constexpr std::string_view kELASTICRODParameters[] = {"F/str", "prstr"};
constexpr LawField kELASTICRODReads[] = {{0, 2, 0}};
constexpr LawField kELASTICRODWrites[] = {{0, 2, 0}};
constexpr InternalSlot kELASTICRODInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kELASTICRODInternals3D[] = {{2, "gapREF        "}};
// 26 VOIGT_ROD
constexpr std::string_view kVOIGTRODParameters[] = {"F/str", "prstr", "F/sra"};
constexpr LawField kVOIGTRODReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kVOIGTRODWrites[] = {{0, 2, 0}, {1, 1, 2}};
constexpr InternalSlot kVOIGTRODInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kVOIGTRODInternals3D[] = {{2, "gapREF        "}};
// 27 ELASTIC_WIRE
constexpr std::string_view kELASTICWIREParameters[] = {"F/str", "prstr"};
constexpr LawField kELASTICWIREReads[] = {{0, 2, 0}};
constexpr LawField kELASTICWIREWrites[] = {{0, 2, 0}};
constexpr InternalSlot kELASTICWIREInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kELASTICWIREInternals3D[] = {{2, "gapREF        "}};
// 28 VOIGT_WIRE
constexpr std::string_view kVOIGTWIREParameters[] = {"F/str", "prstr", "F/sra"};
constexpr LawField kVOIGTWIREReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kVOIGTWIREWrites[] = {{0, 2, 0}, {1, 1, 2}};
constexpr InternalSlot kVOIGTWIREInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kVOIGTWIREInternals3D[] = {{2, "gapREF        "}};
// 29 MD_JKRs
constexpr std::string_view kMDJKRsParameters[] = {"kn   ", "kt   ", "dampn", "gamma", "sfric"};
constexpr LawField kMDJKRsReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
constexpr LawField kMDJKRsWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
// 30 ELASTIC_WET_NT
constexpr std::string_view kELASTICWETNTParameters[] = {"kn   ", "kt   ", "dampn", "dampt", "adhen", "adhet"};
constexpr LawField kELASTICWETNTReads[] = {{0, 2, 0}, {1, 2, 2}, {1, 2, 4}};
constexpr LawField kELASTICWETNTWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kELASTICWETNTInternals2D[] = {
    {2, "Ix ini        "}, {17, "Iy ini        "}, {32, "Iz ini        "}};
constexpr InternalSlot kELASTICWETNTInternals3D[] = {
    {2, "Ix ini        "}, {17, "Iy ini        "}, {32, "Iz ini        "}};
// 31 COUPLED_DOF
constexpr std::span<const std::string_view> kCOUPLEDDOFParameters;
constexpr std::span<const LawField> kCOUPLEDDOFReads;
constexpr std::span<const LawField> kCOUPLEDDOFWrites;
// 32 TANGENTIAL_COUPLED_DOF
constexpr std::span<const std::string_view> kTANGENTIALCOUPLEDDOFParameters;
constexpr std::span<const LawField> kTANGENTIALCOUPLEDDOFReads;
constexpr std::span<const LawField> kTANGENTIALCOUPLEDDOFWrites;
// 33 NORMAL_COUPLED_DOF
constexpr std::span<const std::string_view> kNORMALCOUPLEDDOFParameters;
constexpr std::span<const LawField> kNORMALCOUPLEDDOFReads;
constexpr std::span<const LawField> kNORMALCOUPLEDDOFWrites;
// 34 PERIO_DOF
constexpr std::string_view kPERIODOFParameters[] = {"E_XX ", "E_YY ", "E_XY "};
constexpr LawField kPERIODOFReads[] = {{0, 1, 0}, {0, 1, 1}, {0, 1, 2}};
constexpr LawField kPERIODOFWrites[] = {{0, 1, 0}, {1, 1, 1}, {2, 1, 2}};
// 35 GAP_SGR_CLB_WEAR
constexpr std::string_view kGAPSGRCLBWEARParameters[] = {"kcdwe", "kanwe", "fric "};
constexpr LawField kGAPSGRCLBWEARReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kGAPSGRCLBWEARWrites[] = {{0, 2, 0}, {1, 1, 2}};
constexpr InternalSlot kGAPSGRCLBWEARInternals2D[] = {
    {2, "       ?????  "}, {17, "       ?????  "}, {32, "       ?????  "}};
constexpr InternalSlot kGAPSGRCLBWEARInternals3D[] = {
    {2, "       ?????  "}, {17, "       ?????  "}, {32, "       ?????  "}};
// 36 IQS_SGR_CLB_WEAR
constexpr std::string_view kIQSSGRCLBWEARParameters[] = {"scohe", "dcohe", "fric ", "Wethk"};
constexpr LawField kIQSSGRCLBWEARReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kIQSSGRCLBWEARWrites[] = {{0, 2, 0}, {1, 2, 2}};
constexpr InternalSlot kIQSSGRCLBWEARInternals2D[] = {
    {2, "       ?????  "}, {17, "       ?????  "}, {32, "       ?????  "}};
constexpr InternalSlot kIQSSGRCLBWEARInternals3D[] = {
    {2, "       ?????  "}, {17, "       ?????  "}, {32, "       ?????  "}};
// 37 MAC_CZM
constexpr std::string_view kMACCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "visco", "dupre"};
constexpr LawField kMACCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kMACCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kMACCZMInternals2D[] = {{2, "taille_ele    "},
                                               {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "},
                                               {47, "beta          "},
                                               {62, "TPSini        "}};
constexpr InternalSlot kMACCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                               {62, "beta          "}, {77, "TPSini        "}};
// 38 IQS_MAC_CZM
constexpr std::string_view kIQSMACCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "visco", "dupre"};
constexpr LawField kIQSMACCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kIQSMACCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kIQSMACCZMInternals2D[] = {{2, "taille_ele    "},
                                                  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "},
                                                  {47, "beta          "},
                                                  {62, "TPSini        "}};
constexpr InternalSlot kIQSMACCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                  {62, "beta          "}, {77, "TPSini        "}};
// 39 WET_CZM
constexpr std::span<const std::string_view> kWETCZMParameters;
constexpr std::span<const LawField> kWETCZMReads;
constexpr std::span<const LawField> kWETCZMWrites;
// 40 GAP_MOHR_DS_CLB
constexpr std::string_view kGAPMOHRDSCLBParameters[] = {"cohen", "cohet", "dfric", "sfric"};
constexpr LawField kGAPMOHRDSCLBReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kGAPMOHRDSCLBWrites[] = {{0, 2, 0}, {1, 2, 2}};
// 41 MAC_CZM_nosldt
constexpr std::string_view kMACCZMNosldtParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                        "visco", "dupre", "dt___"};
constexpr LawField kMACCZMNosldtReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr LawField kMACCZMNosldtWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr InternalSlot kMACCZMNosldtInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                     {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                     {62, "beta          "}, {77, "TPSini        "}};
// 42 MAC_CZM_noslds
constexpr std::string_view kMACCZMNosldsParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                        "visco", "dupre", "ds___"};
constexpr LawField kMACCZMNosldsReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr LawField kMACCZMNosldsWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr InternalSlot kMACCZMNosldsInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                     {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                     {62, "beta          "}, {77, "TPSini        "}};
// 43 IQS_MAC_CZM_nosldt
constexpr std::string_view kIQSMACCZMNosldtParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                           "visco", "dupre", "dt___"};
constexpr LawField kIQSMACCZMNosldtReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr LawField kIQSMACCZMNosldtWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr InternalSlot kIQSMACCZMNosldtInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                        {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                        {62, "beta          "}, {77, "TPSini        "}};
// 44 IQS_MAC_CZM_noslds
constexpr std::string_view kIQSMACCZMNosldsParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                           "visco", "dupre", "ds___"};
constexpr LawField kIQSMACCZMNosldsReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr LawField kIQSMACCZMNosldsWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr InternalSlot kIQSMACCZMNosldsInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                        {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                        {62, "beta          "}, {77, "TPSini        "}};
// 45 ER_MAC_CZM
constexpr std::string_view kERMACCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "visco", "dupre"};
constexpr LawField kERMACCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kERMACCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kERMACCZMInternals2D[] = {
    {2, "taille_ele    "}, {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "beta          "}};
constexpr InternalSlot kERMACCZMInternals3D[] = {{2, "taille_ele    "},
                                                 {17, "saut_de_ut    "},
                                                 {32, "saut_de_un    "},
                                                 {47, "saut_de_us    "},
                                                 {62, "beta          "}};
// 46 IQS_WET_CZM
constexpr std::string_view kIQSWETCZMParameters[] = {"cohen", "Wethk", "cn   ", "ct   ", "visco", "dupre"};
constexpr LawField kIQSWETCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kIQSWETCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kIQSWETCZMInternals2D[] = {{2, "taille_ele    "},
                                                  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "},
                                                  {47, "beta          "},
                                                  {62, "Cnd anisotrope"}};
constexpr InternalSlot kIQSWETCZMInternals3D[] = {{2, "taille_ele    "},
                                                  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "},
                                                  {47, "beta          "},
                                                  {62, "Cnd anisotrope"}};
// 47 DEM_FIBs
constexpr std::string_view kDEMFIBsParameters[] = {"kn   ", "dampn", "gamma"};
constexpr LawField kDEMFIBsReads[] = {{0, 1, 0}, {1, 2, 1}};
constexpr LawField kDEMFIBsWrites[] = {{0, 1, 0}, {1, 2, 1}};
constexpr InternalSlot kDEMFIBsInternals2D[] = {{2, "status        "},
                                                {17, "gapREF        "},
                                                {32, "I0_x          "},
                                                {47, "I0_y          "},
                                                {62, "I0_z          "}};
constexpr InternalSlot kDEMFIBsInternals3D[] = {{2, "status        "},
                                                {17, "gapREF        "},
                                                {32, "I0_x          "},
                                                {47, "I0_y          "},
                                                {62, "I0_z          "}};
// 48 KV_WET
constexpr std::string_view kKVWETParameters[] = {"F/str", "F/sra", "cohen", "Wethk"};
constexpr LawField kKVWETReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kKVWETWrites[] = {{0, 2, 0}, {1, 2, 2}};
constexpr InternalSlot kKVWETInternals2D[] = {
    {2, "       Status "}, {17, "       GapREF "}, {32, "       Length "}};
constexpr InternalSlot kKVWETInternals3D[] = {
    {2, "       Status "}, {17, "       GapREF "}, {32, "       Length "}};
// 49 VISCO_ELASTIC_REPELL_WET
constexpr std::string_view kVISCOELASTICREPELLWETParameters[] = {"F/gap", "F/sra", "cohen", "Wethk", "fric "};
constexpr LawField kVISCOELASTICREPELLWETReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
constexpr LawField kVISCOELASTICREPELLWETWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
// 50 RIGID_WIRE
constexpr std::span<const std::string_view> kRIGIDWIREParameters;
constexpr std::span<const LawField> kRIGIDWIREReads;
constexpr std::span<const LawField> kRIGIDWIREWrites;
constexpr InternalSlot kRIGIDWIREInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kRIGIDWIREInternals3D[] = {{2, "gapREF        "}};
// 51 IQS_BW_CLB
constexpr std::string_view kIQSBWCLBParameters[] = {"Afric", "Bfric", "Atsld", "Btsld",
                                                    "Alpha", "VtTsh", "CFreq"};
constexpr LawField kIQSBWCLBReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr LawField kIQSBWCLBWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 1, 6}};
constexpr InternalSlot kIQSBWCLBInternals2D[] = {{2, "cycle number  "}, {17, "              "}};
constexpr InternalSlot kIQSBWCLBInternals3D[] = {{2, "cycle number  "}, {17, "              "}};
// 52 IQS_CAP_MOHR_DS_CLB
constexpr std::string_view kIQSCAPMOHRDSCLBParameters[] = {"cohen", "cohet", "dfric",
                                                           "sfric", "s_ten", "s_com"};
constexpr LawField kIQSCAPMOHRDSCLBReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kIQSCAPMOHRDSCLBWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
// 53 IQS_MAL_CZM
constexpr std::string_view kIQSMALCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                     "S1   ", "S2   ", "G1   ", "G2   "};
constexpr LawField kIQSMALCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr LawField kIQSMALCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr InternalSlot kIQSMALCZMInternals2D[] = {
    {2, "taille_ele    "}, {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "beta          "}};
constexpr InternalSlot kIQSMALCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                  {62, "beta          "}, {77, "TPSini        "}};
// 54 GAP_CAP_MOHR_DS_CLB
constexpr std::string_view kGAPCAPMOHRDSCLBParameters[] = {"cohen", "cohet", "dfric",
                                                           "sfric", "s_ten", "s_com"};
constexpr LawField kGAPCAPMOHRDSCLBReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kGAPCAPMOHRDSCLBWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
// 55 BROKEN_DOF
constexpr std::string_view kBROKENDOFParameters[] = {"thshd"};
constexpr LawField kBROKENDOFReads[] = {{0, 1, 0}};
constexpr LawField kBROKENDOFWrites[] = {{0, 1, 0}};
constexpr InternalSlot kBROKENDOFInternals2D[] = {{2, "       status "}};
constexpr InternalSlot kBROKENDOFInternals3D[] = {{2, "       status "}};
// 56 IQS_CLB_g0
constexpr std::string_view kIQSCLBG0Parameters[] = {"sfric"};
constexpr LawField kIQSCLBG0Reads[] = {{0, 1, 0}};
constexpr LawField kIQSCLBG0Writes[] = {{0, 1, 0}};
constexpr InternalSlot kIQSCLBG0Internals2D[] = {{2, "g_ref         "}};
constexpr InternalSlot kIQSCLBG0Internals3D[] = {{2, "g_ref         "}};
// 57 IQS_MAP
constexpr std::string_view kIQSMAPParameters[] = {"sfric"};
constexpr LawField kIQSMAPReads[] = {{0, 1, 0}};
constexpr LawField kIQSMAPWrites[] = {{0, 1, 0}};
constexpr InternalSlot kIQSMAPInternals2D[] = {{2, "fric          "}};
constexpr InternalSlot kIQSMAPInternals3D[] = {{2, "fric          "}};
// 58 RST_WET_CLB
constexpr std::string_view kRSTWETCLBParameters[] = {"cohen", "cohet", "restn", "restt",
                                                     "Wethk", "dfric", "sfric"};
constexpr LawField kRSTWETCLBReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}, {3, 2, 5}};
constexpr LawField kRSTWETCLBWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}, {3, 2, 5}};
// 59 LJ_POTENTIAL
constexpr std::string_view kLJPOTENTIALParameters[] = {"sigma", "epsil", "elect", "noycd",
                                                       "noyan", "radcd", "radan"};
constexpr LawField kLJPOTENTIALReads[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}, {2, 2, 5}};
constexpr LawField kLJPOTENTIALWrites[] = {{0, 2, 0}, {1, 1, 2}, {2, 2, 3}, {3, 2, 5}};
// 60 GAP_SGR_CLB_g0
constexpr std::string_view kGAPSGRCLBG0Parameters[] = {"sfric"};
constexpr LawField kGAPSGRCLBG0Reads[] = {{0, 1, 0}};
constexpr LawField kGAPSGRCLBG0Writes[] = {{0, 1, 0}};
constexpr InternalSlot kGAPSGRCLBG0Internals2D[] = {{2, "taille_ele    "}, {17, "g_ref         "}};
constexpr InternalSlot kGAPSGRCLBG0Internals3D[] = {{2, "taille_ele    "}, {17, "g_ref         "}};
// 61 BRITTLE_ELASTIC_WIRE
constexpr std::string_view kBRITTLEELASTICWIREParameters[] = {"F/str", "prstr", "snmax"};
constexpr LawField kBRITTLEELASTICWIREReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kBRITTLEELASTICWIREWrites[] = {{0, 2, 0}, {1, 1, 2}};
constexpr InternalSlot kBRITTLEELASTICWIREInternals2D[] = {{2, "gapREF        "}};
constexpr InternalSlot kBRITTLEELASTICWIREInternals3D[] = {{2, "gapREF        "}};
// 62 ELASTIC_REPELL_CLB_g0
constexpr std::string_view kELASTICREPELLCLBG0Parameters[] = {"F/gap", "sfric"};
constexpr LawField kELASTICREPELLCLBG0Reads[] = {{0, 1, 0}, {1, 1, 1}};
constexpr LawField kELASTICREPELLCLBG0Writes[] = {{0, 1, 0}, {1, 1, 1}};
constexpr InternalSlot kELASTICREPELLCLBG0Internals2D[] = {{2, "g_ref         "}};
constexpr InternalSlot kELASTICREPELLCLBG0Internals3D[] = {{2, "g_ref         "}};
// 63 MP_CZM
constexpr std::string_view kMPCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "dupre"};
constexpr LawField kMPCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
constexpr LawField kMPCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 1, 4}};
constexpr InternalSlot kMPCZMInternals2D[] = {{2, "taille_ele    "},
                                              {17, "saut_de_ut    "},
                                              {32, "saut_de_un    "},
                                              {47, "beta          "},
                                              {62, "TPSini        "}};
constexpr InternalSlot kMPCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                              {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                              {62, "beta          "}, {77, "TPSini        "}};
// 64 MP3_CZM
constexpr std::string_view kMP3CZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "smax ", "dupre"};
constexpr LawField kMP3CZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kMP3CZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kMP3CZMInternals2D[] = {{2, "taille_ele    "},
                                               {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "},
                                               {47, "beta          "},
                                               {62, "TPSini        "}};
constexpr InternalSlot kMP3CZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                               {62, "beta          "}, {77, "TPSini        "}};
// 65 MP3_CZM_THER
constexpr std::string_view kMP3CZMTHERParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                      "smax ", "dupre", "lmbds", "lmbdc"};
constexpr LawField kMP3CZMTHERReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr LawField kMP3CZMTHERWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}};
constexpr InternalSlot kMP3CZMTHERInternals2D[] = {{2, "taille_ele    "},
                                                   {17, "saut_de_ut    "},
                                                   {32, "saut_de_un    "},
                                                   {47, "beta          "},
                                                   {62, "TPSini        "}};
constexpr InternalSlot kMP3CZMTHERInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                   {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                   {62, "beta          "}, {77, "TPSini        "}};
// 66 TH_CZM
constexpr std::string_view kTHCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "s1   ",
                                                 "s2   ", "G1   ", "G2   ", "l1   ", "l2   "};
constexpr LawField kTHCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr LawField kTHCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr InternalSlot kTHCZMInternals2D[] = {{2, "taille_ele    "},
                                              {17, "saut_de_ut    "},
                                              {32, "saut_de_un    "},
                                              {47, "beta          "},
                                              {62, "TPSini        "}};
constexpr InternalSlot kTHCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                              {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                              {62, "beta          "}, {77, "TPSini        "}};
// 67 IQS_TH_CZM
constexpr std::string_view kIQSTHCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "s1   ",
                                                    "s2   ", "G1   ", "G2   ", "l1   ", "l2   "};
constexpr LawField kIQSTHCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr LawField kIQSTHCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr InternalSlot kIQSTHCZMInternals2D[] = {{2, "taille_ele    "},
                                                 {17, "saut_de_ut    "},
                                                 {32, "saut_de_un    "},
                                                 {47, "beta          "},
                                                 {62, "TPSini        "}};
constexpr InternalSlot kIQSTHCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                 {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                 {62, "beta          "}, {77, "TPSini        "}};
// 68 postGAP_IQS_CZM
constexpr std::span<const std::string_view> kPostGAPIQSCZMParameters;
constexpr std::span<const LawField> kPostGAPIQSCZMReads;
constexpr std::span<const LawField> kPostGAPIQSCZMWrites;
// 69 WET_3C
constexpr std::span<const std::string_view> kWET3CParameters;
constexpr std::span<const LawField> kWET3CReads;
constexpr std::span<const LawField> kWET3CWrites;
// 70 VISCO_ELASTIC_REPELL_CLB
constexpr std::string_view kVISCOELASTICREPELLCLBParameters[] = {"F/gap", "etan ", "sfric"};
constexpr LawField kVISCOELASTICREPELLCLBReads[] = {{0, 2, 0}, {1, 1, 2}};
constexpr LawField kVISCOELASTICREPELLCLBWrites[] = {{0, 2, 0}, {1, 1, 2}};
// 71 ELASTIC_REPELL_MAC_CZM
constexpr std::string_view kELASTICREPELLMACCZMParameters[] = {"F/gap", "gcmax", "cn   ",
                                                               "ct   ", "visco", "dupre"};
constexpr LawField kELASTICREPELLMACCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kELASTICREPELLMACCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kELASTICREPELLMACCZMInternals2D[] = {
    {2, "taille_ele    "}, {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "beta          "}};
constexpr InternalSlot kELASTICREPELLMACCZMInternals3D[] = {
    {2, "taille_ele    "}, {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "beta          "}};
// 72 IQS_PLAS_CLB
constexpr std::string_view kIQSPLASCLBParameters[] = {"rnmax", "rovrg", "sfric", "pfric", "dgap ", "dfric"};
constexpr LawField kIQSPLASCLBReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr LawField kIQSPLASCLBWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}};
constexpr InternalSlot kIQSPLASCLBInternals2D[] = {
    {2, "pgap          "}, {17, "pfric         "}, {32, "pgap max      "}};
constexpr InternalSlot kIQSPLASCLBInternals3D[] = {
    {2, "pgap          "}, {17, "pfric         "}, {32, "pgap max      "}};
// 73 ABP_CZM
constexpr std::string_view kABPCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ", "S2   ",
                                                  "G1   ", "G2   ", "Du1  ", "Du2  ", "Phi  "};
constexpr LawField kABPCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}, {5, 1, 10}};
constexpr LawField kABPCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}, {5, 1, 10}};
constexpr InternalSlot kABPCZMInternals2D[] = {{2, "taille_ele    "},
                                               {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "},
                                               {47, "beta          "},
                                               {62, "TPSini        "}};
constexpr InternalSlot kABPCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                               {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                               {62, "beta          "}, {77, "TPSini        "}};
// 74 IQS_ABP_CZM
constexpr std::string_view kIQSABPCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ", "S2   ",
                                                     "G1   ", "G2   ", "Du1  ", "Du2  ", "Phi  "};
constexpr LawField kIQSABPCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}, {5, 1, 10}};
constexpr LawField kIQSABPCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}, {5, 1, 10}};
constexpr InternalSlot kIQSABPCZMInternals2D[] = {{2, "taille_ele    "},
                                                  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "},
                                                  {47, "beta          "},
                                                  {62, "TPSini        "}};
constexpr InternalSlot kIQSABPCZMInternals3D[] = {{2, "taille_ele    "},  {17, "saut_de_ut    "},
                                                  {32, "saut_de_un    "}, {47, "saut_de_us    "},
                                                  {62, "beta          "}, {77, "TPSini        "}};
// 75 BRITTLE_COATING_CLB
constexpr std::string_view kBRITTLECOATINGCLBParameters[] = {"fric ", "F/gap", "snmax", "g0   "};
constexpr LawField kBRITTLECOATINGCLBReads[] = {{0, 1, 0}, {1, 1, 1}, {2, 1, 2}, {3, 1, 3}};
constexpr LawField kBRITTLECOATINGCLBWrites[] = {{0, 1, 0}, {1, 1, 1}, {2, 1, 2}, {3, 1, 3}};
// 76 IQS_STICK
constexpr std::span<const std::string_view> kIQSSTICKParameters;
constexpr std::span<const LawField> kIQSSTICKReads;
constexpr std::span<const LawField> kIQSSTICKWrites;
// 77 GAP_SGR_STICK
constexpr std::span<const std::string_view> kGAPSGRSTICKParameters;
constexpr std::span<const LawField> kGAPSGRSTICKReads;
constexpr std::span<const LawField> kGAPSGRSTICKWrites;
// 78 GAP_SGR_CLB_nosldt
constexpr std::string_view kGAPSGRCLBNosldtParameters[] = {"sfric", "dt___"};
constexpr LawField kGAPSGRCLBNosldtReads[] = {{0, 2, 0}};
constexpr LawField kGAPSGRCLBNosldtWrites[] = {{0, 2, 0}};
constexpr InternalSlot kGAPSGRCLBNosldtInternals2D[] = {{2, "saut_de_ut    "}};
constexpr InternalSlot kGAPSGRCLBNosldtInternals3D[] = {{2, "saut_de_ut    "}};
// 79 GAP_SGR_CLB_noslds
constexpr std::string_view kGAPSGRCLBNosldsParameters[] = {"sfric", "ds___"};
constexpr LawField kGAPSGRCLBNosldsReads[] = {{0, 2, 0}};
constexpr LawField kGAPSGRCLBNosldsWrites[] = {{0, 2, 0}};
constexpr InternalSlot kGAPSGRCLBNosldsInternals2D[] = {{2, "saut_de_us    "}};
constexpr InternalSlot kGAPSGRCLBNosldsInternals3D[] = {{2, "saut_de_us    "}};
// 80 preGAP_SGR_CLB
constexpr std::string_view kPreGAPSGRCLBParameters[] = {"pgap_", "sfric"};
constexpr LawField kPreGAPSGRCLBReads[] = {{0, 2, 0}};
constexpr LawField kPreGAPSGRCLBWrites[] = {{0, 2, 0}};
constexpr InternalSlot kPreGAPSGRCLBInternals2D[] = {{2, "taille_ele    "}};
constexpr InternalSlot kPreGAPSGRCLBInternals3D[] = {{2, "taille_ele    "}};
// 81 NARD_ROD
constexpr std::string_view kNARDRODParameters[] = {"E    ", "nu   ", "S1   ", "S2   "};
constexpr LawField kNARDRODReads[] = {{0, 2, 0}, {1, 2, 2}};
constexpr LawField kNARDRODWrites[] = {{0, 2, 0}, {1, 2, 2}};
constexpr InternalSlot kNARDRODInternals2D[] = {{2, "dn         "},  {14, "dt         "},
                                                {26, "ds         "}, {38, "surf       "},
                                                {50, "l0         "}, {62, "Masse      "}};
constexpr InternalSlot kNARDRODInternals3D[] = {{2, "dn         "},  {14, "dt         "},
                                                {26, "ds         "}, {38, "surf       "},
                                                {50, "l0         "}, {62, "Masse      "}};
// 82 IQS_EXPO_CZM
constexpr std::string_view kIQSEXPOCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ",
                                                      "S2   ", "G1   ", "G2   ", "eta  "};
constexpr LawField kIQSEXPOCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 1, 8}};
constexpr LawField kIQSEXPOCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 1, 8}};
constexpr InternalSlot kIQSEXPOCZMInternals2D[] = {{2, "taille_ele    "},
                                                   {17, "saut_de_ut    "},
                                                   {32, "saut_de_un    "},
                                                   {47, "beta          "},
                                                   {62, "TPSini        "}};
constexpr InternalSlot kIQSEXPOCZMInternals3D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "saut_de_us    "},
    {62, "beta          "}, {77, "TPSini        "}, {92, "g0            "}};
// 83 EXPO_CZM
constexpr std::string_view kEXPOCZMParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ",
                                                   "S2   ", "G1   ", "G2   ", "eta  "};
constexpr LawField kEXPOCZMReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 1, 8}};
constexpr LawField kEXPOCZMWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 1, 8}};
constexpr InternalSlot kEXPOCZMInternals2D[] = {{2, "taille_ele    "},
                                                {17, "saut_de_ut    "},
                                                {32, "saut_de_un    "},
                                                {47, "beta          "},
                                                {62, "TPSini        "}};
constexpr InternalSlot kEXPOCZMInternals3D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "}, {32, "saut_de_un    "}, {47, "saut_de_us    "},
    {62, "beta          "}, {77, "TPSini        "}, {92, "g0            "}};
// 84 IQS_EXPO_CZM_SPRING
constexpr std::string_view kIQSEXPOCZMSPRINGParameters[] = {
    "dfric", "sfric", "cn   ", "ct   ", "S1   ", "S2   ", "G1   ", "G2   ", "eta  ", "k1   ", "k2   "};
constexpr LawField kIQSEXPOCZMSPRINGReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                               {3, 2, 6}, {4, 1, 8}, {5, 2, 9}};
constexpr LawField kIQSEXPOCZMSPRINGWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                                {3, 2, 6}, {4, 1, 8}, {5, 2, 9}};
constexpr InternalSlot kIQSEXPOCZMSPRINGInternals2D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "},  {32, "saut_de_un    "},
    {47, "beta          "}, {62, "TPSini        "},  {77, "saut_de_ut_e  "},
    {92, "g0            "}, {107, "beta_coh_th   "}, {122, "beta_spring_th"}};
constexpr InternalSlot kIQSEXPOCZMSPRINGInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "}, {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "saut_de_ut_e  "}, {107, "saut_de_us_e  "},
    {122, "g0            "}, {137, "beta_coh_th   "}, {152, "beta_spring_th"}};
// 85 EXPO_CZM_SPRING
constexpr std::string_view kEXPOCZMSPRINGParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ", "S2   ",
                                                         "G1   ", "G2   ", "eta  ", "k1   ", "k2   "};
constexpr LawField kEXPOCZMSPRINGReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 1, 8}, {5, 2, 9}};
constexpr LawField kEXPOCZMSPRINGWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                             {3, 2, 6}, {4, 1, 8}, {5, 2, 9}};
constexpr InternalSlot kEXPOCZMSPRINGInternals2D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "},  {32, "saut_de_un    "},
    {47, "beta          "}, {62, "TPSini        "},  {77, "saut_de_ut_e  "},
    {92, "g0            "}, {107, "beta_coh_th   "}, {122, "beta_spring_th"}};
constexpr InternalSlot kEXPOCZMSPRINGInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "}, {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "saut_de_ut_e  "}, {107, "saut_de_us_e  "},
    {122, "g0            "}, {137, "beta_coh_th   "}, {152, "beta_spring_th"}};
// 86 IQS_EXPO_CZM_P
constexpr std::string_view kIQSEXPOCZMPParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ",
                                                       "S2   ", "G1   ", "G2   ", "mu_g ", "eta  "};
constexpr LawField kIQSEXPOCZMPReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr LawField kIQSEXPOCZMPWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr InternalSlot kIQSEXPOCZMPInternals2D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "},  {32, "saut_de_un    "},
    {47, "beta          "}, {62, "TPSini        "},  {77, "saut_de_ut_p  "},
    {92, "saut_de_un_p  "}, {107, "saut_de_ut_p1 "}, {122, "saut_de_un_p1 "}};
constexpr InternalSlot kIQSEXPOCZMPInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "g0            "},  {107, "saut_de_ut_p  "},
    {122, "saut_de_un_p  "}, {137, "saut_de_us_p  "}, {152, "saut_de_ut_p1 "}, {167, "saut_de_us_p1 "},
    {182, "saut_de_un_p1 "}};
// 87 EXPO_CZM_P
constexpr std::string_view kEXPOCZMPParameters[] = {"dfric", "sfric", "cn   ", "ct   ", "S1   ",
                                                    "S2   ", "G1   ", "G2   ", "mu_g ", "eta  "};
constexpr LawField kEXPOCZMPReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr LawField kEXPOCZMPWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4}, {3, 2, 6}, {4, 2, 8}};
constexpr InternalSlot kEXPOCZMPInternals2D[] = {
    {2, "taille_ele    "},  {17, "saut_de_ut    "},  {32, "saut_de_un    "},
    {47, "beta          "}, {62, "TPSini        "},  {77, "saut_de_ut_p  "},
    {92, "saut_de_un_p  "}, {107, "saut_de_ut_p1 "}, {122, "saut_de_un_p1 "}};
constexpr InternalSlot kEXPOCZMPInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "g0            "},  {107, "saut_de_ut_p  "},
    {122, "saut_de_un_p  "}, {137, "saut_de_us_p  "}, {152, "saut_de_ut_p1 "}, {167, "saut_de_us_p1 "},
    {182, "saut_de_un_p1 "}};
// 88 IQS_EXPO_CZM_SPRING_P
constexpr std::string_view kIQSEXPOCZMSPRINGPParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                             "S1   ", "S2   ", "G1   ", "G2   ",
                                                             "mu_g ", "eta  ", "k1   ", "k2   "};
constexpr LawField kIQSEXPOCZMSPRINGPReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                                {3, 2, 6}, {4, 2, 8}, {5, 2, 10}};
constexpr LawField kIQSEXPOCZMSPRINGPWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                                 {3, 2, 6}, {4, 2, 8}, {5, 2, 10}};
constexpr InternalSlot kIQSEXPOCZMSPRINGPInternals2D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "}, {47, "beta          "},
    {62, "TPSini        "},  {77, "saut_de_ut_e  "},  {92, "g0            "}, {107, "saut_de_ut_p  "},
    {122, "saut_de_un_p  "}, {137, "saut_de_ut_p1 "}, {152, "saut_de_un_p1 "}};
constexpr InternalSlot kIQSEXPOCZMSPRINGPInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "saut_de_ut_e  "},  {107, "saut_de_us_e  "},
    {122, "g0            "}, {137, "saut_de_ut_p  "}, {152, "saut_de_us_p  "}, {167, "saut_de_un_p  "},
    {182, "saut_de_ut_p1 "}, {197, "saut_de_us_p1 "}, {212, "saut_de_un_p1 "}};
// 89 EXPO_CZM_SPRING_P
constexpr std::string_view kEXPOCZMSPRINGPParameters[] = {"dfric", "sfric", "cn   ", "ct   ",
                                                          "S1   ", "S2   ", "G1   ", "G2   ",
                                                          "mu_g ", "eta  ", "k1   ", "k2   "};
constexpr LawField kEXPOCZMSPRINGPReads[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                             {3, 2, 6}, {4, 2, 8}, {5, 2, 10}};
constexpr LawField kEXPOCZMSPRINGPWrites[] = {{0, 2, 0}, {1, 2, 2}, {2, 2, 4},
                                              {3, 2, 6}, {4, 2, 8}, {5, 2, 10}};
constexpr InternalSlot kEXPOCZMSPRINGPInternals2D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "}, {47, "beta          "},
    {62, "TPSini        "},  {77, "saut_de_ut_e  "},  {92, "g0            "}, {107, "saut_de_ut_p  "},
    {122, "saut_de_un_p  "}, {137, "saut_de_ut_p1 "}, {152, "saut_de_un_p1 "}};
constexpr InternalSlot kEXPOCZMSPRINGPInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "TPSini        "},  {92, "saut_de_ut_e  "},  {107, "saut_de_us_e  "},
    {122, "g0            "}, {137, "saut_de_ut_p  "}, {152, "saut_de_us_p  "}, {167, "saut_de_un_p  "},
    {182, "saut_de_ut_p1 "}, {197, "saut_de_us_p1 "}, {212, "saut_de_un_p1 "}};
// 90 GTN_CZM
constexpr std::string_view kGTNCZMParameters[] = {"dyfr ", "stfr ", "cn   ", "ct   ", "f0   ", "fc   ",
                                                  "k    ", "q1   ", "q2   ", "e    ", "Y    ", "s0   ",
                                                  "Kh   ", "n    ", "fN   ", "eN   ", "sN   "};
constexpr LawField kGTNCZMReads[] = {{0, 2, 0},  {1, 2, 2},  {2, 2, 4},  {3, 2, 6}, {4, 2, 8},
                                     {5, 2, 10}, {6, 2, 12}, {7, 2, 14}, {8, 1, 16}};
constexpr LawField kGTNCZMWrites[] = {{0, 2, 0},  {1, 2, 2},  {2, 2, 4},  {3, 2, 6}, {4, 2, 8},
                                      {5, 2, 10}, {6, 2, 12}, {7, 2, 14}, {8, 1, 16}};
// 91 GTN2_CZM
constexpr std::string_view kGTN2CZMParameters[] = {"dyfr ", "stfr ", "cn   ", "ct   ", "f0   ", "fc   ",
                                                   "k    ", "q1   ", "q2   ", "e    ", "Y    ", "s0   ",
                                                   "Kh   ", "n    ", "fN   ", "eN   ", "sN   "};
constexpr LawField kGTN2CZMReads[] = {{0, 2, 0},  {1, 2, 2},  {2, 2, 4},  {3, 2, 6}, {4, 2, 8},
                                      {5, 2, 10}, {6, 2, 12}, {7, 2, 14}, {8, 1, 16}};
constexpr LawField kGTN2CZMWrites[] = {{0, 2, 0},  {1, 2, 2},  {2, 2, 4},  {3, 2, 6}, {4, 2, 8},
                                       {5, 2, 10}, {6, 2, 12}, {7, 2, 14}, {8, 1, 16}};
// 92 TOSI_CZM
constexpr std::string_view kTOSICZMParameters[] = {"dyfr ", "stfr ", "cn   ", "ct   ", "f0   ", "fc   ",
                                                   "n    ", "kcoal", "R    ", "s0   ", "Gc1  ", "Gc2  ",
                                                   "K    ", "hdef ", "n_mol", "Q    "};
constexpr LawField kTOSICZMReads[] = {{0, 2, 0}, {1, 2, 2},  {2, 2, 4},  {3, 2, 6},
                                      {4, 2, 8}, {5, 2, 10}, {6, 2, 12}, {7, 2, 14}};
constexpr LawField kTOSICZMWrites[] = {{0, 2, 0}, {1, 2, 2},  {2, 2, 4},  {3, 2, 6},
                                       {4, 2, 8}, {5, 2, 10}, {6, 2, 12}, {7, 2, 14}};
constexpr InternalSlot kTOSICZMInternals2D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "}, {47, "beta          "},
    {62, "saut_de_ut_max"},  {77, "saut_de_un_max"},  {92, "coalescence   "}, {107, "tris_coal     "},
    {122, "energy1       "}, {137, "energy2       "}, {152, "fc            "}};
constexpr InternalSlot kTOSICZMInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "saut_de_ut_max"},  {92, "saut_de_un_max"},  {107, "saut_de_us_max"},
    {122, "coalescence   "}, {137, "tris_coal     "}, {152, "energy1       "}, {167, "energy2       "},
    {182, "fc            "}};
// 93 TOSI_CZM_INCRE
constexpr std::string_view kTOSICZMINCREParameters[] = {"dyfr ", "stfr ", "cn   ", "ct   ", "f0   ", "fc   ",
                                                        "n    ", "kcoal", "R    ", "s0   ", "Gc1  ", "Gc2  ",
                                                        "K    ", "hdef ", "n_mol", "Q    "};
constexpr LawField kTOSICZMINCREReads[] = {{0, 2, 0}, {1, 2, 2},  {2, 2, 4},  {3, 2, 6},
                                           {4, 2, 8}, {5, 2, 10}, {6, 2, 12}, {7, 2, 14}};
constexpr LawField kTOSICZMINCREWrites[] = {{0, 2, 0}, {1, 2, 2},  {2, 2, 4},  {3, 2, 6},
                                            {4, 2, 8}, {5, 2, 10}, {6, 2, 12}, {7, 2, 14}};
constexpr InternalSlot kTOSICZMINCREInternals2D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "beta          "},
    {62, "saut_de_ut_max"},  {77, "saut_de_un_max"},  {92, "coalescence   "},  {107, "tris_coal     "},
    {122, "energy1       "}, {137, "energy2       "}, {152, "fc            "}, {167, "gamma         "},
    {182, "Rn_a          "}, {197, "Rt_a          "}};
constexpr InternalSlot kTOSICZMINCREInternals3D[] = {
    {2, "taille_ele    "},   {17, "saut_de_ut    "},  {32, "saut_de_un    "},  {47, "saut_de_us    "},
    {62, "beta          "},  {77, "saut_de_ut_max"},  {92, "saut_de_un_max"},  {107, "saut_de_us_max"},
    {122, "coalescence   "}, {137, "tris_coal     "}, {152, "energy1       "}, {167, "energy2       "},
    {182, "fc            "}, {197, "gamma         "}, {212, "Rn_a          "}, {227, "Rt_a          "},
    {242, "Rs_a          "}};
// 94 ELASTIC_REPELL_CLB_adapt
constexpr std::string_view kELASTICREPELLCLBAdaptParameters[] = {"F/gap", "sfric"};
constexpr LawField kELASTICREPELLCLBAdaptReads[] = {{0, 1, 0}, {1, 1, 1}};
constexpr LawField kELASTICREPELLCLBAdaptWrites[] = {{0, 1, 0}, {1, 1, 1}};
constexpr InternalSlot kELASTICREPELLCLBAdaptInternals2D[] = {{2, "F/gap         "}};
constexpr InternalSlot kELASTICREPELLCLBAdaptInternals3D[] = {{2, "F/gap         "}};

constexpr LawKind kLawKinds[] = {
    LawKind{1, "IQS_CLB", kIQSCLBParameters, kIQSCLBReads, kIQSCLBWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{2, "IQS_CLB_nosldt", kIQSCLBNosldtParameters, kIQSCLBNosldtReads, kIQSCLBNosldtWrites,
            InternalLayout{1, kIQSCLBNosldtInternals2D}, InternalLayout{1, kIQSCLBNosldtInternals3D}, true,
            ""},
    LawKind{3, "IQS_CLB_noslds", kIQSCLBNosldsParameters, kIQSCLBNosldsReads, kIQSCLBNosldsWrites,
            InternalLayout{1, kIQSCLBNosldsInternals2D}, InternalLayout{1, kIQSCLBNosldsInternals3D}, true,
            ""},
    LawKind{4, "IQS_CLB_RGR", kIQSCLBRGRParameters, kIQSCLBRGRReads, kIQSCLBRGRWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{5, "IQS_DS_CLB", kIQSDSCLBParameters, kIQSDSCLBReads, kIQSDSCLBWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{6, "IQS_WET_DS_CLB", kIQSWETDSCLBParameters, kIQSWETDSCLBReads, kIQSWETDSCLBWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{7, "postGAP_IQS_MAC_CZM", kPostGAPIQSMACCZMParameters, kPostGAPIQSMACCZMReads,
            kPostGAPIQSMACCZMWrites, InternalLayout{6, kPostGAPIQSMACCZMInternals2D}, InternalLayout{-1, {}},
            true, ""},
    LawKind{8, "PLASTIC_COUPLED_DOF", kPLASTICCOUPLEDDOFParameters, kPLASTICCOUPLEDDOFReads,
            kPLASTICCOUPLEDDOFWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{9, "xQS_WET_DS_CLB", kXQSWETDSCLBParameters, kXQSWETDSCLBReads, kXQSWETDSCLBWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{10, "TEX_SOL", kTEXSOLParameters, kTEXSOLReads, kTEXSOLWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{11, "TEX_SOL_UNILAT", kTEXSOLUNILATParameters, kTEXSOLUNILATReads, kTEXSOLUNILATWrites,
            InternalLayout{1, kTEXSOLUNILATInternals2D}, InternalLayout{1, kTEXSOLUNILATInternals3D}, true,
            ""},
    LawKind{12, "GAP_SGR_CLB", kGAPSGRCLBParameters, kGAPSGRCLBReads, kGAPSGRCLBWrites,
            InternalLayout{1, kGAPSGRCLBInternals2D}, InternalLayout{1, kGAPSGRCLBInternals3D}, true, ""},
    LawKind{13, "VEL_SGR_CLB", kVELSGRCLBParameters, kVELSGRCLBReads, kVELSGRCLBWrites,
            InternalLayout{1, kVELSGRCLBInternals2D}, InternalLayout{1, kVELSGRCLBInternals3D}, true, ""},
    LawKind{14, "GAP_WET_DS_CLB", kGAPWETDSCLBParameters, kGAPWETDSCLBReads, kGAPWETDSCLBWrites,
            InternalLayout{1, kGAPWETDSCLBInternals2D}, InternalLayout{1, kGAPWETDSCLBInternals3D}, true, ""},
    LawKind{15, "MSMP_CZM", kMSMPCZMParameters, kMSMPCZMReads, kMSMPCZMWrites,
            InternalLayout{5, kMSMPCZMInternals2D}, InternalLayout{-1, {}}, true, ""},
    LawKind{16, "GAP_SGR_DS_CLB", kGAPSGRDSCLBParameters, kGAPSGRDSCLBReads, kGAPSGRDSCLBWrites,
            InternalLayout{1, kGAPSGRDSCLBInternals2D}, InternalLayout{1, kGAPSGRDSCLBInternals3D}, true, ""},
    LawKind{17, "VEL_SGR_DS_CLB", kVELSGRDSCLBParameters, kVELSGRDSCLBReads, kVELSGRDSCLBWrites,
            InternalLayout{1, kVELSGRDSCLBInternals2D}, InternalLayout{1, kVELSGRDSCLBInternals3D}, true, ""},
    LawKind{18, "RST_CLB", kRSTCLBParameters, kRSTCLBReads, kRSTCLBWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{19, "RST_DS_CLB", kRSTDSCLBParameters, kRSTDSCLBReads, kRSTDSCLBWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{20, "IQS_MOHR_DS_CLB", kIQSMOHRDSCLBParameters, kIQSMOHRDSCLBReads, kIQSMOHRDSCLBWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{21, "MAL_CZM", kMALCZMParameters, kMALCZMReads, kMALCZMWrites,
            InternalLayout{5, kMALCZMInternals2D}, InternalLayout{6, kMALCZMInternals3D}, true, ""},
    LawKind{22, "ELASTIC_REPELL_CLB", kELASTICREPELLCLBParameters, kELASTICREPELLCLBReads,
            kELASTICREPELLCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{23, "CRITICAL_VOIGT_CLB", kCRITICALVOIGTCLBParameters, kCRITICALVOIGTCLBReads,
            kCRITICALVOIGTCLBWrites, InternalLayout{3, kCRITICALVOIGTCLBInternals2D},
            InternalLayout{3, kCRITICALVOIGTCLBInternals3D}, true, ""},
    LawKind{24, "ELASTIC_REPELL_WET_CLB", kELASTICREPELLWETCLBParameters, kELASTICREPELLWETCLBReads,
            kELASTICREPELLWETCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{25, "ELASTIC_ROD", kELASTICRODParameters, kELASTICRODReads, kELASTICRODWrites,
            InternalLayout{1, kELASTICRODInternals2D}, InternalLayout{1, kELASTICRODInternals3D}, true, ""},
    LawKind{26, "VOIGT_ROD", kVOIGTRODParameters, kVOIGTRODReads, kVOIGTRODWrites,
            InternalLayout{1, kVOIGTRODInternals2D}, InternalLayout{1, kVOIGTRODInternals3D}, true, ""},
    LawKind{27, "ELASTIC_WIRE", kELASTICWIREParameters, kELASTICWIREReads, kELASTICWIREWrites,
            InternalLayout{1, kELASTICWIREInternals2D}, InternalLayout{1, kELASTICWIREInternals3D}, true, ""},
    LawKind{28, "VOIGT_WIRE", kVOIGTWIREParameters, kVOIGTWIREReads, kVOIGTWIREWrites,
            InternalLayout{1, kVOIGTWIREInternals2D}, InternalLayout{1, kVOIGTWIREInternals3D}, true, ""},
    LawKind{29, "MD_JKRs", kMDJKRsParameters, kMDJKRsReads, kMDJKRsWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{30, "ELASTIC_WET_NT", kELASTICWETNTParameters, kELASTICWETNTReads, kELASTICWETNTWrites,
            InternalLayout{3, kELASTICWETNTInternals2D}, InternalLayout{3, kELASTICWETNTInternals3D}, true,
            "LMGC90 reads adhen, adhet from the same line and columns as dampn, dampt (no line read in "
            "between), so they equal dampn, dampt; its writer prints a third line"},
    LawKind{31, "COUPLED_DOF", kCOUPLEDDOFParameters, kCOUPLEDDOFReads, kCOUPLEDDOFWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{32, "TANGENTIAL_COUPLED_DOF", kTANGENTIALCOUPLEDDOFParameters, kTANGENTIALCOUPLEDDOFReads,
            kTANGENTIALCOUPLEDDOFWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{33, "NORMAL_COUPLED_DOF", kNORMALCOUPLEDDOFParameters, kNORMALCOUPLEDDOFReads,
            kNORMALCOUPLEDDOFWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{34, "PERIO_DOF", kPERIODOFParameters, kPERIODOFReads, kPERIODOFWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true,
            "LMGC90 reads E_XX, E_YY and E_XY from the same field (columns 46-59 of the law line), so the "
            "three values are equal; its writer prints them on three lines"},
    LawKind{35, "GAP_SGR_CLB_WEAR", kGAPSGRCLBWEARParameters, kGAPSGRCLBWEARReads, kGAPSGRCLBWEARWrites,
            InternalLayout{3, kGAPSGRCLBWEARInternals2D}, InternalLayout{3, kGAPSGRCLBWEARInternals3D}, true,
            ""},
    LawKind{36, "IQS_SGR_CLB_WEAR", kIQSSGRCLBWEARParameters, kIQSSGRCLBWEARReads, kIQSSGRCLBWEARWrites,
            InternalLayout{3, kIQSSGRCLBWEARInternals2D}, InternalLayout{3, kIQSSGRCLBWEARInternals3D}, true,
            "LMGC90 allocates 3 parameters but reads 4 (Wethk lands out of bounds and is lost; its echo "
            "prints an undefined 4th value); lmgc keeps the 4 values"},
    LawKind{37, "MAC_CZM", kMACCZMParameters, kMACCZMReads, kMACCZMWrites,
            InternalLayout{5, kMACCZMInternals2D}, InternalLayout{6, kMACCZMInternals3D}, true, ""},
    LawKind{38, "IQS_MAC_CZM", kIQSMACCZMParameters, kIQSMACCZMReads, kIQSMACCZMWrites,
            InternalLayout{5, kIQSMACCZMInternals2D}, InternalLayout{6, kIQSMACCZMInternals3D}, true, ""},
    LawKind{39, "WET_CZM", kWETCZMParameters, kWETCZMReads, kWETCZMWrites, InternalLayout{-1, {}},
            InternalLayout{-1, {}}, false, "integer id only: LMGC90's reader rejects the keyword"},
    LawKind{40, "GAP_MOHR_DS_CLB", kGAPMOHRDSCLBParameters, kGAPMOHRDSCLBReads, kGAPMOHRDSCLBWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{41, "MAC_CZM_nosldt", kMACCZMNosldtParameters, kMACCZMNosldtReads, kMACCZMNosldtWrites,
            InternalLayout{-1, {}}, InternalLayout{6, kMACCZMNosldtInternals3D}, true, ""},
    LawKind{42, "MAC_CZM_noslds", kMACCZMNosldsParameters, kMACCZMNosldsReads, kMACCZMNosldsWrites,
            InternalLayout{-1, {}}, InternalLayout{6, kMACCZMNosldsInternals3D}, true, ""},
    LawKind{43, "IQS_MAC_CZM_nosldt", kIQSMACCZMNosldtParameters, kIQSMACCZMNosldtReads,
            kIQSMACCZMNosldtWrites, InternalLayout{-1, {}}, InternalLayout{6, kIQSMACCZMNosldtInternals3D},
            true, ""},
    LawKind{44, "IQS_MAC_CZM_noslds", kIQSMACCZMNosldsParameters, kIQSMACCZMNosldsReads,
            kIQSMACCZMNosldsWrites, InternalLayout{-1, {}}, InternalLayout{6, kIQSMACCZMNosldsInternals3D},
            true, ""},
    LawKind{45, "ER_MAC_CZM", kERMACCZMParameters, kERMACCZMReads, kERMACCZMWrites,
            InternalLayout{4, kERMACCZMInternals2D}, InternalLayout{5, kERMACCZMInternals3D}, true, ""},
    LawKind{46, "IQS_WET_CZM", kIQSWETCZMParameters, kIQSWETCZMReads, kIQSWETCZMWrites,
            InternalLayout{6, kIQSWETCZMInternals2D}, InternalLayout{6, kIQSWETCZMInternals3D}, true, ""},
    LawKind{47, "DEM_FIBs", kDEMFIBsParameters, kDEMFIBsReads, kDEMFIBsWrites,
            InternalLayout{5, kDEMFIBsInternals2D}, InternalLayout{5, kDEMFIBsInternals3D}, true, ""},
    LawKind{48, "KV_WET", kKVWETParameters, kKVWETReads, kKVWETWrites, InternalLayout{3, kKVWETInternals2D},
            InternalLayout{3, kKVWETInternals3D}, true, ""},
    LawKind{49, "VISCO_ELASTIC_REPELL_WET", kVISCOELASTICREPELLWETParameters, kVISCOELASTICREPELLWETReads,
            kVISCOELASTICREPELLWETWrites, InternalLayout{6, {}}, InternalLayout{6, {}}, true, ""},
    LawKind{50, "RIGID_WIRE", kRIGIDWIREParameters, kRIGIDWIREReads, kRIGIDWIREWrites,
            InternalLayout{1, kRIGIDWIREInternals2D}, InternalLayout{1, kRIGIDWIREInternals3D}, true, ""},
    LawKind{51, "IQS_BW_CLB", kIQSBWCLBParameters, kIQSBWCLBReads, kIQSBWCLBWrites,
            InternalLayout{4, kIQSBWCLBInternals2D}, InternalLayout{4, kIQSBWCLBInternals3D}, true,
            "LMGC90 allocates 6 parameters but reads a 7th (CFreq) and its info table declares 7 (naming the "
            "6th CFreq): add_to_tact_behav_ll stops with \"nb of parameters is wrong\"; lmgc reads and keeps "
            "the 7 values"},
    LawKind{52, "IQS_CAP_MOHR_DS_CLB", kIQSCAPMOHRDSCLBParameters, kIQSCAPMOHRDSCLBReads,
            kIQSCAPMOHRDSCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{53, "IQS_MAL_CZM", kIQSMALCZMParameters, kIQSMALCZMReads, kIQSMALCZMWrites,
            InternalLayout{4, kIQSMALCZMInternals2D}, InternalLayout{6, kIQSMALCZMInternals3D}, true, ""},
    LawKind{54, "GAP_CAP_MOHR_DS_CLB", kGAPCAPMOHRDSCLBParameters, kGAPCAPMOHRDSCLBReads,
            kGAPCAPMOHRDSCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{55, "BROKEN_DOF", kBROKENDOFParameters, kBROKENDOFReads, kBROKENDOFWrites,
            InternalLayout{1, kBROKENDOFInternals2D}, InternalLayout{1, kBROKENDOFInternals3D}, true, ""},
    LawKind{56, "IQS_CLB_g0", kIQSCLBG0Parameters, kIQSCLBG0Reads, kIQSCLBG0Writes,
            InternalLayout{1, kIQSCLBG0Internals2D}, InternalLayout{1, kIQSCLBG0Internals3D}, true, ""},
    LawKind{57, "IQS_MAP", kIQSMAPParameters, kIQSMAPReads, kIQSMAPWrites,
            InternalLayout{1, kIQSMAPInternals2D}, InternalLayout{1, kIQSMAPInternals3D}, true,
            "LMGC90 reads IQS_MAP but its TACT_BEHAV.OUT writer has no branch for it (stops); lmgc writes it "
            "like IQS_CLB"},
    LawKind{58, "RST_WET_CLB", kRSTWETCLBParameters, kRSTWETCLBReads, kRSTWETCLBWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{59, "LJ_POTENTIAL", kLJPOTENTIALParameters, kLJPOTENTIALReads, kLJPOTENTIALWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true,
            "LMGC90 reads radcd, radan from the same line and columns as noycd, noyan (no line read in "
            "between), so they equal noycd, noyan; its writer prints a fourth line"},
    LawKind{60, "GAP_SGR_CLB_g0", kGAPSGRCLBG0Parameters, kGAPSGRCLBG0Reads, kGAPSGRCLBG0Writes,
            InternalLayout{2, kGAPSGRCLBG0Internals2D}, InternalLayout{2, kGAPSGRCLBG0Internals3D}, true, ""},
    LawKind{61, "BRITTLE_ELASTIC_WIRE", kBRITTLEELASTICWIREParameters, kBRITTLEELASTICWIREReads,
            kBRITTLEELASTICWIREWrites, InternalLayout{1, kBRITTLEELASTICWIREInternals2D},
            InternalLayout{1, kBRITTLEELASTICWIREInternals3D}, true, ""},
    LawKind{62, "ELASTIC_REPELL_CLB_g0", kELASTICREPELLCLBG0Parameters, kELASTICREPELLCLBG0Reads,
            kELASTICREPELLCLBG0Writes, InternalLayout{1, kELASTICREPELLCLBG0Internals2D},
            InternalLayout{1, kELASTICREPELLCLBG0Internals3D}, true, ""},
    LawKind{63, "MP_CZM", kMPCZMParameters, kMPCZMReads, kMPCZMWrites, InternalLayout{5, kMPCZMInternals2D},
            InternalLayout{6, kMPCZMInternals3D}, true, ""},
    LawKind{64, "MP3_CZM", kMP3CZMParameters, kMP3CZMReads, kMP3CZMWrites,
            InternalLayout{5, kMP3CZMInternals2D}, InternalLayout{6, kMP3CZMInternals3D}, true, ""},
    LawKind{65, "MP3_CZM_THER", kMP3CZMTHERParameters, kMP3CZMTHERReads, kMP3CZMTHERWrites,
            InternalLayout{5, kMP3CZMTHERInternals2D}, InternalLayout{6, kMP3CZMTHERInternals3D}, true, ""},
    LawKind{66, "TH_CZM", kTHCZMParameters, kTHCZMReads, kTHCZMWrites, InternalLayout{5, kTHCZMInternals2D},
            InternalLayout{6, kTHCZMInternals3D}, true, ""},
    LawKind{67, "IQS_TH_CZM", kIQSTHCZMParameters, kIQSTHCZMReads, kIQSTHCZMWrites,
            InternalLayout{5, kIQSTHCZMInternals2D}, InternalLayout{6, kIQSTHCZMInternals3D}, true, ""},
    LawKind{68, "postGAP_IQS_CZM", kPostGAPIQSCZMParameters, kPostGAPIQSCZMReads, kPostGAPIQSCZMWrites,
            InternalLayout{-1, {}}, InternalLayout{-1, {}}, false,
            "integer id only (used internally for postGAP_IQS_MAC_CZM): LMGC90's reader rejects the keyword"},
    LawKind{69, "WET_3C", kWET3CParameters, kWET3CReads, kWET3CWrites, InternalLayout{-1, {}},
            InternalLayout{-1, {}}, false, "integer id only: LMGC90's reader rejects the keyword"},
    LawKind{70, "VISCO_ELASTIC_REPELL_CLB", kVISCOELASTICREPELLCLBParameters, kVISCOELASTICREPELLCLBReads,
            kVISCOELASTICREPELLCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{71, "ELASTIC_REPELL_MAC_CZM", kELASTICREPELLMACCZMParameters, kELASTICREPELLMACCZMReads,
            kELASTICREPELLMACCZMWrites, InternalLayout{4, kELASTICREPELLMACCZMInternals2D},
            InternalLayout{4, kELASTICREPELLMACCZMInternals3D}, true, ""},
    LawKind{72, "IQS_PLAS_CLB", kIQSPLASCLBParameters, kIQSPLASCLBReads, kIQSPLASCLBWrites,
            InternalLayout{3, kIQSPLASCLBInternals2D}, InternalLayout{3, kIQSPLASCLBInternals3D}, true, ""},
    LawKind{73, "ABP_CZM", kABPCZMParameters, kABPCZMReads, kABPCZMWrites,
            InternalLayout{5, kABPCZMInternals2D}, InternalLayout{6, kABPCZMInternals3D}, true, ""},
    LawKind{74, "IQS_ABP_CZM", kIQSABPCZMParameters, kIQSABPCZMReads, kIQSABPCZMWrites,
            InternalLayout{5, kIQSABPCZMInternals2D}, InternalLayout{6, kIQSABPCZMInternals3D}, true, ""},
    LawKind{75, "BRITTLE_COATING_CLB", kBRITTLECOATINGCLBParameters, kBRITTLECOATINGCLBReads,
            kBRITTLECOATINGCLBWrites, InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{76, "IQS_STICK", kIQSSTICKParameters, kIQSSTICKReads, kIQSSTICKWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{77, "GAP_SGR_STICK", kGAPSGRSTICKParameters, kGAPSGRSTICKReads, kGAPSGRSTICKWrites,
            InternalLayout{0, {}}, InternalLayout{0, {}}, true, ""},
    LawKind{78, "GAP_SGR_CLB_nosldt", kGAPSGRCLBNosldtParameters, kGAPSGRCLBNosldtReads,
            kGAPSGRCLBNosldtWrites, InternalLayout{1, kGAPSGRCLBNosldtInternals2D},
            InternalLayout{1, kGAPSGRCLBNosldtInternals3D}, true, ""},
    LawKind{79, "GAP_SGR_CLB_noslds", kGAPSGRCLBNosldsParameters, kGAPSGRCLBNosldsReads,
            kGAPSGRCLBNosldsWrites, InternalLayout{1, kGAPSGRCLBNosldsInternals2D},
            InternalLayout{1, kGAPSGRCLBNosldsInternals3D}, true, ""},
    LawKind{80, "preGAP_SGR_CLB", kPreGAPSGRCLBParameters, kPreGAPSGRCLBReads, kPreGAPSGRCLBWrites,
            InternalLayout{1, kPreGAPSGRCLBInternals2D}, InternalLayout{1, kPreGAPSGRCLBInternals3D}, true,
            ""},
    LawKind{81, "NARD_ROD", kNARDRODParameters, kNARDRODReads, kNARDRODWrites,
            InternalLayout{6, kNARDRODInternals2D}, InternalLayout{6, kNARDRODInternals3D}, true, ""},
    LawKind{82, "IQS_EXPO_CZM", kIQSEXPOCZMParameters, kIQSEXPOCZMReads, kIQSEXPOCZMWrites,
            InternalLayout{5, kIQSEXPOCZMInternals2D}, InternalLayout{7, kIQSEXPOCZMInternals3D}, true, ""},
    LawKind{83, "EXPO_CZM", kEXPOCZMParameters, kEXPOCZMReads, kEXPOCZMWrites,
            InternalLayout{5, kEXPOCZMInternals2D}, InternalLayout{7, kEXPOCZMInternals3D}, true, ""},
    LawKind{84, "IQS_EXPO_CZM_SPRING", kIQSEXPOCZMSPRINGParameters, kIQSEXPOCZMSPRINGReads,
            kIQSEXPOCZMSPRINGWrites, InternalLayout{9, kIQSEXPOCZMSPRINGInternals2D},
            InternalLayout{11, kIQSEXPOCZMSPRINGInternals3D}, true, ""},
    LawKind{85, "EXPO_CZM_SPRING", kEXPOCZMSPRINGParameters, kEXPOCZMSPRINGReads, kEXPOCZMSPRINGWrites,
            InternalLayout{9, kEXPOCZMSPRINGInternals2D}, InternalLayout{11, kEXPOCZMSPRINGInternals3D}, true,
            ""},
    LawKind{86, "IQS_EXPO_CZM_P", kIQSEXPOCZMPParameters, kIQSEXPOCZMPReads, kIQSEXPOCZMPWrites,
            InternalLayout{9, kIQSEXPOCZMPInternals2D}, InternalLayout{13, kIQSEXPOCZMPInternals3D}, true,
            ""},
    LawKind{87, "EXPO_CZM_P", kEXPOCZMPParameters, kEXPOCZMPReads, kEXPOCZMPWrites,
            InternalLayout{9, kEXPOCZMPInternals2D}, InternalLayout{13, kEXPOCZMPInternals3D}, true, ""},
    LawKind{88, "IQS_EXPO_CZM_SPRING_P", kIQSEXPOCZMSPRINGPParameters, kIQSEXPOCZMSPRINGPReads,
            kIQSEXPOCZMSPRINGPWrites, InternalLayout{11, kIQSEXPOCZMSPRINGPInternals2D},
            InternalLayout{15, kIQSEXPOCZMSPRINGPInternals3D}, true, ""},
    LawKind{89, "EXPO_CZM_SPRING_P", kEXPOCZMSPRINGPParameters, kEXPOCZMSPRINGPReads, kEXPOCZMSPRINGPWrites,
            InternalLayout{11, kEXPOCZMSPRINGPInternals2D}, InternalLayout{15, kEXPOCZMSPRINGPInternals3D},
            true, ""},
    LawKind{90, "GTN_CZM", kGTNCZMParameters, kGTNCZMReads, kGTNCZMWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{91, "GTN2_CZM", kGTN2CZMParameters, kGTN2CZMReads, kGTN2CZMWrites, InternalLayout{0, {}},
            InternalLayout{0, {}}, true, ""},
    LawKind{92, "TOSI_CZM", kTOSICZMParameters, kTOSICZMReads, kTOSICZMWrites,
            InternalLayout{11, kTOSICZMInternals2D}, InternalLayout{13, kTOSICZMInternals3D}, true, ""},
    LawKind{93, "TOSI_CZM_INCRE", kTOSICZMINCREParameters, kTOSICZMINCREReads, kTOSICZMINCREWrites,
            InternalLayout{14, kTOSICZMINCREInternals2D}, InternalLayout{17, kTOSICZMINCREInternals3D}, true,
            ""},
    LawKind{94, "ELASTIC_REPELL_CLB_adapt", kELASTICREPELLCLBAdaptParameters, kELASTICREPELLCLBAdaptReads,
            kELASTICREPELLCLBAdaptWrites, InternalLayout{1, kELASTICREPELLCLBAdaptInternals2D},
            InternalLayout{1, kELASTICREPELLCLBAdaptInternals3D}, true, ""},
};

static_assert(std::size(kLawKinds) == 94, "LMGC90 has 94 law ids");

constexpr GuideOnlyLawName kGuideOnly[] = {
    {"IQS_MAC_CZM_3D", "IQS_MAC_CZM"},
    {"IQS_MAC_CZM_3D_nosldt", "IQS_MAC_CZM_nosldt"},
    {"IQS_MAC_CZM_3D_noslds", "IQS_MAC_CZM_noslds"},
    {"MAC_CZM_3D_nosldt", "MAC_CZM_nosldt"},
    {"MAC_CZM_3D_noslds", "MAC_CZM_noslds"},
    {"DEM_Cohe_Hertz", ""},
};

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

}  // namespace

int LawKind::read_line_count() const {
  int lines = 1;
  for (const LawField& field : reads) lines = std::max(lines, field.line + 1);
  return lines;
}

int LawKind::values_on_read_line(int line) const {
  int values = 0;
  for (const LawField& field : reads)
    if (field.line == line) values += field.count;
  return values;
}

std::vector<double> values_read_back_from_echo(const LawKind& kind, std::span<const double> values) {
  std::vector<double> result(kind.parameters.size(), 0.0);
  for (const LawField& read : kind.reads) {
    for (int slot = 0; slot < read.count; ++slot) {
      const std::size_t target = static_cast<std::size_t>(read.first) + static_cast<std::size_t>(slot);
      if (target >= result.size()) continue;
      // The printed field at the same physical line and slot, if any.
      for (const LawField& write : kind.writes) {
        if (write.line != read.line || slot >= write.count) continue;
        const std::size_t source = static_cast<std::size_t>(write.first) + static_cast<std::size_t>(slot);
        result[target] = source < values.size() ? values[source] : 0.0;
      }
    }
  }
  return result;
}

std::span<const LawKind> law_catalogue() {
  return kLawKinds;
}

const LawKind* find_law_kind(std::string_view keyword) {
  for (const LawKind& kind : kLawKinds)
    if (kind.keyword == keyword) return &kind;
  return nullptr;
}

std::span<const GuideOnlyLawName> guide_only_law_names() {
  return kGuideOnly;
}

std::string law_keyword_hint(std::string_view keyword) {
  for (const GuideOnlyLawName& old : kGuideOnly) {
    if (old.guide_name != keyword) continue;
    if (old.current_keyword.empty())
      return "'" + std::string(keyword) +
             "' is a law of LMGC90's 2012 user's guide that the current LMGC90 no longer has";
    return "'" + std::string(keyword) + "' is the user's guide name; the current keyword is '" +
           std::string(old.current_keyword) + "' (the dimension comes from the run, not the name)";
  }
  if (const LawKind* kind = find_law_kind(keyword); kind != nullptr && !kind->readable)
    return "'" + std::string(keyword) + "' is an internal law id of LMGC90; its reader does not accept it";
  for (const LawKind& kind : kLawKinds)
    if (kind.readable && equal_ignoring_case(kind.keyword, keyword))
      return "law keywords are case-sensitive: did you mean '" + std::string(kind.keyword) + "'?";
  const LawKind* closest = nullptr;
  int matches = 0;
  for (const LawKind& kind : kLawKinds) {
    if (!kind.readable || edit_distance(kind.keyword, keyword) > 2) continue;
    closest = &kind;
    ++matches;
  }
  if (matches == 1) return "did you mean '" + std::string(closest->keyword) + "'?";
  return {};
}

std::string internal_variables_comment(const InternalLayout& layout) {
  if (layout.count <= 0) return {};
  std::string line(285, ' ');
  line[0] = '#';
  for (const auto& slot : layout.slots)
    if (slot.column >= 1 && slot.column - 1 + slot.text.size() <= line.size())
      line.replace(slot.column - 1, slot.text.size(), slot.text);
  return line;
}

}  // namespace lmgc::grammar
