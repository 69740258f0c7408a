// Physical sanity of TACT_BEHAV.DAT: friction, restitution, stiffnesses, alert distances.
// docs/lmgc90-facts/contact-laws.md §0 (parameters), §1.2 (alert).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {

void check_contact_laws(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.tact_behav) return;
  const std::string path = datbox_path(files, "TACT_BEHAV.DAT");
  for (const auto& law : files.tact_behav->laws) {
    const grammar::LawKind* kind = grammar::find_law_kind(law.keyword.value);
    if (!kind) continue;
    for (std::size_t i = 0; i < kind->parameters.size() && i < law.parameters.size(); ++i) {
      std::string_view name = kind->parameters[i];
      name = name.substr(0, name.find_last_not_of(' ') + 1);  // catalogue names are padded to 5
      const grammar::Real& value = law.parameters[i];
      const grammar::Location where{path, value.span};
      if ((name == "sfric" || name == "dfric" || name == "fric") && value.value < 0.0)
        sink.report("L3005", where,
                    fmt::format("friction coefficient '{}' of law '{}' is {}; it must be >= 0", name,
                                law.nickname.value, value.value));
      if ((name == "restn" || name == "restt") && (value.value < 0.0 || value.value > 1.0))
        sink.report("L3006", where,
                    fmt::format("restitution '{}' of law '{}' is {}; it must be in [0, 1]", name,
                                law.nickname.value, value.value));
      if ((name == "F/gap" || name == "F/str" || name == "cn" || name == "ct" || name == "kn" ||
           name == "kt") &&
          value.value <= 0.0)
        sink.report("L3003", where,
                    fmt::format("stiffness '{}' of law '{}' is {}; it must be > 0", name, law.nickname.value,
                                value.value));
    }
    // Static friction below dynamic friction is unusual but allowed: a warning.
    double s = -1, d = -1;
    for (std::size_t i = 0; i < kind->parameters.size() && i < law.parameters.size(); ++i) {
      if (kind->parameters[i] == "sfric") s = law.parameters[i].value;
      if (kind->parameters[i] == "dfric") d = law.parameters[i].value;
    }
    if (s >= 0 && d >= 0 && d > s)
      sink.report("L3016", grammar::Location{path, law.keyword.span},
                  fmt::format("law '{}' has a dynamic friction {} above its static friction {}",
                              law.nickname.value, d, s));
  }
  for (const auto& see : files.tact_behav->sees)
    if (!(see.alert.value > 0.0))
      sink.report("L3007", grammar::Location{path, see.alert.span},
                  fmt::format("alert distance is {}; it must be > 0 (contacts are created only within it)",
                              see.alert.value));
}

}  // namespace lmgc::validate
