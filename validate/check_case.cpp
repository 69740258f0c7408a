// All semantic checks of a loaded case, in a fixed order (references first, physics last), so
// that the diagnostics of a case always come in the same order. A check says nothing at a place
// where a reader already reported an error: the reader's diagnostic explains it (a rigid node
// other than 1 in DRV_DOF.DAT, two '$seety' rows with different laws, ...), and one error per
// place reads better than two.
#include <unordered_set>

#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

std::string place(const grammar::Location& where) {
  return where.file + ":" + std::to_string(where.span.line) + ":" + std::to_string(where.span.column);
}

}  // namespace

bool script_drives(const CaseFiles& files, const CheckOptions& options) {
  return files.command_script && !options.prefer_command_dat;
}
bool command_dat_drives(const CaseFiles& files, const CheckOptions& options) {
  return files.command && options.command_dat && !script_drives(files, options);
}

void check_case(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options) {
  std::unordered_set<std::string> reader_errors;
  for (const auto& d : sink.items())
    if (d.severity == grammar::Severity::error && d.where.span.line > 0) reader_errors.insert(place(d.where));

  grammar::DiagnosticSink checks(static_cast<std::size_t>(-1));
  check_references(files, checks);
  check_state_references(files, checks);
  check_ptpt3_network(files, checks);
  check_consistency(files, checks);
  check_geometry(files, checks);
  check_materials(files, checks);
  check_contact_laws(files, checks);
  check_visibility(files, checks);
  check_interpenetration(files, checks);
  check_time_step(files, checks, options);
  check_drivers(files, checks, options);

  for (const auto& d : checks.items())
    if (!reader_errors.count(place(d.where))) sink.report(d);
}

}  // namespace lmgc::validate
