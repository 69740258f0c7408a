#include "validate/visibility_table.hpp"

#include <algorithm>
#include <cmath>

namespace lmgc::validate {
namespace {

std::string pair_key(const std::string& a, const std::string& b) {
  return a < b ? a + "|" + b : b + "|" + a;
}

}  // namespace

std::string see_name(const std::string& type) {
  return std::string(grammar::see_name(type));
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
