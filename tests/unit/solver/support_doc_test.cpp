// docs/support.md: what lmgc-solve runs, generated from the catalogues and the solver's own
// predicates (the contactor kinds its scene builders take, each law's 2D and 3D forms, the POSTPRO
// commands its post-processors compute), so that the page cannot drift from the code. When they
// differ, the expected tables are written to test_scratch/support_doc/support.tables.md: review
// them and paste them into the page.
#include <gtest/gtest.h>

#include <fstream>

#include "grammar/bodies/contactor_catalogue.hpp"
#include "grammar/postpro/catalogue.hpp"
#include "grammar/tact_behav/contactor_pairs.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "solver/io/postpro_2d.hpp"
#include "solver/io/postpro_3d.hpp"
#include "solver/laws/contact_law.hpp"
#include "solver/model/build_scene_2d.hpp"
#include "solver/model/build_scene_3d.hpp"
#include "solver/model/mesh_bodies.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

std::string yes_no(bool yes) {
  return yes ? "yes" : "not yet";
}

std::string expected_tables() {
  std::string out = "### Contactors\n\n| contactor | bodies | lmgc-solve |\n| --- | --- | --- |\n";
  for (const grammar::ContactorKind& k : grammar::contactor_catalogue()) {
    std::string bodies, runs;
    if (k.bodies & grammar::kOnRbdy2) bodies += "RBDY2 ", runs = yes_no(runs_contactor_2d(k.keyword));
    if (k.bodies & grammar::kOnRbdy3) bodies += "RBDY3 ", runs = yes_no(runs_contactor_3d(k.keyword));
    if (k.bodies & grammar::kOnMailx)
      bodies += "MAILx ", runs = runs_mesh_contactor_2d(k.keyword) ? "yes (2D)" : "not yet (MAILx)";
    if (!k.guide_only.empty()) runs = "removed from LMGC90 (error)";
    out +=
        "| `" + std::string(k.keyword) + "` | " + bodies.substr(0, bodies.size() - 1) + " | " + runs + " |\n";
  }
  out += "\n### Contact laws\n\n| law | 2D | 3D |\n| --- | --- | --- |\n";
  for (const grammar::LawKind& k : grammar::law_catalogue()) {
    if (!k.readable) continue;
    ContactLaw law;
    const bool known = law_from_card(k.keyword, {}, law);
    out += "| `" + std::string(k.keyword) + "` | " + yes_no(known && provided_in_2d(law)) + " | " +
           yes_no(known && provided_in_3d(law)) + " |\n";
  }
  out += "\n### POSTPRO commands\n\n| command | 2D | 3D |\n| --- | --- | --- |\n";
  for (const grammar::PostproCommandKind& k : grammar::postpro_catalogue()) {
    PostproKind2D kind;
    const bool known = postpro_kind_of(k.name, kind);
    out += "| `" + std::string(k.name) + "` | " + (k.available_in(2) ? yes_no(known) : "—") + " | " +
           (k.available_in(3) ? yes_no(known && Postpro3D::provides(kind)) : "—") + " |\n";
  }
  return out;
}

// The README's summary of the same tables: what lmgc-solve runs, out of what LMGC90 has, per dimension.
std::string expected_summary() {
  int contactors[2] = {0, 0}, contactors_all[2] = {0, 0};
  for (const grammar::ContactorKind& k : grammar::contactor_catalogue()) {
    if (!k.guide_only.empty()) continue;
    if (k.bodies & grammar::kOnRbdy2) ++contactors_all[0], contactors[0] += runs_contactor_2d(k.keyword);
    if (k.bodies & grammar::kOnRbdy3) ++contactors_all[1], contactors[1] += runs_contactor_3d(k.keyword);
    if ((k.bodies & grammar::kOnMailx) && k.dimension == 2)
      ++contactors_all[0], contactors[0] += runs_mesh_contactor_2d(k.keyword);
  }
  int pairs[2] = {0, 0}, pairs_all[2] = {0, 0};
  for (const grammar::ContactorPair& p : grammar::contactor_pairs()) {
    const int d = p.dimension == 2 ? 0 : 1;
    ++pairs_all[d];
    PairFamily2D family_2d;
    PairFamily3D family_3d;
    pairs[d] += d == 0 ? contactor_pair_family_2d(p.candidate, p.antagonist, family_2d)
                       : pair_family_3d(std::string(p.candidate), std::string(p.antagonist), family_3d);
  }
  int laws[2] = {0, 0}, laws_all = 0;
  for (const grammar::LawKind& k : grammar::law_catalogue()) {
    if (!k.readable) continue;
    ++laws_all;
    ContactLaw law;
    const bool known = law_from_card(k.keyword, {}, law);
    laws[0] += known && provided_in_2d(law);
    laws[1] += known && provided_in_3d(law);
  }
  int postpro[2] = {0, 0}, postpro_all[2] = {0, 0};
  for (const grammar::PostproCommandKind& k : grammar::postpro_catalogue()) {
    PostproKind2D kind;
    const bool known = postpro_kind_of(k.name, kind);
    if (k.available_in(2)) ++postpro_all[0], postpro[0] += known;
    if (k.available_in(3)) ++postpro_all[1], postpro[1] += known && Postpro3D::provides(kind);
  }
  const auto of = [](int n, int all) { return std::to_string(n) + " of " + std::to_string(all); };
  std::string out = "| lmgc-solve runs | 2D (RBDY2, MAILx) | rigid 3D (RBDY3) |\n| --- | --- | --- |\n";
  out += "| contactors | " + of(contactors[0], contactors_all[0]) + " | " +
         of(contactors[1], contactors_all[1]) + " |\n";
  out += "| contactor pairs | " + of(pairs[0], pairs_all[0]) + " | " + of(pairs[1], pairs_all[1]) + " |\n";
  out += "| contact laws | " + of(laws[0], laws_all) + " | " + of(laws[1], laws_all) + " |\n";
  out += "| POSTPRO commands | " + of(postpro[0], postpro_all[0]) + " | " + of(postpro[1], postpro_all[1]) +
         " |\n";
  return out;
}

TEST(SupportDoc, ReadmeSummarisesWhatLmgcSolveRunsAsTheCodeDoes) {
  const std::string readme = test::read_file(std::filesystem::path(LMGC_SOURCE_DIR) / "README.md");
  const std::string summary = expected_summary();
  const bool listed = readme.find(summary) != std::string::npos;
  if (!listed) std::ofstream(test::scratch_dir("support_doc") / "readme.summary.md") << summary;
  EXPECT_TRUE(listed) << "README.md does not hold the generated summary (written to "
                         "test_scratch/support_doc/readme.summary.md)";
}

TEST(SupportDoc, ListsWhatLmgcSolveRunsAsTheCodeDoes) {
  const std::string doc = test::read_file(std::filesystem::path(LMGC_SOURCE_DIR) / "docs" / "support.md");
  const std::string tables = expected_tables();
  const bool listed = doc.find(tables) != std::string::npos;
  if (!listed) std::ofstream(test::scratch_dir("support_doc") / "support.tables.md") << tables;
  EXPECT_TRUE(listed) << "docs/support.md does not hold the generated tables (written to "
                         "test_scratch/support_doc/support.tables.md)";
}

}  // namespace
}  // namespace lmgc::solver
