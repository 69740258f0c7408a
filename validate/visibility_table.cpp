#include "validate/visibility_table.hpp"

#include <algorithm>
#include <cmath>

namespace lmgc::validate {
namespace {

// The interaction modules of LMGC90 (state-and-outputs.md §1.4.1-1.4.2, contact-laws.md §1.2).
constexpr InteractionFamily kFamilies[] = {
    {"DISKx", "DISKx", "DKDKx", 2}, {"DISKx", "JONCx", "DKJCx", 2}, {"DISKx", "xKSID", "DKKDx", 2},
    {"DISKx", "POLYG", "DKPLx", 2}, {"POLYG", "POLYG", "PLPLx", 2}, {"POLYG", "JONCx", "PLJCx", 2},
    {"PT2Dx", "PT2Dx", "PTPT2", 2}, {"CLxxx", "ALpxx", "CLALp", 2}, {"CLxxx", "JONCx", "CLJCx", 2},
    {"DISKx", "ALpxx", "DKALp", 2}, {"POLYG", "ALpxx", "PLALp", 2}, {"PT2DL", "PT2DL", "P2P2L", 2},
    {"DISKx", "DISKL", "DKDKL", 2}, {"SPHER", "SPHER", "SPSPx", 3}, {"SPHER", "PLANx", "SPPLx", 3},
    {"SPHER", "CYLND", "SPCDx", 3}, {"SPHER", "DNLYC", "SPDCx", 3}, {"CYLND", "CYLND", "CDCDx", 3},
    {"CYLND", "PLANx", "CDPLx", 3}, {"POLYR", "POLYR", "PRPRx", 3}, {"POLYR", "PLANx", "PRPLx", 3},
    {"POLYR", "ASpxx", "PRASp", 3}, {"CSxxx", "ASpxx", "CSASp", 3}, {"CSxxx", "POLYR", "CSPRx", 3},
    {"PT3Dx", "PT3Dx", "PTPT3", 3}, {"SPHER", "POLYR", "SPPRx", 3},
};

std::string pair_key(const std::string& a, const std::string& b) {
  return a < b ? a + "|" + b : b + "|" + a;
}

}  // namespace

const InteractionFamily* find_interaction_family(std::string_view candidate, std::string_view antagonist) {
  for (const InteractionFamily& f : kFamilies)
    if (f.candidate == candidate && f.antagonist == antagonist) return &f;
  return nullptr;
}

std::string see_name(const std::string& type) {
  if (type == "DISKb") return "DISKx";
  if (type == "SPHEb") return "SPHER";
  if (type.rfind("CSp", 0) == 0 || type.rfind("CSxx", 0) == 0) return "CSxxx";
  if (type.rfind("ASp", 0) == 0) return "ASpxx";
  if (type == "POLYF") return "POLYR";
  if (type == "PT2TL") return "PT2DL";
  return type;
}

std::string see_class(std::string_view body_type, std::string_view see_contactor, std::string_view colour) {
  std::string out;
  out.reserve(17);
  out.append(body_type).append("/").append(see_contactor).append("/").append(colour);
  return out;
}

std::string see_class(const grammar::Body& body, const grammar::Contactor& contactor) {
  return see_class(grammar::body_type_keyword(body.type), see_name(contactor.type.value),
                   contactor.color.value);
}

double characteristic_size(const grammar::Contactor& c) {
  const std::string& t = c.type.value;
  if (t == "DISKx" || t == "DISKb" || t == "SPHER" || t == "SPHEb" || t == "xKSID")
    return c.values.empty() ? 0.0 : c.values[0].value;
  if (t == "POLYG" || t == "POLYR") {
    double r = 0.0;
    for (const auto& v : c.vertices)
      for (const auto& w : c.vertices)
        r = std::max(r,
                     std::sqrt(std::pow(v[0].value - w[0].value, 2) + std::pow(v[1].value - w[1].value, 2) +
                               std::pow(v[2].value - w[2].value, 2)));
    return 0.5 * r;
  }
  if (t == "CYLND") return c.values.size() > 1 ? c.values[1].value : 0.0;
  return 0.0;
}

SeeTable::SeeTable(const grammar::TactBehavFile& file) {
  for (const auto& see : file.sees) {
    const std::string a =
        see_class(see.candidate_body.value, see.candidate_contactor.value, see.candidate_colour.value);
    const std::string b =
        see_class(see.antagonist_body.value, see.antagonist_contactor.value, see.antagonist_colour.value);
    rows_.emplace(pair_key(a, b), &see);  // the first row wins
  }
}

const grammar::SeeEntry* SeeTable::find(const std::string& class_a, const std::string& class_b) const {
  auto it = rows_.find(pair_key(class_a, class_b));
  return it == rows_.end() ? nullptr : it->second;
}

}  // namespace lmgc::validate
