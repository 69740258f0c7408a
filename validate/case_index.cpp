#include "validate/case_index.hpp"

#include <fmt/format.h>

#include "grammar/common/diagnostic_catalogue.hpp"

namespace lmgc::validate {

int body_type_index(std::string_view type) {
  if (type == "MAILx") return static_cast<int>(grammar::BodyType::mailx);
  if (type == "RBDY2") return static_cast<int>(grammar::BodyType::rbdy2);
  if (type == "RBDY3") return static_cast<int>(grammar::BodyType::rbdy3);
  return -1;
}

BodyIndex::BodyIndex(const grammar::BodiesFile& file) {
  for (const auto& b : file.bodies) {
    auto& list = of_type_[static_cast<int>(b.type)];
    list.push_back(&b);
    rank_.emplace(&b, list.size());
  }
}

const grammar::Body* BodyIndex::find(std::string_view type, std::int64_t rank) const {
  const int t = body_type_index(type);
  if (t < 0 || rank < 1 || rank > static_cast<std::int64_t>(of_type_[t].size())) return nullptr;
  return of_type_[t][static_cast<std::size_t>(rank - 1)];
}

std::size_t BodyIndex::count(std::string_view type) const {
  const int t = body_type_index(type);
  return t < 0 ? 0 : of_type_[t].size();
}

std::size_t BodyIndex::rank_of(const grammar::Body& body) const {
  auto it = rank_.find(&body);
  return it == rank_.end() ? 0 : it->second;
}

std::string body_name(const grammar::Body& body, std::size_t rank) {
  return fmt::format("{} {}", grammar::body_type_keyword(body.type), rank);
}

int node_dofs(std::string_view node_type) {
  return node_type.size() == 5 && node_type.substr(0, 2) == "NO" && node_type[2] >= '1' && node_type[2] <= '6'
             ? node_type[2] - '0'
             : 0;
}

std::unordered_map<std::string, const grammar::BulkLaw*> bulk_laws_by_name(
    const grammar::BulkBehavFile& file) {
  std::unordered_map<std::string, const grammar::BulkLaw*> out;
  for (const auto& law : file.laws) out.emplace(law.nickname.value, &law);
  return out;
}

std::unordered_map<std::string, const grammar::Model*> models_by_name(const grammar::ModelsFile& file) {
  std::unordered_map<std::string, const grammar::Model*> out;
  for (const auto& model : file.models) out.emplace(model.nickname.value, &model);
  return out;
}

std::unordered_map<std::string, const grammar::TactLaw*> contact_laws_by_name(
    const grammar::TactBehavFile& file) {
  std::unordered_map<std::string, const grammar::TactLaw*> out;
  for (const auto& law : file.laws) out.emplace(law.nickname.value, &law);
  return out;
}

const grammar::BulkBlock* find_bulk_block(const grammar::BulkLaw& law, grammar::BulkBlockKind kind) {
  for (const auto& block : law.blocks)
    if (block.kind == kind) return &block;
  return nullptr;
}

const grammar::Word* model_option(const grammar::Model& model, std::string_view id) {
  for (const auto& option : model.options)
    if (option.id.value == id) return &option.value;
  return nullptr;
}

InitialDisplacements::InitialDisplacements(const CaseFiles& files) {
  if (!files.dof_ini) return;
  for (const auto& section : files.dof_ini->sections)
    for (const auto& body : section.bodies) {
      const int t = body_type_index(body.body_type.value);
      for (const auto& node : body.nodes)
        for (const auto& v : node.v)
          if (v.value != 0.0) any_velocity = true;
      if (t < 0 || body.number.value < 1 || body.nodes.empty()) continue;
      const std::uint64_t key =
          (static_cast<std::uint64_t>(t) << 40) | static_cast<std::uint64_t>(body.number.value);
      nodes_.emplace(key, &body.nodes.front());
    }
}

const grammar::DofNode* InitialDisplacements::find(int type_index, std::size_t rank) const {
  const std::uint64_t key = (static_cast<std::uint64_t>(type_index) << 40) | static_cast<std::uint64_t>(rank);
  auto it = nodes_.find(key);
  return it == nodes_.end() ? nullptr : it->second;
}

const std::vector<grammar::Real>& InitialDisplacements::of(int type_index, std::size_t rank) const {
  const grammar::DofNode* node = find(type_index, rank);
  return node ? node->x : none_;
}

const std::vector<grammar::Real>& InitialDisplacements::frame_of(int type_index, std::size_t rank) const {
  const grammar::DofNode* node = find(type_index, rank);
  return node ? node->frame : none_;
}

void report_related(grammar::DiagnosticSink& sink, std::string_view code, grammar::Location where,
                    std::string message, std::vector<grammar::RelatedLocation> related, std::string hint) {
  const grammar::DiagnosticKind* kind = grammar::find_diagnostic_kind(code);
  sink.report(grammar::Diagnostic{std::string(code), kind ? kind->severity : grammar::Severity::error,
                                  std::move(where), std::move(message), std::move(related), std::move(hint)});
}

int case_dimension(const CaseFiles& files) {
  return files.bodies ? grammar::bodies_dimension(*files.bodies) : 2;
}

}  // namespace lmgc::validate
