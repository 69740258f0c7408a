#pragma once
// Lookups over a loaded case that several checks share: bodies by type and rank (LMGC90 numbers
// bodies by order of appearance within their type, datbox-inputs.md §1), bulk behaviours, models
// and contact laws by nickname, initial displacements by body. Built once per check, in linear
// time, with hash maps.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/bodies/ast.hpp"
#include "grammar/bulk_behav/ast.hpp"
#include "grammar/dof/ast.hpp"
#include "grammar/models/ast.hpp"
#include "grammar/tact_behav/ast.hpp"

namespace lmgc::validate {

using case_folder::CaseFiles;  // the checks read the case as loaded (case_folder/)

// 0 for MAILx, 1 for RBDY2, 2 for RBDY3 (the order of grammar::BodyType); -1 for another word.
int body_type_index(std::string_view type);

// Bodies of each type by rank (1-based).
class BodyIndex {
 public:
  explicit BodyIndex(const grammar::BodiesFile& file);
  // The body of this type and rank, or nullptr.
  const grammar::Body* find(std::string_view type, std::int64_t rank) const;
  std::size_t count(std::string_view type) const;
  std::size_t count(grammar::BodyType type) const { return of_type_[static_cast<int>(type)].size(); }
  // The rank of a body of the file within its type (1-based).
  std::size_t rank_of(const grammar::Body& body) const;

 private:
  std::array<std::vector<const grammar::Body*>, 3> of_type_;
  std::unordered_map<const grammar::Body*, std::size_t> rank_;
};

// "RBDY2 12": a body as diagnostics name it (type and rank).
std::string body_name(const grammar::Body& body, std::size_t rank);

// Number of dofs of a node type NOnxx (0 for another word).
int node_dofs(std::string_view node_type);

// The first definition of each nickname, in file order (LMGC90 uses the first).
std::unordered_map<std::string, const grammar::BulkLaw*> bulk_laws_by_name(
    const grammar::BulkBehavFile& file);
std::unordered_map<std::string, const grammar::Model*> models_by_name(const grammar::ModelsFile& file);
std::unordered_map<std::string, const grammar::TactLaw*> contact_laws_by_name(
    const grammar::TactBehavFile& file);

// The block of a kind in a bulk law, or nullptr.
const grammar::BulkBlock* find_bulk_block(const grammar::BulkLaw& law, grammar::BulkBlockKind kind);

// The value of a model option (as written, trailing blanks removed), or nullptr when absent.
const grammar::Word* model_option(const grammar::Model& model, std::string_view id);

// The initial state of each body listed in DOF.INI (its first node), by (type index, rank).
struct InitialDisplacements {
  explicit InitialDisplacements(const CaseFiles& files);
  // X(1..n) of the body's node, or an empty vector when the body is not listed (LMGC90: X = 0).
  const std::vector<grammar::Real>& of(int type_index, std::size_t rank) const;
  // RBDY3: the columns a, b, c of the body's frame (9 values), or an empty vector (identity).
  const std::vector<grammar::Real>& frame_of(int type_index, std::size_t rank) const;
  // True when DOF.INI gives some body a non-zero velocity.
  bool any_velocity = false;

 private:
  const grammar::DofNode* find(int type_index, std::size_t rank) const;
  std::unordered_map<std::uint64_t, const grammar::DofNode*> nodes_;
  std::vector<grammar::Real> none_;
};

// Reports `code` with its catalogue severity and related positions ("defined here", ...).
void report_related(grammar::DiagnosticSink& sink, std::string_view code, grammar::Location where,
                    std::string message, std::vector<grammar::RelatedLocation> related,
                    std::string hint = {});

// Dimension of the case: 3 with RBDY3 bodies or NO3xx MAILx nodes, else 2 (grammar's rule).
int case_dimension(const CaseFiles& files);

}  // namespace lmgc::validate
