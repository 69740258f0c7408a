#pragma once
// The one table of diagnostic codes. A code is never reused or renumbered; a retired code
// stays here marked `removed`. Families: L1xxx syntax (grammar), L2xxx references,
// L3xxx physical sanity, L4xxx run setup (COMMAND.DAT), L9xxx input/output.
#include <optional>
#include <span>
#include <string_view>

#include "grammar/common/diagnostic.hpp"

namespace lmgc::grammar {

struct DiagnosticKind {
  std::string_view code;
  Severity severity;
  std::string_view summary;      // one line, used by --explain and docs/diagnostics.md
  std::string_view explanation;  // longer text for --explain
  bool removed = false;
  // A feature of LMGC90 that lmgc-solve does not run yet: a warning for lmgc-check (the case is
  // valid for LMGC90), and lmgc-solve refuses the case (exit 5) rather than run another problem.
  bool refuses_run = false;
};

// True when a diagnostic of this code makes lmgc-solve refuse the case.
bool refuses_run(std::string_view code);

std::span<const DiagnosticKind> diagnostic_catalogue();
const DiagnosticKind* find_diagnostic_kind(std::string_view code);

}  // namespace lmgc::grammar
