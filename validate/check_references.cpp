// Cross references between the files of a case: laws of visibility rows, element nodes, bodies,
// nodes and dofs named by DRV_DOF.DAT and DOF.INI. spec: datbox-inputs.md §1, §3, §5, §6.
#include <fmt/format.h>

#include <set>
#include <unordered_set>

#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

// Bodies of each type by rank (LMGC90 numbers bodies within their type).
struct BodyIndex {
  std::vector<const grammar::Body*> of_type[3];
  explicit BodyIndex(const grammar::BodiesFile& file) {
    for (const auto& b : file.bodies) of_type[static_cast<int>(b.type)].push_back(&b);
  }
  const grammar::Body* find(std::string_view type, std::int64_t rank) const {
    int t = type == "MAILx" ? 0 : type == "RBDY2" ? 1 : type == "RBDY3" ? 2 : -1;
    if (t < 0 || rank < 1 || rank > static_cast<std::int64_t>(of_type[t].size())) return nullptr;
    return of_type[t][static_cast<std::size_t>(rank - 1)];
  }
  std::size_t count(std::string_view type) const {
    int t = type == "MAILx" ? 0 : type == "RBDY2" ? 1 : type == "RBDY3" ? 2 : -1;
    return t < 0 ? 0 : of_type[t].size();
  }
};

int node_dofs(const std::string& node_type) {
  return node_type.size() == 5 && node_type.rfind("NO", 0) == 0 ? node_type[2] - '0' : 0;
}

}  // namespace

std::string datbox_path(const CaseFiles& files, const std::string& name) {
  return (files.case_dir / "DATBOX" / name).string();
}

void check_references(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  // Element connectivities name nodes of their own body.
  if (files.bodies) {
    const std::string path = datbox_path(files, "BODIES.DAT");
    std::size_t rank = 0;
    for (const auto& body : files.bodies->bodies) {
      if (body.type != grammar::BodyType::mailx) continue;
      ++rank;
      for (const auto& e : body.elements)
        for (const auto& n : e.nodes)
          if (n.value < 1 || n.value > static_cast<std::int64_t>(body.nodes.size()))
            sink.report("L2005", grammar::Location{path, n.span},
                        fmt::format("element {} of MAILx {} names node {}; the body has nodes 1..{}", e.type.value, rank,
                                    n.value, body.nodes.size()));
      for (const auto& c : body.contactors) {
        auto check_node = [&](const grammar::Integer& n) {
          if (n.value < 1 || n.value > static_cast<std::int64_t>(body.nodes.size()))
            sink.report("L2005", grammar::Location{path, n.span},
                        fmt::format("contactor {} of MAILx {} names node {}; the body has nodes 1..{}", c.type.value,
                                    rank, n.value, body.nodes.size()));
        };
        if (c.type.value != "POLYD")
          for (const auto& n : c.nodes) check_node(n);
        for (const auto& more : c.continuations)
          for (const auto& n : more.nodes) check_node(n);
      }
    }
  }

  // Visibility rows name laws of TACT_BEHAV.DAT.
  if (files.tact_behav) {
    const std::string path = datbox_path(files, "TACT_BEHAV.DAT");
    std::set<std::string> laws;
    for (const auto& law : files.tact_behav->laws) {
      if (!laws.insert(law.nickname.value).second)
        sink.report("L2012", grammar::Location{path, law.nickname.span},
                    fmt::format("law nickname '{}' is defined twice; LMGC90 uses the first", law.nickname.value));
    }
    for (const auto& see : files.tact_behav->sees)
      if (!laws.count(see.law_nickname.value))
        sink.report("L2002", grammar::Location{path, see.law_nickname.span},
                    fmt::format("law '{}' used by this visibility row is not defined in TACT_BEHAV.DAT",
                                see.law_nickname.value));
  }

  if (!files.bodies) return;
  const BodyIndex index(*files.bodies);

  // DRV_DOF.DAT: bodies, nodes and dofs exist.
  if (files.drv_dof) {
    const std::string path = datbox_path(files, "DRV_DOF.DAT");
    for (const auto& body : files.drv_dof->bodies) {
      const grammar::Body* target = index.find(body.body_type.value, body.rank.value);
      if (!target) {
        sink.report("L2003", grammar::Location{path, body.rank.span},
                    fmt::format("{} body {} does not exist (BODIES.DAT has {} {} bodies)", body.body_type.value,
                                body.rank.value, index.count(body.body_type.value), body.body_type.value));
        continue;
      }
      for (const auto& node : body.nodes) {
        const std::int64_t n = node.number.value;
        if (n < 1 || n > static_cast<std::int64_t>(target->nodes.size())) {
          sink.report("L2006", grammar::Location{path, node.number.span},
                      fmt::format("node {} of {} body {} does not exist (it has {} node{})", n, body.body_type.value,
                                  body.rank.value, target->nodes.size(), target->nodes.size() == 1 ? "" : "s"));
          continue;
        }
        const auto& real = target->nodes[static_cast<std::size_t>(n - 1)];
        const int dofs = node_dofs(real.type.value);
        for (const auto& dof : node.dofs)
          if (dof.dof.value < 1 || dof.dof.value > dofs)
            sink.report("L2008", grammar::Location{path, dof.dof.span},
                        fmt::format("dof {} does not exist on node {} ({} has {} dofs)", dof.dof.value, n,
                                    real.type.value, dofs));
      }
    }
  }

  // DOF.INI: bodies exist with the right type.
  if (files.dof_ini) {
    const std::string path = datbox_path(files, "DOF.INI");
    for (const auto& section : files.dof_ini->sections)
      for (const auto& body : section.bodies)
        if (!index.find(body.body_type.value, body.number.value))
          sink.report("L2003", grammar::Location{path, body.number.span},
                      fmt::format("{} body {} does not exist (BODIES.DAT has {} {} bodies)", body.body_type.value,
                                  body.number.value, index.count(body.body_type.value), body.body_type.value));
  }
}

}  // namespace lmgc::validate
