#pragma once
// Semantic checks of a loaded case: cross references between files, consistency, physical sanity.
// Each check emits diagnostics with a stable code (grammar/common/diagnostic_catalogue.cpp);
// docs/diagnostics.md lists them with an example.
#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"

namespace lmgc::validate {

using case_folder::CaseFiles;  // the checks read the case as loaded (case_folder/)

// What the checks are told about the run.
struct CheckOptions {
  // COMMAND.DAT may drive the run (lmgc-solve --no-command-dat says it does not).
  bool command_dat = true;
  // COMMAND.DAT drives the run even when the case has a command.py (--command-dat).
  bool prefer_command_dat = false;
  // command.py is read, not run (lmgc-solve --read-script, or run-parameter flags): the calls only
  // a running script does (PutBodyVector, ...) are refused.
  bool script_read_only = false;
};

// The driver whose commands and parameters the run takes: the case's command.py (as LMGC90 2025,
// which no longer reads COMMAND.DAT) unless told otherwise, else COMMAND.DAT.
bool script_drives(const CaseFiles& files, const CheckOptions& options);
bool command_dat_drives(const CaseFiles& files, const CheckOptions& options);

// Every check below, in this order.
void check_case(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options = {});

// The families, callable one by one (tests).
// L2001-L2006, L2008, L2012, L2017: names a file gives to bodies, behaviours, models, laws, nodes.
void check_references(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L2003, L2006, L2007: bodies, elements, contactors and nodes named by the state files
// (Vloc_Rloc.INI, GPV.INI) and POSTPRO.DAT.
void check_state_references(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L2021, L2022: the points PTPT3_NETWORK.DAT links, and the visibility row of each link.
void check_ptpt3_network(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L2009, L2013, L2016, L2018-L2020: dimensions, element/model/law compatibility, evolution files.
void check_consistency(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L3001, L3009-L3011: contactor sizes, polygons, polyhedra, element Jacobians.
void check_geometry(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L3002-L3004, L3014: densities, elastic constants, loading.
void check_materials(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L3003, L3005-L3007, L3016: contact law parameters and alert distances.
void check_contact_laws(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L2010, L2011, L2014, L2015, L3008: the visibility table against the contactors present.
void check_visibility(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L3012: rigid contactors overlapping at the start.
void check_interpenetration(const CaseFiles& files, grammar::DiagnosticSink& sink);
// L3013: COMMAND.DAT's time step against the fastest time scales of the case.
void check_time_step(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options = {});

// L4005-L4007, L4009, L4010, L4012: what COMMAND.DAT and command.py ask of a run, and the case's
// multi-physics data, against what lmgc-solve runs.
void check_drivers(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options = {});

// Path of a DATBOX file of the case, as used in diagnostics.
std::string datbox_path(const CaseFiles& files, const std::string& name);

}  // namespace lmgc::validate
