#pragma once
// Reading DRV_DOF.DAT and DOF.INI for rigid bodies of one type, shared by the 2D and 3D scene
// builders. docs/lmgc90-facts/datbox-inputs.md §5 (driven dofs), §6 (DOF.INI).
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "grammar/common/diagnostic.hpp"
#include "grammar/dof/ast.hpp"
#include "grammar/drv_dof/ast.hpp"
#include "solver/model/driven_dof.hpp"

namespace lmgc::solver {

// The `vlocy`/`force` rows of bodies of `body_type` ("RBDY2", "RBDY3"), dofs 1..dof_count, bodies
// by rank (body_of_rank[rank - 1] = scene index). Reports L2003 for a rank that does not exist and
// returns false then.
bool read_driven_dofs(const grammar::DrvDofFile& file, std::string_view body_type,
                      std::span<const std::int32_t> body_of_rank, int dof_count,
                      const std::map<std::string, grammar::EvolutionFile>* evolutions,
                      const std::string& path, std::vector<DrivenDof2D>& driven,
                      grammar::DiagnosticSink& sink);

// The first node of every DOF.INI body of `body_type` that names an existing rank, with the scene
// index of its body.
std::vector<std::pair<std::size_t, const grammar::DofNode*>> initial_dof_nodes(
    const grammar::DofFile& file, std::string_view body_type, std::span<const std::int32_t> body_of_rank);

}  // namespace lmgc::solver
