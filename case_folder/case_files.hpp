#pragma once
// A case folder as read from disk: every file of CASE_DIR/DATBOX/ that LMGC90 reads, parsed into
// its AST, with the source text kept for diagnostics. The one table of DATBOX file kinds lives in
// case_files.cpp.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grammar/bodies/ast.hpp"
#include "grammar/bulk_behav/ast.hpp"
#include "grammar/command/ast.hpp"
#include "grammar/command_py/script.hpp"
#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/dof/ast.hpp"
#include "grammar/drv_dof/ast.hpp"
#include "grammar/gpv/ast.hpp"
#include "grammar/models/ast.hpp"
#include "grammar/postpro/ast.hpp"
#include "grammar/ptpt3_network/ast.hpp"
#include "grammar/tact_behav/ast.hpp"
#include "grammar/vloc_rloc/ast.hpp"

namespace lmgc::case_folder {

struct CaseFiles {
  std::filesystem::path case_dir;
  // Source texts by the path shown in diagnostics (e.g. "case/DATBOX/BODIES.DAT").
  std::map<std::string, grammar::SourceText> sources;

  std::optional<grammar::BodiesFile> bodies;
  std::optional<grammar::BulkBehavFile> bulk_behav;
  std::optional<grammar::TactBehavFile> tact_behav;
  std::optional<grammar::ModelsFile> models;
  std::optional<grammar::DrvDofFile> drv_dof;
  std::optional<grammar::DofFile> dof_ini;
  std::optional<grammar::VlocRlocFile> vloc_rloc_ini;
  std::optional<grammar::GpvFile> gpv_ini;
  std::optional<grammar::PostproFile> postpro;
  std::optional<grammar::CommandFile> command;
  // Read when present; a run uses it when asked (lmgc-solve --ptpt3-network, PTPT3_LoadNetwork).
  std::optional<grammar::Ptpt3NetworkFile> ptpt3_network;
  // DATBOX/EXACT_STATE.INI: lmgc's full-precision restart state (a copy of a run's
  // OUTBOX/EXACT_STATE.LAST), not an LMGC90 file; its bytes.
  std::optional<std::string> exact_state;
  // CASE_DIR/command.py, the script LMGC90 runs (read, never run: its literals and chipy calls).
  std::optional<grammar::CommandScript> command_script;
  // Evolution files named by DRV_DOF.DAT, by file name.
  std::map<std::string, grammar::EvolutionFile> evolutions;
  // DATBOX files LMGC90 does not read (legacy or pre-processor files).
  std::vector<std::string> unread_files;
};

// Which of the files a run reads only when its script asks for them are read.
struct LoadOptions {
  // PTPT3_NETWORK.DAT (PTPT3_LoadNetwork): lmgc-check reads it when present; lmgc-solve only with
  // --ptpt3-network, as LMGC90 (else it is a file the run does not read, note L1021).
  bool ptpt3_network = true;
};

// Reads CASE_DIR/DATBOX/. Returns nullopt (after reporting L9002) when the folder is not a case.
std::optional<CaseFiles> load_case(const std::filesystem::path& case_dir, grammar::DiagnosticSink& sink,
                                   const LoadOptions& options = {});

// The echo files LMGC90 writes when it reads the case: path relative to the case folder
// (OUTBOX/BODIES.OUT, ..., POSTPRO/POSTPRO.OUT) and content.
struct OutputFile {
  std::filesystem::path relative_path;
  std::string content;
};
std::vector<OutputFile> echo_files(const CaseFiles& files);

}  // namespace lmgc::case_folder
