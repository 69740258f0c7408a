// The '$seety' table against the contactors present: pairs LMGC90 can detect, rows that never
// match, colours no row mentions, conflicting rows, alert distances against contactor sizes.
// docs/lmgc90-facts/contact-laws.md §1.2, numerics.md §5.1.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "grammar/tact_behav/see_table.hpp"
#include "validate/checks.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

struct ClassInfo {
  std::size_t count = 0;
  std::vector<double> sizes;
};

}  // namespace

void check_visibility(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.tact_behav || !files.bodies) return;
  const std::string path = datbox_path(files, "TACT_BEHAV.DAT");
  // Contactor classes present: (body model, see name, colour).
  std::map<std::tuple<std::string, std::string, std::string>, ClassInfo> classes;
  for (const auto& body : files.bodies->bodies)
    for (const auto& c : body.contactors) {
      ClassInfo& info = classes[{std::string(grammar::body_type_keyword(body.type)), see_name(c.type.value),
                                 c.color.value}];
      ++info.count;
      const double size = characteristic_size(c);
      if (size > 0.0 && info.sizes.size() < 10000) info.sizes.push_back(size);
    }
  auto present = [&](const grammar::Word& body, const grammar::Word& type, const grammar::Word& colour) {
    return classes.find({body.value, type.value, colour.value}) != classes.end();
  };
  auto median_size = [&](const grammar::Word& body, const grammar::Word& type, const grammar::Word& colour) {
    auto it = classes.find({body.value, type.value, colour.value});
    if (it == classes.end() || it->second.sizes.empty()) return 0.0;
    std::vector<double> s = it->second.sizes;
    std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(s.size() / 2), s.end());
    return s[s.size() / 2];
  };

  std::set<std::tuple<std::string, std::string, std::string>> mentioned;
  const auto duplicates = grammar::see_duplicate_of(files.tact_behav->sees);
  for (std::size_t i = 0; i < files.tact_behav->sees.size(); ++i) {
    const grammar::SeeEntry& see = files.tact_behav->sees[i];
    mentioned.insert({see.candidate_body.value, see.candidate_contactor.value, see.candidate_colour.value});
    mentioned.insert(
        {see.antagonist_body.value, see.antagonist_contactor.value, see.antagonist_colour.value});
    if (duplicates[i] != grammar::kNoDuplicate) {
      const grammar::SeeEntry& first = files.tact_behav->sees[duplicates[i]];
      if (first.law_nickname.value != see.law_nickname.value)
        sink.report(
            grammar::Diagnostic{"L2015",
                                grammar::Severity::error,
                                grammar::Location{path, see.law_nickname.span},
                                fmt::format("this visibility row gives law '{}' to a pair that an earlier "
                                            "row gives law '{}'; LMGC90 stops "
                                            "on it",
                                            see.law_nickname.value, first.law_nickname.value),
                                {{grammar::Location{path, first.law_nickname.span}, "the earlier row"}},
                                {}});
      continue;
    }
    const InteractionFamily* family =
        find_interaction_family(see.candidate_contactor.value, see.antagonist_contactor.value);
    if (!family) {
      const bool swapped =
          find_interaction_family(see.antagonist_contactor.value, see.candidate_contactor.value) != nullptr;
      sink.report(
          "L2014", grammar::Location{path, see.candidate_contactor.span},
          fmt::format(
              "LMGC90 has no interaction with candidate '{}' and antagonist '{}'; this row creates no "
              "contact",
              see.candidate_contactor.value, see.antagonist_contactor.value),
          swapped ? "swap the candidate and antagonist columns" : "");
      continue;
    }
    if (!present(see.candidate_body, see.candidate_contactor, see.candidate_colour) ||
        !present(see.antagonist_body, see.antagonist_contactor, see.antagonist_colour)) {
      const bool cd = present(see.candidate_body, see.candidate_contactor, see.candidate_colour);
      const grammar::SeeEntry& s = see;
      sink.report("L2010",
                  grammar::Location{path, cd ? s.antagonist_contactor.span : s.candidate_contactor.span},
                  fmt::format("no {} contactor '{}' of colour '{}' exists: this row never matches",
                              cd ? s.antagonist_body.value : s.candidate_body.value,
                              cd ? s.antagonist_contactor.value : s.candidate_contactor.value,
                              cd ? s.antagonist_colour.value : s.candidate_colour.value));
      continue;
    }
    // Alert distance against the size of the contactors it applies to.
    const double a = median_size(see.candidate_body, see.candidate_contactor, see.candidate_colour);
    const double b = median_size(see.antagonist_body, see.antagonist_contactor, see.antagonist_colour);
    const double size = a > 0.0 && b > 0.0 ? std::min(a, b) : std::max(a, b);
    if (size > 0.0 && see.alert.value > size)
      sink.report(
          "L3008", grammar::Location{path, see.alert.span},
          fmt::format("alert distance {} is larger than the contactors it applies to (typical size {}): "
                      "contacts would be created far from touching",
                      see.alert.value, size),
          "an alert distance of a few percent of the smallest radius is usual");
    else if (size > 0.0 && see.alert.value > 0.0 && see.alert.value < 1e-9 * size)
      sink.report(
          "L3008", grammar::Location{path, see.alert.span},
          fmt::format(
              "alert distance {} is negligible against the contactors it applies to (typical size {}): "
              "fast contacts may be missed",
              see.alert.value, size));
  }
  // Colours of contactors that no visibility row mentions: they never touch anything.
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");
  for (const auto& [key, info] : classes) {
    if (mentioned.count(key)) continue;
    const auto& [body, type, colour] = key;
    if (type == "PT2Dx" || type == "PT3Dx") continue;  // points are often markers
    sink.report(
        "L2011", grammar::Location{bodies_path, {}},
        fmt::format("{} contactors '{}' of colour '{}' ({} of them) appear in no visibility row: they never "
                    "touch anything",
                    body, type, colour, info.count));
  }
}

}  // namespace lmgc::validate
