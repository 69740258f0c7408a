#include "grammar/tact_behav/contactor_pairs.hpp"

namespace lmgc::grammar {
namespace {

// The interaction modules of LMGC90 (state-and-outputs.md §1.4.1-1.4.2, contact-laws.md §1.2).
constexpr ContactorPair kPairs[] = {
    {"DISKx", "DISKx", "DKDKx", 2}, {"DISKx", "JONCx", "DKJCx", 2},          {"DISKx", "xKSID", "DKKDx", 2},
    {"DISKx", "POLYG", "DKPLx", 2}, {"POLYG", "POLYG", "PLPLx", 2},          {"POLYG", "JONCx", "PLJCx", 2},
    {"PT2Dx", "PT2Dx", "PTPT2", 2}, {"CLxxx", "ALpxx", "CLALp", 2},          {"CLxxx", "JONCx", "CLJCx", 2},
    {"DISKx", "ALpxx", "DKALp", 2}, {"POLYG", "ALpxx", "PLALp", 2},          {"PT2DL", "PT2DL", "P2P2L", 2},
    {"DISKx", "DISKL", "DKDKL", 2}, {"SPHER", "SPHER", "SPSPx", 3},          {"SPHER", "PLANx", "SPPLx", 3},
    {"SPHER", "CYLND", "SPCDx", 3}, {"SPHER", "DNLYC", "SPDCx", 3},          {"CYLND", "CYLND", "CDCDx", 3},
    {"CYLND", "PLANx", "CDPLx", 3}, {"POLYR", "POLYR", "PRPRx", 3},          {"POLYR", "PLANx", "PRPLx", 3},
    {"POLYR", "ASpxx", "PRASp", 3}, {"CSxxx", "ASpxx", "CSASp", 3, "CSASx"}, {"CSxxx", "POLYR", "CSPRx", 3},
    {"PT3Dx", "PT3Dx", "PTPT3", 3}, {"SPHER", "POLYR", "SPPRx", 3},
};

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

}  // namespace

std::span<const ContactorPair> contactor_pairs() {
  return kPairs;
}

const ContactorPair* find_contactor_pair(std::string_view candidate, std::string_view antagonist) {
  for (const ContactorPair& p : kPairs)
    if (p.candidate == candidate && p.antagonist == antagonist) return &p;
  return nullptr;
}

const ContactorPair* find_interaction_pair(std::string_view interaction) {
  for (const ContactorPair& p : kPairs)
    if (p.interaction == interaction) return &p;
  return nullptr;
}

std::string_view see_name(std::string_view type) {
  if (type == "DISKb") return "DISKx";
  if (type == "SPHEb") return "SPHER";
  if (starts_with(type, "CSp") || starts_with(type, "CSxx")) return "CSxxx";
  if (starts_with(type, "ASp")) return "ASpxx";
  if (type == "POLYF") return "POLYR";
  if (type == "PT2TL") return "PT2DL";
  return type;
}

}  // namespace lmgc::grammar
