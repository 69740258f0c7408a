#include "solver/model/driven_dofs.hpp"

namespace lmgc::solver {

bool read_driven_dofs(const grammar::DrvDofFile& file, std::string_view body_type,
                      std::span<const std::int32_t> body_of_rank, int dof_count,
                      const std::map<std::string, grammar::EvolutionFile>* evolutions,
                      const std::string& path, std::vector<DrivenDof2D>& driven,
                      grammar::DiagnosticSink& sink) {
  bool ok = true;
  for (const grammar::DrvDofBody& body : file.bodies) {
    if (body.body_type.value != body_type) continue;
    const std::int64_t rank = body.rank.value;
    if (rank < 1 || rank > static_cast<std::int64_t>(body_of_rank.size())) {
      sink.report("L2003", grammar::Location{path, body.rank.span},
                  std::string(body_type) + " body " + std::to_string(rank) + " does not exist");
      ok = false;
      continue;
    }
    for (const grammar::DrvDofNode& node : body.nodes)
      for (const grammar::DrivenDof& dof : node.dofs) {
        DrivenDof2D d;
        d.body = body_of_rank[static_cast<std::size_t>(rank - 1)];
        d.dof = static_cast<std::int32_t>(dof.dof.value) - 1;
        d.is_force = dof.kind.value == "force";
        if (d.dof < 0 || d.dof >= dof_count) continue;
        if (dof.uses_evolution) {
          if (evolutions) {
            auto it = evolutions->find(dof.evolution_file.value);
            if (it != evolutions->end())
              for (const auto& point : it->second.points)
                d.evolution.push_back({point.time.value, point.value.value});
          }
        } else {
          for (std::size_t k = 0; k < 6; ++k) d.coefficients[k] = dof.parameters[k].value;
        }
        driven.push_back(d);
      }
  }
  return ok;
}

std::vector<std::pair<std::size_t, const grammar::DofNode*>> initial_dof_nodes(
    const grammar::DofFile& file, std::string_view body_type, std::span<const std::int32_t> body_of_rank) {
  std::vector<std::pair<std::size_t, const grammar::DofNode*>> nodes;
  for (const auto& section : file.sections)
    for (const grammar::DofBody& body : section.bodies) {
      if (body.body_type.value != body_type || body.nodes.empty()) continue;
      const std::int64_t rank = body.number.value;
      if (rank < 1 || rank > static_cast<std::int64_t>(body_of_rank.size())) continue;
      nodes.emplace_back(static_cast<std::size_t>(body_of_rank[static_cast<std::size_t>(rank - 1)]),
                         &body.nodes.front());
    }
  return nodes;
}

}  // namespace lmgc::solver
