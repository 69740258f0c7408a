// What the initial state files, PTPT3_NETWORK.DAT and POSTPRO.DAT name: the bodies and contactors
// of the interactions of Vloc_Rloc.INI, the bodies and elements of GPV.INI, the points of the
// PTPT3 network, the bodies and nodes of POSTPRO.DAT's commands. docs/lmgc90-facts/datbox-inputs.md §7
// (Vloc_Rloc.INI, GPV.INI), §8 (POSTPRO.DAT); PTPT3_NETWORK.DAT: grammar/ptpt3_network/ast.hpp.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "grammar/command/expand.hpp"
#include "grammar/common/exact_state_header.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "validate/case_index.hpp"
#include "validate/checks.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

// One side of an interaction: body model, body rank, contactor type, contactor rank.
struct InteractionSide {
  const grammar::Word* body_type = nullptr;
  const grammar::Integer* body = nullptr;
  const grammar::Word* contactor_type = nullptr;
  const grammar::Integer* contactor = nullptr;
};

// The candidate and antagonist of a Vloc_Rloc data line. Every module writes
// 'cdbdy numbr cdtac numbr' first; the antagonist is the first body model word after them,
// followed by its number, its contactor type and number (interaction_catalogue.cpp formats).
std::optional<std::pair<InteractionSide, InteractionSide>> interaction_sides(
    const grammar::VlocRlocInteraction& interaction) {
  const grammar::InteractionKind* kind =
      grammar::find_interaction_kind(interaction.type.value, interaction.xxl);
  if (!kind) return std::nullopt;
  struct Item {
    const grammar::Word* word = nullptr;
    const grammar::Integer* integer = nullptr;
  };
  std::vector<Item> items;
  std::size_t w = 0, i = 0;
  for (const grammar::DataItem& d : grammar::data_items(kind->data_format)) {
    if (d.kind == 'A' && w < interaction.words.size()) items.push_back({&interaction.words[w++], nullptr});
    if (d.kind == 'I' && i < interaction.integers.size())
      items.push_back({nullptr, &interaction.integers[i++]});
  }
  auto side = [&](std::size_t at) -> std::optional<InteractionSide> {
    if (at + 3 >= items.size() || !items[at].word || !items[at + 1].integer || !items[at + 2].word ||
        !items[at + 3].integer)
      return std::nullopt;
    return InteractionSide{items[at].word, items[at + 1].integer, items[at + 2].word, items[at + 3].integer};
  };
  const auto candidate = side(0);
  if (!candidate) return std::nullopt;
  for (std::size_t k = 4; k < items.size(); ++k)
    if (items[k].word && body_type_index(items[k].word->value) >= 0) {
      const auto antagonist = side(k);
      if (!antagonist) return std::nullopt;
      return std::make_pair(*candidate, *antagonist);
    }
  return std::nullopt;
}

// Reads the integers of POSTPRO.DAT argument lines in order (one command's arguments).
class ArgumentCursor {
 public:
  explicit ArgumentCursor(const grammar::PostproCommand& command) : command_(command) {}
  // The integers of the next argument line, or nullptr at the end.
  const std::vector<grammar::Integer>* next() {
    if (at_ >= command_.arguments.size()) return nullptr;
    return &command_.arguments[at_++].integers;
  }

 private:
  const grammar::PostproCommand& command_;
  std::size_t at_ = 0;
};

}  // namespace

namespace {

// The run's time step as lmgc-check can know it: COMMAND.DAT's, else the script's literal, else
// lmgc-solve's default.
double expected_time_step(const CaseFiles& files) {
  if (files.command) {
    grammar::DiagnosticSink scratch(static_cast<std::size_t>(-1));
    const grammar::CommandRunParameters p = grammar::command_run_parameters(*files.command, scratch);
    if (p.lines.count("dt") && p.dt > 0.0) return p.dt;
  }
  if (files.command_script)
    for (const grammar::ScriptCall* call : files.command_script->calls_to("TimeEvolution_SetTimeStep"))
      if (!call->arguments.empty() && call->arguments[0].value.number &&
          *call->arguments[0].value.number > 0.0)
        return *call->arguments[0].value.number;
  return 1e-3;
}

}  // namespace

// A restart reads the step and time of DOF.INI; LMGC90 stops when Vloc_Rloc.INI was written at
// another step or a time more than 1e-3 time steps away (Read_in_Vloc_Rloc), and when GPV.INI's
// differ at all (Read_in_gpv): L1020 on the other file's '$steps' line.
void check_state_headers(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.dof_ini) return;
  const grammar::DofFile& dof = *files.dof_ini;
  const auto mismatch = [&](const char* name, const grammar::Integer& step, const grammar::Real& time,
                            double time_tolerance) {
    if (step.value == dof.step.value && std::abs(time.value - dof.time.value) <= time_tolerance) return;
    grammar::Diagnostic d;
    d.code = "L1020";
    d.severity = grammar::Severity::error;
    d.where = grammar::Location{datbox_path(files, name), step.span};
    d.message = std::string(name) + " was written at step " + std::to_string(step.value) + ", time " +
                fmt::format("{}", time.value) + "; DOF.INI at step " + std::to_string(dof.step.value) +
                ", time " + fmt::format("{}", dof.time.value) + ": LMGC90 stops on such a restart";
    d.related.push_back(
        {grammar::Location{datbox_path(files, "DOF.INI"), dof.step.span}, "DOF.INI's step and time"});
    d.hint = "copy DOF.LAST and Vloc_Rloc.LAST (and GPV.LAST) of the same run together";
    sink.report(std::move(d));
  };
  if (files.vloc_rloc_ini)
    mismatch("Vloc_Rloc.INI", files.vloc_rloc_ini->step, files.vloc_rloc_ini->time,
             1e-3 * expected_time_step(files));
  if (files.gpv_ini) mismatch("GPV.INI", files.gpv_ini->step, files.gpv_ini->time, 0.0);
  // lmgc's exact state: the run it continues must be the one DOF.INI comes from (its time printed
  // with 7 digits).
  if (files.exact_state) {
    const std::string path = datbox_path(files, "EXACT_STATE.INI");
    const auto header = grammar::read_exact_state_header(*files.exact_state);
    if (!header) {
      sink.report(
          "L1012", grammar::Location{path, {}},
          "EXACT_STATE.INI does not start with lmgc's exact-state line: not a copy of EXACT_STATE.LAST");
    } else if (header->step != dof.step.value ||
               std::abs(header->time - dof.time.value) > 1e-6 * std::abs(header->time) + 1e-300) {
      grammar::Diagnostic d;
      d.code = "L1020";
      d.severity = grammar::Severity::error;
      d.where = grammar::Location{path, grammar::SourceSpan{1, 1, 2}};
      d.message = "EXACT_STATE.INI was written at step " + std::to_string(header->step) + ", time " +
                  fmt::format("{}", header->time) + "; DOF.INI at step " + std::to_string(dof.step.value) +
                  ", time " + fmt::format("{}", dof.time.value);
      d.hint = "copy EXACT_STATE.LAST with the DOF.LAST of the same run, or remove it";
      sink.report(std::move(d));
    }
  }
}

void check_state_references(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  check_state_headers(files, sink);
  if (!files.bodies) return;
  const BodyIndex index(*files.bodies);
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");

  // Vloc_Rloc.INI: LMGC90 skips an interaction whose contactors do not exist (read_ini_Vloc_Rloc
  // finds no contactor to attach it to): its initial reaction is silently lost.
  if (files.vloc_rloc_ini) {
    const std::string path = datbox_path(files, "Vloc_Rloc.INI");
    for (const auto& interaction : files.vloc_rloc_ini->interactions) {
      const auto sides = interaction_sides(interaction);
      if (!sides) continue;
      for (const InteractionSide& s : {sides->first, sides->second}) {
        const grammar::Body* body = index.find(s.body_type->value, s.body->value);
        if (!body) {
          sink.report(
              "L2007", grammar::Location{path, s.body->span},
              fmt::format("interaction {} {} names {} body {}, which does not exist (BODIES.DAT has {} {} "
                          "bodies); LMGC90 skips it",
                          interaction.type.value, interaction.number.value, s.body_type->value, s.body->value,
                          index.count(s.body_type->value), s.body_type->value));
          break;
        }
        if (body->type == grammar::BodyType::mailx) continue;  // MAILx contactors are numbered per patch
        const std::int64_t k = s.contactor->value;
        if (k < 1 || k > static_cast<std::int64_t>(body->contactors.size())) {
          sink.report(
              "L2007", grammar::Location{path, s.contactor->span},
              fmt::format(
                  "interaction {} {} names contactor {} of {}, which has {} contactor{}; LMGC90 skips "
                  "it",
                  interaction.type.value, interaction.number.value, k, body_name(*body, index.rank_of(*body)),
                  body->contactors.size(), body->contactors.size() == 1 ? "" : "s"));
          break;
        }
        const grammar::Contactor& c = body->contactors[static_cast<std::size_t>(k - 1)];
        if (see_name(c.type.value) != see_name(s.contactor_type->value)) {
          report_related(
              sink, "L2007", grammar::Location{path, s.contactor_type->span},
              fmt::format("interaction {} {} names a {} as contactor {} of {}, which is a {}; LMGC90 "
                          "skips it",
                          interaction.type.value, interaction.number.value, s.contactor_type->value, k,
                          body_name(*body, index.rank_of(*body)), c.type.value),
              {{grammar::Location{bodies_path, c.type.span}, "the contactor is defined here"}});
          break;
        }
      }
    }
  }

  // GPV.INI: LMGC90 stops on a body outside the collection and reads elements by rank.
  if (files.gpv_ini) {
    const std::string path = datbox_path(files, "GPV.INI");
    for (const auto& gpv_body : files.gpv_ini->bodies) {
      const grammar::Body* body = index.find("MAILx", gpv_body.number.value);
      if (!body) {
        sink.report("L2003", grammar::Location{path, gpv_body.number.span},
                    fmt::format("MAILx body {} does not exist (BODIES.DAT has {} MAILx bodies)",
                                gpv_body.number.value, index.count("MAILx")));
        continue;
      }
      for (const auto& element : gpv_body.elements) {
        const std::int64_t e = element.number.value;
        if (e < 1 || e > static_cast<std::int64_t>(body->elements.size())) {
          sink.report("L2006", grammar::Location{path, element.number.span},
                      fmt::format("element {} of MAILx body {} does not exist (it has {} elements)", e,
                                  gpv_body.number.value, body->elements.size()));
          continue;
        }
        const grammar::Element& real = body->elements[static_cast<std::size_t>(e - 1)];
        if (real.type.value != element.type.value)
          report_related(sink, "L2006", grammar::Location{path, element.type.span},
                         fmt::format("element {} of MAILx body {} is a {}, not a {}", e,
                                     gpv_body.number.value, real.type.value, element.type.value),
                         {{grammar::Location{bodies_path, real.type.span}, "the element is defined here"}});
      }
    }
  }

  // POSTPRO.DAT: the body ranks of the commands that name rigid bodies (RBDY2 in 2D, RBDY3 in
  // 3D) and the MAILx bodies and nodes of 'NEW MECAx SETS'.
  if (files.postpro) {
    const std::string path = datbox_path(files, "POSTPRO.DAT");
    const std::string rigid = case_dimension(files) == 3 ? "RBDY3" : "RBDY2";
    auto check_body = [&](const std::string& type, const grammar::Integer& rank,
                          const grammar::Word& command) {
      const grammar::Body* body = index.find(type, rank.value);
      if (!body)
        report_related(
            sink, "L2003", grammar::Location{path, rank.span},
            fmt::format("{} body {} does not exist (BODIES.DAT has {} {} bodies)", type, rank.value,
                        index.count(type), type),
            {{grammar::Location{path, command.span}, fmt::format("named by '{}'", command.value)}});
      return body;
    };
    for (const auto& command : files.postpro->commands) {
      const std::string& name = command.name.value;
      ArgumentCursor args(command);
      if (name == "BODY TRACKING" || name == "TORQUE EVOLUTION") {
        const auto* n = args.next();
        if (!n || n->empty()) continue;
        for (std::int64_t k = 0; k < n->front().value; ++k) {
          const auto* line = args.next();
          if (!line) break;
          if (!line->empty()) check_body(rigid, line->front(), command.name);
        }
      } else if (name == "NEW RIGID SETS") {
        const auto* sets = args.next();
        for (std::int64_t s = 0; sets && !sets->empty() && s < sets->front().value; ++s) {
          const auto* size = args.next();
          if (!size || size->empty()) break;
          for (std::int64_t k = 0; k < size->front().value; ++k) {
            const auto* line = args.next();
            if (!line) break;
            if (!line->empty()) check_body(rigid, line->front(), command.name);
          }
        }
      } else if (name == "NEW MECAx SETS") {
        const auto* sets = args.next();
        for (std::int64_t s = 0; sets && !sets->empty() && s < sets->front().value; ++s) {
          const auto* members = args.next();
          if (!members || members->empty()) break;
          for (std::int64_t m = 0; m < members->front().value; ++m) {
            const auto* member = args.next();  // (I7,1X,I7): body, number of nodes
            if (!member || member->size() < 2) break;
            const grammar::Body* body = check_body("MAILx", (*member)[0], command.name);
            for (std::int64_t k = 0; k < (*member)[1].value; ++k) {
              const auto* line = args.next();
              if (!line) break;
              if (!body || line->empty()) continue;
              const grammar::Integer& node = line->front();
              if (node.value < 1 || node.value > static_cast<std::int64_t>(body->nodes.size()))
                sink.report("L2006", grammar::Location{path, node.span},
                            fmt::format("node {} of MAILx body {} does not exist (it has {} nodes)",
                                        node.value, (*member)[0].value, body->nodes.size()));
            }
          }
        }
      }
    }
  }
}

void check_ptpt3_network(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.ptpt3_network || !files.bodies) return;
  // The PT3Dx of the case in LMGC90's numbering: BODIES.DAT order over the RBDY3 bodies.
  struct Point {
    const grammar::Body* body;
    std::size_t body_rank;
    const grammar::Contactor* contactor;
  };
  std::vector<Point> points;
  std::size_t rank = 0;
  for (const grammar::Body& body : files.bodies->bodies) {
    if (body.type != grammar::BodyType::rbdy3) continue;
    ++rank;
    for (const grammar::Contactor& c : body.contactors)
      if (c.type.value == "PT3Dx") points.push_back({&body, rank, &c});
  }
  std::optional<SeeTable> see;
  if (files.tact_behav) see.emplace(*files.tact_behav);
  const std::string path = datbox_path(files, "PTPT3_NETWORK.DAT");
  for (const grammar::Ptpt3Link& link : files.ptpt3_network->links) {
    bool known = true;
    for (const grammar::Integer* point : {&link.candidate, &link.antagonist})
      if (point->value < 1 || point->value > static_cast<std::int64_t>(points.size())) {
        sink.report("L2021", grammar::Location{path, point->span},
                    fmt::format("point {} does not exist: the case has {} PT3Dx contactor{}", point->value,
                                points.size(), points.size() == 1 ? "" : "s"));
        known = false;
      }
    if (!known) continue;
    const Point& cd = points[static_cast<std::size_t>(link.candidate.value - 1)];
    const Point& an = points[static_cast<std::size_t>(link.antagonist.value - 1)];
    if (cd.body == an.body) {
      sink.report(
          "L2022", grammar::Location{path, link.antagonist.span},
          fmt::format("points {} and {} are both on {}: a link joins two bodies", link.candidate.value,
                      link.antagonist.value, body_name(*cd.body, cd.body_rank)));
      continue;
    }
    if (see && !see->find(see_class(*cd.body, *cd.contactor), see_class(*an.body, *an.contactor)))
      sink.report("L2022", grammar::Location{path, link.candidate.span},
                  fmt::format("no '$seety' row of TACT_BEHAV.DAT reads PT3Dx {} against PT3Dx {}: the link "
                              "between points {} and {} has no law",
                              cd.contactor->color.value, an.contactor->color.value, link.candidate.value,
                              link.antagonist.value));
  }
}

}  // namespace lmgc::validate
