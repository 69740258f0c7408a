#pragma once
// Semantic checks of a loaded case: cross references between files, consistency, physical sanity.
// Each check emits diagnostics with a stable code (grammar/common/diagnostic_catalogue.cpp).
#include "grammar/common/diagnostic.hpp"
#include "validate/case_files.hpp"

namespace lmgc::validate {

void check_case(const CaseFiles& files, grammar::DiagnosticSink& sink);

// The families, callable one by one (tests).
void check_references(const CaseFiles& files, grammar::DiagnosticSink& sink);
void check_geometry(const CaseFiles& files, grammar::DiagnosticSink& sink);
void check_contact_laws(const CaseFiles& files, grammar::DiagnosticSink& sink);
void check_visibility(const CaseFiles& files, grammar::DiagnosticSink& sink);

// Path of a DATBOX file of the case, as used in diagnostics.
std::string datbox_path(const CaseFiles& files, const std::string& name);

}  // namespace lmgc::validate
