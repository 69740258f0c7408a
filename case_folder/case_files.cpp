// Loading a case folder: which DATBOX files LMGC90 reads and how each is parsed and echoed.
// docs/lmgc90-facts/state-and-outputs.md §0 (layout), §1.6 (echo files); datbox-inputs.md §5 (evolution).
#include "case_folder/case_files.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <system_error>

#include "grammar/bodies/parser.hpp"
#include "grammar/bodies/writer.hpp"
#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/common/input_file.hpp"
#include "grammar/dof/parser.hpp"
#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"
#include "grammar/gpv/parser.hpp"
#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"
#include "grammar/postpro/parser.hpp"
#include "grammar/ptpt3_network/parser.hpp"
#include "grammar/tact_behav/parser.hpp"
#include "grammar/tact_behav/writer.hpp"
#include "grammar/vloc_rloc/parser.hpp"

namespace lmgc::case_folder {
namespace {

namespace fs = std::filesystem;
using grammar::DiagnosticSink;
using grammar::SourceText;

// Which files a case must have. The thermal examples of LMGC90 run without TACT_BEHAV.DAT and
// Vloc_Rloc.INI (no contactor, so no interaction to read), so TACT_BEHAV.DAT is needed only when a
// body carries contactors. ReadDatbox reads Vloc_Rloc.INI whenever TACT_BEHAV.DAT defines a law
// (macro.py, tact_behav_GetNbTactBehav() > 0), and LMGC90 stops when it is missing ('keyword
// steps not found': Fortran creates the file empty): required then, even with no interaction.
enum class Requirement { always, with_mailx, with_contactors, with_laws, optional };

// The DATBOX files LMGC90 reads (ChiPy ReadDatbox, the legacy COMMAND.DAT driver, and
// PTPT3_LoadNetwork's PTPT3_NETWORK.DAT).
struct DatboxFileKind {
  std::string_view name;
  Requirement requirement;
  void (*parse)(CaseFiles&, const SourceText&, DiagnosticSink&);
  // A file LMGC90 reads only when the run's script asks for it: the option that says so, and how.
  bool LoadOptions::*asked = nullptr;
  std::string_view asked_as = {};
};

constexpr DatboxFileKind kDatboxFiles[] = {
    {"BODIES.DAT", Requirement::always,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.bodies = grammar::parse_bodies(s, d); }},
    {"BULK_BEHAV.DAT", Requirement::always,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) {
       c.bulk_behav = grammar::parse_bulk_behav(s, d);
     }},
    {"TACT_BEHAV.DAT", Requirement::with_contactors,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) {
       c.tact_behav = grammar::parse_tact_behav(s, d);
     }},
    {"MODELS.DAT", Requirement::with_mailx,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.models = grammar::parse_models(s, d); }},
    {"DRV_DOF.DAT", Requirement::always,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.drv_dof = grammar::parse_drv_dof(s, d); }},
    {"DOF.INI", Requirement::always,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.dof_ini = grammar::parse_dof(s, d); }},
    {"Vloc_Rloc.INI", Requirement::with_laws,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) {
       c.vloc_rloc_ini = grammar::parse_vloc_rloc(s, d);
     }},
    {"GPV.INI", Requirement::with_mailx,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.gpv_ini = grammar::parse_gpv(s, d); }},
    {"POSTPRO.DAT", Requirement::optional,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.postpro = grammar::parse_postpro(s, d); }},
    {"COMMAND.DAT", Requirement::optional,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) { c.command = grammar::parse_command(s, d); }},
    {"PTPT3_NETWORK.DAT", Requirement::optional,
     [](CaseFiles& c, const SourceText& s, DiagnosticSink& d) {
       c.ptpt3_network = grammar::parse_ptpt3_network(s, d);
     },
     &LoadOptions::ptpt3_network, "lmgc-solve --ptpt3-network, PTPT3_LoadNetwork"},
};

bool has_contactors(const CaseFiles& c) {
  if (!c.bodies) return false;
  for (const auto& b : c.bodies->bodies)
    if (!b.contactors.empty()) return true;
  return false;
}

bool has_laws(const CaseFiles& c) {
  return c.tact_behav && !c.tact_behav->laws.empty();
}

bool has_mailx(const CaseFiles& c) {
  if (!c.bodies) return false;
  for (const auto& b : c.bodies->bodies)
    if (b.type == grammar::BodyType::mailx) return true;
  return false;
}

}  // namespace

std::optional<CaseFiles> load_case(const fs::path& case_dir, DiagnosticSink& sink,
                                   const LoadOptions& options) {
  std::error_code ec;
  const fs::path datbox = case_dir / "DATBOX";
  if (!fs::is_directory(case_dir, ec) || !fs::is_directory(datbox, ec)) {
    sink.report("L9002", grammar::Location{case_dir.string(), {}},
                fs::is_directory(case_dir, ec) ? "'" + case_dir.string() + "' has no DATBOX/ folder"
                                               : "'" + case_dir.string() + "' is not a folder");
    return std::nullopt;
  }
  CaseFiles files;
  files.case_dir = case_dir;
  std::set<std::string> known;
  // A file that exists is read whole, or refused when it is not one (L9001): nullptr then; `missing`
  // is set when nothing is at the path.
  auto read_source = [&](const std::string& name, bool* missing = nullptr) -> const SourceText* {
    const fs::path path = datbox / name;
    grammar::InputFile input = grammar::read_input_file(path);
    if (missing) *missing = input.status == grammar::InputFileStatus::missing;
    if (input.status != grammar::InputFileStatus::read) {
      if (input.status == grammar::InputFileStatus::refused || !missing)
        sink.report("L9001", grammar::Location{path.string(), {}},
                    "cannot read '" + path.string() +
                        "': " + (input.error.empty() ? std::string("no such file") : input.error));
      return nullptr;
    }
    auto [it, inserted] =
        files.sources.emplace(path.string(), SourceText(path.string(), std::move(input.text)));
    return &it->second;
  };

  std::map<std::string, std::string_view> not_asked;  // file name → how a run asks for it
  for (const DatboxFileKind& kind : kDatboxFiles) {
    const std::string name(kind.name);
    if (kind.asked && !(options.*kind.asked)) {
      not_asked.emplace(name, kind.asked_as);
      continue;
    }
    known.insert(name);
    const fs::path path = datbox / name;
    bool missing = false;
    const SourceText* source = read_source(name, &missing);
    if (missing) {
      const bool required = kind.requirement == Requirement::always ||
                            (kind.requirement == Requirement::with_mailx && has_mailx(files)) ||
                            (kind.requirement == Requirement::with_contactors && has_contactors(files)) ||
                            (kind.requirement == Requirement::with_laws && has_laws(files));
      const char* which = kind.requirement == Requirement::with_mailx        ? " with MAILx bodies"
                          : kind.requirement == Requirement::with_contactors ? " with contactors"
                          : kind.requirement == Requirement::with_laws
                              ? " whose TACT_BEHAV.DAT defines a law, and stops without it (write one with "
                                "its '$steps' header and no interaction)"
                              : "";
      if (required)
        sink.report("L9001", grammar::Location{path.string(), {}},
                    "'" + name + "' is missing; LMGC90 reads it for every case" + which);
      continue;
    }
    if (source) kind.parse(files, *source, sink);
  }

  // Evolution files named by driven dofs.
  if (files.drv_dof) {
    for (const auto& body : files.drv_dof->bodies)
      for (const auto& node : body.nodes)
        for (const auto& dof : node.dofs) {
          if (!dof.uses_evolution) continue;
          const std::string name = dof.evolution_file.value;
          if (name.empty() || files.evolutions.count(name) || known.count(name)) continue;
          known.insert(name);
          bool missing = false;
          const SourceText* source = read_source(name, &missing);
          if (missing) {
            sink.report("L9001",
                        grammar::Location{(datbox / "DRV_DOF.DAT").string(), dof.evolution_file.span},
                        "evolution file '" + name + "' named here does not exist in DATBOX/");
            continue;
          }
          if (source) files.evolutions.emplace(name, grammar::parse_evolution(*source, sink));
        }
  }

  // lmgc's exact restart state (known: never "not read by LMGC90").
  {
    const fs::path path = datbox / "EXACT_STATE.INI";
    grammar::InputFile input = grammar::read_input_file(path);
    known.insert("EXACT_STATE.INI");
    if (input.status == grammar::InputFileStatus::refused)
      sink.report("L9001", grammar::Location{path.string(), {}},
                  "cannot read '" + path.string() + "': " + input.error);
    else if (input.status == grammar::InputFileStatus::read)
      files.exact_state = std::move(input.text);
  }

  // The Python driver beside DATBOX/.
  {
    const fs::path path = case_dir / "command.py";
    grammar::InputFile input = grammar::read_input_file(path);
    if (input.status == grammar::InputFileStatus::refused) {
      sink.report("L9001", grammar::Location{path.string(), {}},
                  "cannot read '" + path.string() + "': " + input.error);
    } else if (input.status == grammar::InputFileStatus::read) {
      auto [it, inserted] =
          files.sources.emplace(path.string(), SourceText(path.string(), std::move(input.text)));
      files.command_script = grammar::read_command_script(path.string(), it->second.text());
    }
  }

  // Everything else in DATBOX/ is not read by LMGC90: say so once per file.
  std::vector<std::string> others;
  // The error_code forms throughout: a symbolic link loop in DATBOX/ is a file to report, not an
  // exception.
  for (fs::directory_iterator it(datbox, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code entry_ec;
    if (it->is_regular_file(entry_ec) && !known.count(it->path().filename().string()))
      others.push_back(it->path().filename().string());
  }
  std::sort(others.begin(), others.end());
  for (const auto& name : others) {
    files.unread_files.push_back(name);
    // LMGC90's multi-physics and PTPT2 scripts read these (check_drivers says so, L4007).
    if (name == "MP_DEM.DAT" || name == "PTPT2_NETWORK.DAT") continue;
    const auto asked = not_asked.find(name);
    sink.report("L1021", grammar::Location{(datbox / name).string(), {}},
                asked != not_asked.end()
                    ? "'" + name + "' is read only when the run asks for it (" + std::string(asked->second) +
                          "); this run does not, so it is not checked"
                    : "'" + name + "' is not read by LMGC90; it is not checked");
  }
  return files;
}

namespace {

// What the run's modules are, from BODIES.DAT and MODELS.DAT: LMGC90 writes each module's part of
// DRV_DOF.OUT (its closing dashed line too) when the module has bodies, driven or not, and a MAILx
// node's type from the mesh's dimension.
grammar::DrvDofEchoSetup drv_dof_echo_setup(const CaseFiles& c) {
  grammar::DrvDofEchoSetup setup = grammar::drv_dof_echo_setup_of(*c.drv_dof);
  if (!c.bodies) return setup;
  setup.dimension = grammar::bodies_dimension(*c.bodies);
  for (const grammar::Body& body : c.bodies->bodies) {
    if (body.type != grammar::BodyType::mailx) continue;
    setup.node_type_from_mesh = true;
    if (!c.models) continue;
    for (const grammar::Element& element : body.elements)
      for (const grammar::ModelReference& reference : element.models)
        for (const grammar::Model& model : c.models->models)
          if (model.nickname.value == reference.model.value) {
            setup.meca_mailx |= model.kind.value == "MECAx";
            setup.ther_mailx |= model.kind.value == "THERM";
            setup.poro_mailx |= model.kind.value == "POROx";
          }
  }
  return setup;
}

}  // namespace

std::vector<OutputFile> echo_files(const CaseFiles& c) {
  std::vector<OutputFile> out;
  if (c.bodies) out.push_back({"OUTBOX/BODIES.OUT", grammar::write_bodies(*c.bodies)});
  if (c.bulk_behav) out.push_back({"OUTBOX/BULK_BEHAV.OUT", grammar::write_bulk_behav(*c.bulk_behav)});
  // LMGC90 writes TACT_BEHAV.OUT even without TACT_BEHAV.DAT (its comment block, no law).
  out.push_back({"OUTBOX/TACT_BEHAV.OUT",
                 grammar::write_tact_behav(c.tact_behav ? *c.tact_behav : grammar::TactBehavFile{})});
  if (c.models) out.push_back({"OUTBOX/MODELS.OUT", grammar::write_models(*c.models)});
  if (c.drv_dof)
    out.push_back({"OUTBOX/DRV_DOF.OUT", grammar::write_drv_dof(*c.drv_dof, drv_dof_echo_setup(c))});
  // LMGC90 rewrites each evolution file into OUTBOX/ (datbox-inputs.md §5).
  for (const auto& [name, evolution] : c.evolutions)
    out.push_back({fs::path("OUTBOX") / name, grammar::write_evolution(evolution)});
  // POSTPRO.OUT is created empty in POSTPRO/ (datbox-inputs.md §8).
  if (c.postpro) out.push_back({"POSTPRO/POSTPRO.OUT", ""});
  return out;
}

}  // namespace lmgc::case_folder
