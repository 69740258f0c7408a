// lmgc-check: reads a case folder like a compiler reads a program (syntax of every file, then the
// semantic checks of validate/checks.hpp), and reports every problem with its file, line and
// column. Exit: 0 no error, 1 errors in the data, 2 usage error or unreadable folder, 4 an echo
// file could not be written.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic_catalogue.hpp"
#include "grammar/common/output_file.hpp"
#include "lmgc_revision.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/case_input.hpp"
#include "solver/driver/run_loop.hpp"
#include "validate/checks.hpp"
#include "validate/render.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitDataErrors = 1;
constexpr int kExitUsage = 2;
constexpr int kExitOutput = 4;  // an echo file could not be written

int explain(const std::string& code) {
  const auto* kind = lmgc::grammar::find_diagnostic_kind(code);
  if (!kind) {
    std::cerr << "lmgc-check: unknown diagnostic code '" << code << "'\n";
    return kExitUsage;
  }
  std::cout << kind->code << " (" << lmgc::grammar::severity_name(kind->severity) << "): " << kind->summary
            << "\n\n"
            << kind->explanation << "\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lmgc-check: validate an LMGC90 case folder (CASE_DIR/DATBOX/) before running it"};
  std::string case_dir;
  std::string explain_code;
  bool echo = false, json = false, quiet = false, werror = false, no_color = false, command_dat = false;
  app.add_option("CASE_DIR", case_dir, "case folder holding DATBOX/");
  app.add_flag("--echo", echo,
               "also write the echo files LMGC90 writes when it reads the case (OUTBOX/*.OUT)");
  app.add_flag("--json", json,
               "print the diagnostics as one JSON array on standard output (schema: docs/diagnostics.md)");
  app.add_flag("-q,--quiet", quiet, "print only errors and the summary");
  app.add_flag("--werror", werror, "treat warnings as errors (exit code 1)");
  app.add_flag("--no-color", no_color, "never color the output (NO_COLOR in the environment does the same)");
  bool read_script = false;
  app.add_flag("--read-script", read_script,
               "check command.py as lmgc-solve --read-script runs it: read, not run (what it computes is "
               "named, L4013; the calls only a running script does are refused, L4005)");
  app.add_flag(
      "--command-dat", command_dat,
      "check the case as lmgc-solve --command-dat runs it: driven by DATBOX/COMMAND.DAT even when it "
      "has a command.py");
  app.add_option("--explain", explain_code, "print the long description of a diagnostic code and exit");
  app.set_version_flag("--version",
                       std::string("lmgc-check ") + LMGC_VERSION + " (revision " + LMGC_REVISION + ")");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  if (!explain_code.empty()) return explain(explain_code);
  if (case_dir.empty()) {
    std::cerr << "lmgc-check: missing CASE_DIR\n" << app.help();
    return kExitUsage;
  }

  lmgc::solver::ignore_file_size_signal();
  lmgc::grammar::DiagnosticSink sink(5000);
  auto files = lmgc::case_folder::load_case(case_dir, sink);
  // Semantic checks (references, consistency, physics) run on whatever could be read: a file
  // with syntax errors still gets its cross references checked.
  if (files) {
    lmgc::validate::CheckOptions options{true, command_dat};
    options.script_read_only = read_script;
    lmgc::validate::check_case(*files, sink, options);
    // What lmgc-solve would refuse or leave out: warnings here, for a case valid for LMGC90.
    lmgc::solver::report_solver_support(*files, sink);
    // The run parameters of the script that drives the run: out of range (L4010) or computed (L4013).
    // By default the script runs (lmgc-run): a computed value is then known; only --read-script
    // has to name it.
    if (lmgc::validate::script_drives(*files, options)) {
      lmgc::run::RunOptions run;
      lmgc::run::ParameterSources sources;
      lmgc::grammar::DiagnosticSink script_sink(5000);
      lmgc::run::apply_script_parameters(*files->command_script, lmgc::solver::is_rigid_3d_case(*files), run,
                                         sources, script_sink);
      for (const auto& d : script_sink.items())
        if (read_script || d.code != "L4013") sink.report(d);
    }
  }

  // Echo files are written only from a case that read without error, and never into DATBOX/.
  if (files && echo && !sink.has_errors()) {
    // As lmgc-solve writes them: BODIES.OUT after LMGC90's rigid pre-computations (avrd, gyrd,
    // centre and frame of inertia).
    const bool three_d = lmgc::solver::is_rigid_3d_case(*files);
    for (const auto& output :
         three_d ? lmgc::solver::echo_files_3d(*files) : lmgc::solver::echo_files_2d(*files)) {
      std::string error;
      if (!lmgc::grammar::write_file_whole(std::filesystem::path(case_dir) / output.relative_path,
                                           output.content, error))
        sink.report(
            "L9003",
            lmgc::grammar::Location{(std::filesystem::path(case_dir) / output.relative_path).string(), {}},
            error);
    }
  }

  std::size_t notes = 0;
  for (const auto& d : sink.items()) notes += d.severity == lmgc::grammar::Severity::note;
  std::vector<lmgc::grammar::Diagnostic> shown = sink.items();
  for (auto& d : sink.overflow_diagnostic()) shown.push_back(std::move(d));
  if (json) {
    std::cout << lmgc::validate::render_json(shown) << "\n";
  } else {
    const bool color = !no_color && std::getenv("NO_COLOR") == nullptr && isatty(STDOUT_FILENO);
    const auto lookup = [&](const std::string& file, std::uint32_t line) -> std::string_view {
      if (!files) return {};
      auto it = files->sources.find(file);
      return it == files->sources.end() ? std::string_view{} : it->second.line_text(line);
    };
    for (const auto& d : shown) {
      if (quiet && d.severity != lmgc::grammar::Severity::error) continue;
      std::cout << lmgc::validate::render_text(d, lookup, {color});
    }
    std::cout << lmgc::validate::render_summary(sink.error_count(), sink.warning_count(), notes) << "\n";
  }
  if (!files) return kExitUsage;
  bool write_failed = false;
  for (const auto& d : sink.items()) write_failed |= d.code == "L9003";
  if (write_failed) return kExitOutput;
  if (sink.has_errors() || (werror && sink.warning_count() > 0)) return kExitDataErrors;
  return kExitOk;
}
