#pragma once
// The '$seety' vocabulary shared by the checks: LMGC90's interaction families (which candidate
// and antagonist contactors a row may name), the contactor names rows use, and the lookup of the
// row that applies to two contactor classes. docs/lmgc90-facts/contact-laws.md §1.2,
// state-and-outputs.md §1.4.1-1.4.2.
#include <string>
#include <string_view>
#include <unordered_map>

#include "grammar/bodies/ast.hpp"
#include "grammar/tact_behav/ast.hpp"
#include "grammar/tact_behav/contactor_pairs.hpp"

namespace lmgc::validate {

// The interaction family of a (candidate, antagonist) pair of '$seety' contactor names, or nullptr
// (the contactor-pair table, grammar/tact_behav/contactor_pairs.hpp).
using InteractionFamily = grammar::ContactorPair;
inline const InteractionFamily* find_interaction_family(std::string_view candidate,
                                                        std::string_view antagonist) {
  return grammar::find_contactor_pair(candidate, antagonist);
}

// The name a BODIES.DAT contactor goes by in '$seety' rows (DISKb is a DISKx, MAILx surfaces are
// CSxxx, ...).
std::string see_name(const std::string& contactor_type);

// "RBDY2/DISKx/BLEUx": the class of contactors a '$seety' side names.
std::string see_class(std::string_view body_type, std::string_view see_contactor, std::string_view colour);
std::string see_class(const grammar::Body& body, const grammar::Contactor& contactor);

// A size that sets the scale of contacts: radius of disks and spheres, circumradius of polygons
// and polyhedra; walls and points have none (0).
double characteristic_size(const grammar::Contactor& contactor);

// The row that applies to two contactor classes: LMGC90's lookup is symmetric and takes the
// first matching row (get_isee, contact-laws.md §1.2).
class SeeTable {
 public:
  explicit SeeTable(const grammar::TactBehavFile& file);
  const grammar::SeeEntry* find(const std::string& class_a, const std::string& class_b) const;

 private:
  std::unordered_map<std::string, const grammar::SeeEntry*> rows_;
};

}  // namespace lmgc::validate
