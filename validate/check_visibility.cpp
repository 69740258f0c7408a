// The '$seety' table against the contactors present: pairs LMGC90 can detect, rows that never
// match, colours no row mentions, conflicting rows, alert distances against contactor sizes.
// spec: contact-laws.md §1.2, numerics.md §5.1.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "grammar/tact_behav/see_table.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

// The interaction families of LMGC90: (candidate contactor, antagonist contactor) as a '$seety'
// row must name them. spec: state-and-outputs.md §1.4.1-1.4.2, contact-laws.md §1.2.
struct Family {
  std::string_view candidate, antagonist, name;
};
constexpr Family kFamilies[] = {
    {"DISKx", "DISKx", "DKDKx"}, {"DISKx", "JONCx", "DKJCx"}, {"DISKx", "xKSID", "DKKDx"}, {"DISKx", "POLYG", "DKPLx"},
    {"POLYG", "POLYG", "PLPLx"}, {"POLYG", "JONCx", "PLJCx"}, {"PT2Dx", "PT2Dx", "PTPT2"}, {"CLxxx", "ALpxx", "CLALp"},
    {"CLxxx", "JONCx", "CLJCx"}, {"DISKx", "ALpxx", "DKALp"}, {"POLYG", "ALpxx", "PLALp"}, {"PT2DL", "PT2DL", "P2P2L"},
    {"DISKx", "DISKL", "DKDKL"}, {"SPHER", "SPHER", "SPSPx"}, {"SPHER", "PLANx", "SPPLx"}, {"SPHER", "CYLND", "SPCDx"},
    {"SPHER", "DNLYC", "SPDCx"}, {"CYLND", "CYLND", "CDCDx"}, {"CYLND", "PLANx", "CDPLx"}, {"POLYR", "POLYR", "PRPRx"},
    {"POLYR", "PLANx", "PRPLx"}, {"POLYR", "ASpxx", "PRASp"}, {"CSxxx", "ASpxx", "CSASp"}, {"CSxxx", "POLYR", "CSPRx"},
    {"PT3Dx", "PT3Dx", "PTPT3"}, {"SPHER", "POLYR", "SPPRx"},
};

// The name a contactor goes by in '$seety' rows (contact-laws.md §1.2: DISKb is a DISKx,
// MAILx surfaces are CSxxx).
std::string see_name(const std::string& type) {
  if (type == "DISKb" || type == "DISPx") return "DISKx";
  if (type == "SPHEb") return "SPHER";
  if (type == "xPSID") return "xKSID";
  if (type.rfind("CSp", 0) == 0 || type.rfind("CSxx", 0) == 0) return "CSxxx";
  if (type.rfind("ASp", 0) == 0) return "ASpxx";
  if (type == "POLYF") return "POLYR";
  if (type == "PT2TL") return "PT2DL";
  return type;
}

const Family* family_of(std::string_view cd, std::string_view an) {
  for (const Family& f : kFamilies)
    if (f.candidate == cd && f.antagonist == an) return &f;
  return nullptr;
}

// A size that sets the scale of contacts for an alert distance: radius of disks and spheres,
// circumradius of polygons and polyhedra; walls and points have none.
double characteristic_size(const grammar::Contactor& c) {
  const std::string& t = c.type.value;
  if (t == "DISKx" || t == "DISKb" || t == "SPHER" || t == "SPHEb" || t == "xKSID" || t == "DISPx")
    return c.values.empty() ? 0.0 : c.values[0].value;
  if (t == "POLYG" || t == "POLYR") {
    double r = 0.0;
    for (const auto& v : c.vertices)
      for (const auto& w : c.vertices)
        r = std::max(r, std::sqrt(std::pow(v[0].value - w[0].value, 2) + std::pow(v[1].value - w[1].value, 2) +
                                  std::pow(v[2].value - w[2].value, 2)));
    return 0.5 * r;
  }
  if (t == "CYLND") return c.values.size() > 1 ? c.values[1].value : 0.0;
  return 0.0;
}

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
      ClassInfo& info = classes[{std::string(grammar::body_type_keyword(body.type)), see_name(c.type.value), c.color.value}];
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
    mentioned.insert({see.antagonist_body.value, see.antagonist_contactor.value, see.antagonist_colour.value});
    if (duplicates[i] != grammar::kNoDuplicate) {
      const grammar::SeeEntry& first = files.tact_behav->sees[duplicates[i]];
      if (first.law_nickname.value != see.law_nickname.value)
        sink.report(grammar::Diagnostic{
            "L2015", grammar::Severity::error, grammar::Location{path, see.law_nickname.span},
            fmt::format("this visibility row gives law '{}' to a pair that an earlier row gives law '{}'; LMGC90 stops "
                        "on it",
                        see.law_nickname.value, first.law_nickname.value),
            {{grammar::Location{path, first.law_nickname.span}, "the earlier row"}},
            {}});
      continue;
    }
    const Family* family = family_of(see.candidate_contactor.value, see.antagonist_contactor.value);
    if (!family) {
      const bool swapped = family_of(see.antagonist_contactor.value, see.candidate_contactor.value) != nullptr;
      sink.report("L2014", grammar::Location{path, see.candidate_contactor.span},
                  fmt::format("LMGC90 has no interaction with candidate '{}' and antagonist '{}'; this row creates no "
                              "contact",
                              see.candidate_contactor.value, see.antagonist_contactor.value),
                  swapped ? "swap the candidate and antagonist columns" : "");
      continue;
    }
    if (!present(see.candidate_body, see.candidate_contactor, see.candidate_colour) ||
        !present(see.antagonist_body, see.antagonist_contactor, see.antagonist_colour)) {
      const bool cd = present(see.candidate_body, see.candidate_contactor, see.candidate_colour);
      const grammar::SeeEntry& s = see;
      sink.report("L2010", grammar::Location{path, cd ? s.antagonist_contactor.span : s.candidate_contactor.span},
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
      sink.report("L3008", grammar::Location{path, see.alert.span},
                  fmt::format("alert distance {} is larger than the contactors it applies to (typical size {}): "
                              "contacts would be created far from touching",
                              see.alert.value, size),
                  "an alert distance of a few percent of the smallest radius is usual");
    else if (size > 0.0 && see.alert.value > 0.0 && see.alert.value < 1e-9 * size)
      sink.report("L3008", grammar::Location{path, see.alert.span},
                  fmt::format("alert distance {} is negligible against the contactors it applies to (typical size {}): "
                              "fast contacts may be missed",
                              see.alert.value, size));
  }
  // Colours of contactors that no visibility row mentions: they never touch anything.
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");
  for (const auto& [key, info] : classes) {
    if (mentioned.count(key)) continue;
    const auto& [body, type, colour] = key;
    if (type == "PT2Dx" || type == "PT3Dx") continue;  // points are often markers
    sink.report("L2011", grammar::Location{bodies_path, {}},
                fmt::format("{} contactors '{}' of colour '{}' ({} of them) appear in no visibility row: they never "
                            "touch anything",
                            body, type, colour, info.count));
  }
}

void check_case(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  check_references(files, sink);
  check_geometry(files, sink);
  check_contact_laws(files, sink);
  check_visibility(files, sink);
}

}  // namespace lmgc::validate
