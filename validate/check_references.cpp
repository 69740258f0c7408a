// Cross references between the files of a case: bulk behaviours and models named by bodies, laws
// of visibility rows, element nodes, bodies, nodes and dofs named by DRV_DOF.DAT and DOF.INI,
// nicknames defined twice, body numbers. docs/lmgc90-facts/datbox-inputs.md §1-§6.
#include <fmt/format.h>

#include <unordered_map>

#include "validate/case_index.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

// "'PLEXx', 'TDURx'": the nicknames a file defines, for hints (at most 6, in file order).
template <class Items, class Name>
std::string nickname_list(const Items& items, Name name) {
  std::string out;
  std::size_t n = 0;
  for (const auto& item : items) {
    if (n == 6) return out + ", ...";
    out += (n++ ? ", '" : "'") + name(item) + "'";
  }
  return out;
}

std::string ordinal(std::size_t n) {
  const char* suffix = (n % 100 >= 11 && n % 100 <= 13) ? "th"
                       : n % 10 == 1                    ? "st"
                       : n % 10 == 2                    ? "nd"
                       : n % 10 == 3                    ? "rd"
                                                        : "th";
  return fmt::format("{}{}", n, suffix);
}

// A nickname defined twice: LMGC90 takes the first (get_bulk_behav_nb, models, laws).
template <class Item>
void first_definitions(const std::vector<Item>& items, const std::string& path, const char* what,
                       grammar::DiagnosticSink& sink, const grammar::Word Item::*nickname) {
  std::unordered_map<std::string, const Item*> first;
  for (const Item& item : items) {
    const grammar::Word& name = item.*nickname;
    auto [it, inserted] = first.emplace(name.value, &item);
    if (!inserted)
      report_related(sink, "L2012", grammar::Location{path, name.span},
                     fmt::format("{} '{}' is defined twice; LMGC90 uses the first", what, name.value),
                     {{grammar::Location{path, (it->second->*nickname).span}, "first defined here"}});
  }
}

}  // namespace

std::string datbox_path(const CaseFiles& files, const std::string& name) {
  return (files.case_dir / "DATBOX" / name).string();
}

void check_references(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  // Nicknames defined twice.
  if (files.bulk_behav)
    first_definitions(files.bulk_behav->laws, datbox_path(files, "BULK_BEHAV.DAT"), "bulk behaviour", sink,
                      &grammar::BulkLaw::nickname);
  if (files.models)
    first_definitions(files.models->models, datbox_path(files, "MODELS.DAT"), "model", sink,
                      &grammar::Model::nickname);
  if (files.tact_behav)
    first_definitions(files.tact_behav->laws, datbox_path(files, "TACT_BEHAV.DAT"), "law nickname", sink,
                      &grammar::TactLaw::nickname);

  // Visibility rows name laws of TACT_BEHAV.DAT.
  if (files.tact_behav) {
    const std::string path = datbox_path(files, "TACT_BEHAV.DAT");
    const auto laws = contact_laws_by_name(*files.tact_behav);
    for (const auto& see : files.tact_behav->sees)
      if (!laws.count(see.law_nickname.value))
        sink.report(
            "L2002", grammar::Location{path, see.law_nickname.span},
            fmt::format("law '{}' used by this visibility row is not defined in TACT_BEHAV.DAT",
                        see.law_nickname.value),
            files.tact_behav->laws.empty()
                ? std::string()
                : "TACT_BEHAV.DAT defines " +
                      nickname_list(files.tact_behav->laws, [](const auto& l) { return l.nickname.value; }));
  }

  if (!files.bodies) return;
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");
  const BodyIndex index(*files.bodies);

  // Bodies name bulk behaviours and models that exist; element connectivities and MAILx
  // contactors name nodes of their own body.
  std::unordered_map<std::string, const grammar::BulkLaw*> bulk;
  if (files.bulk_behav) bulk = bulk_laws_by_name(*files.bulk_behav);
  std::unordered_map<std::string, const grammar::Model*> models;
  if (files.models) models = models_by_name(*files.models);
  auto bulk_hint = [&] {
    return files.bulk_behav && !files.bulk_behav->laws.empty()
               ? "BULK_BEHAV.DAT defines " +
                     nickname_list(files.bulk_behav->laws, [](const auto& l) { return l.nickname.value; })
               : std::string();
  };
  auto check_behav = [&](const grammar::Word& behav, const std::string& owner) {
    if (files.bulk_behav && !bulk.count(behav.value))
      sink.report(
          "L2001", grammar::Location{bodies_path, behav.span},
          fmt::format("bulk behaviour '{}' of {} is not defined in BULK_BEHAV.DAT", behav.value, owner),
          bulk_hint());
  };
  for (const auto& body : files.bodies->bodies) {
    const std::size_t rank = index.rank_of(body);
    const std::string owner = body_name(body, rank);
    if (body.rigid_bulk) check_behav(body.rigid_bulk->behav, owner);
    for (const auto& e : body.elements) {
      for (const auto& n : e.nodes)
        if (n.value < 1 || n.value > static_cast<std::int64_t>(body.nodes.size()))
          sink.report("L2005", grammar::Location{bodies_path, n.span},
                      fmt::format("element {} of {} names node {}; the body has nodes 1..{}", e.type.value,
                                  owner, n.value, body.nodes.size()));
      for (const auto& m : e.models) {
        if (files.models && !models.count(m.model.value))
          sink.report("L2004", grammar::Location{bodies_path, m.model.span},
                      fmt::format("model '{}' of element {} {} of {} is not defined in MODELS.DAT",
                                  m.model.value, e.type.value, &e - body.elements.data() + 1, owner),
                      files.models->models.empty()
                          ? std::string()
                          : "MODELS.DAT defines " + nickname_list(files.models->models, [](const auto& x) {
                              return x.nickname.value;
                            }));
        check_behav(m.behav,
                    fmt::format("element {} {} of {}", e.type.value, &e - body.elements.data() + 1, owner));
      }
    }
    if (body.type != grammar::BodyType::mailx) continue;
    for (const auto& c : body.contactors) {
      auto check_node = [&](const grammar::Integer& n) {
        if (n.value < 1 || n.value > static_cast<std::int64_t>(body.nodes.size()))
          sink.report("L2005", grammar::Location{bodies_path, n.span},
                      fmt::format("contactor {} of {} names node {}; the body has nodes 1..{}", c.type.value,
                                  owner, n.value, body.nodes.size()));
      };
      if (c.type.value != "POLYD")
        for (const auto& n : c.nodes) check_node(n);
      for (const auto& more : c.continuations)
        for (const auto& n : more.nodes) check_node(n);
    }
  }

  // Body numbers: LMGC90 numbers bodies by order within their type and never reads the number
  // written after the type (datbox-inputs.md §1). Said once per type, at the first mismatch.
  for (grammar::BodyType type :
       {grammar::BodyType::mailx, grammar::BodyType::rbdy2, grammar::BodyType::rbdy3}) {
    const grammar::Body* first = nullptr;
    std::size_t first_rank = 0, mismatches = 0, rank = 0;
    for (const auto& body : files.bodies->bodies) {
      if (body.type != type) continue;
      ++rank;
      if (body.number.value == static_cast<std::int64_t>(rank) || body.number.span.line == 0) continue;
      if (!first) first = &body, first_rank = rank;
      ++mismatches;
    }
    if (!first) continue;
    const std::string_view keyword = grammar::body_type_keyword(type);
    sink.report(
        "L2017", grammar::Location{bodies_path, first->number.span},
        fmt::format("the body written '{} {}' is the {} {} body: LMGC90 numbers bodies by order and does not "
                    "read this number ({} of {} {} bodies are written with another number than their rank)",
                    keyword, first->number.value, ordinal(first_rank), keyword, mismatches, rank, keyword),
        "DRV_DOF.DAT, DOF.INI, Vloc_Rloc.INI and POSTPRO.DAT name bodies by their rank; number them 1, 2, "
        "... "
        "in order");
  }

  // DRV_DOF.DAT: bodies, nodes and dofs exist; a dof is driven once.
  if (files.drv_dof) {
    const std::string path = datbox_path(files, "DRV_DOF.DAT");
    std::unordered_map<std::string, const grammar::DrivenDof*> driven;
    for (const auto& body : files.drv_dof->bodies) {
      const grammar::Body* target = index.find(body.body_type.value, body.rank.value);
      if (!target) {
        sink.report(
            "L2003", grammar::Location{path, body.rank.span},
            fmt::format("{} body {} does not exist (BODIES.DAT has {} {} bodies)", body.body_type.value,
                        body.rank.value, index.count(body.body_type.value), body.body_type.value));
        continue;
      }
      for (const auto& node : body.nodes) {
        const std::int64_t n = node.number.value;
        if (n < 1 || n > static_cast<std::int64_t>(target->nodes.size())) {
          sink.report(
              "L2006", grammar::Location{path, node.number.span},
              fmt::format("node {} of {} body {} does not exist (it has {} node{})", n, body.body_type.value,
                          body.rank.value, target->nodes.size(), target->nodes.size() == 1 ? "" : "s"));
          continue;
        }
        const auto& real = target->nodes[static_cast<std::size_t>(n - 1)];
        const int dofs = node_dofs(real.type.value);
        for (const auto& dof : node.dofs) {
          if (dof.dof.value < 1 || dof.dof.value > dofs) {
            sink.report("L2008", grammar::Location{path, dof.dof.span},
                        fmt::format("dof {} does not exist on node {} ({} has {} dofs)", dof.dof.value, n,
                                    real.type.value, dofs));
            continue;
          }
          const std::string key = fmt::format("{} {} {} {} {} {}", body.body_type.value, body.rank.value,
                                              body.model.value, n, dof.kind.value, dof.dof.value);
          auto [it, inserted] = driven.emplace(key, &dof);
          if (!inserted)
            report_related(
                sink, "L2012", grammar::Location{path, dof.kind.span},
                fmt::format("dof {} of node {} of {} body {} is driven twice ('{}')", dof.dof.value, n,
                            body.body_type.value, body.rank.value, dof.kind.value),
                {{grammar::Location{path, it->second->kind.span}, "first driven here"}});
        }
      }
    }
  }

  // DOF.INI: bodies exist with the right type, and so do their nodes; a body's state is given once.
  if (files.dof_ini) {
    const std::string path = datbox_path(files, "DOF.INI");
    std::unordered_map<const grammar::Body*, const grammar::DofBody*> given;
    for (const auto& section : files.dof_ini->sections)
      for (const auto& body : section.bodies) {
        const grammar::Body* target = index.find(body.body_type.value, body.number.value);
        if (target) {
          auto [it, inserted] = given.emplace(target, &body);
          if (!inserted)
            report_related(sink, "L2012", grammar::Location{path, body.number.span},
                           fmt::format("the initial state of {} body {} is given twice", body.body_type.value,
                                       body.number.value),
                           {{grammar::Location{path, it->second->number.span}, "first given here"}});
        }
        if (!target) {
          sink.report(
              "L2003", grammar::Location{path, body.number.span},
              fmt::format("{} body {} does not exist (BODIES.DAT has {} {} bodies)", body.body_type.value,
                          body.number.value, index.count(body.body_type.value), body.body_type.value));
          continue;
        }
        for (const auto& node : body.nodes)
          if (node.number.value < 1 || node.number.value > static_cast<std::int64_t>(target->nodes.size()))
            sink.report("L2006", grammar::Location{path, node.number.span},
                        fmt::format("node {} of {} body {} does not exist (it has {} node{})",
                                    node.number.value, body.body_type.value, body.number.value,
                                    target->nodes.size(), target->nodes.size() == 1 ? "" : "s"));
      }
  }
}

}  // namespace lmgc::validate
