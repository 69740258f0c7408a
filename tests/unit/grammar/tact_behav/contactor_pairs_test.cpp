// The contactor-pair table: each (candidate, antagonist) forms one pair and each module has one; the aliases
// fold BODIES.DAT names into '$seety' names.
#include "grammar/tact_behav/contactor_pairs.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace lmgc::grammar {
namespace {

TEST(ContactorPairs, EachContactorOrderFormsOnePairAndEachModuleHasOne) {
  std::set<std::string> orders, modules;
  for (const ContactorPair& p : contactor_pairs()) {
    EXPECT_TRUE(orders.insert(std::string(p.candidate) + "/" + std::string(p.antagonist)).second)
        << p.interaction;
    EXPECT_TRUE(modules.insert(std::string(p.interaction)).second) << p.interaction;
    EXPECT_EQ(find_contactor_pair(p.candidate, p.antagonist), &p);
    EXPECT_EQ(find_interaction_pair(p.interaction), &p);
  }
  EXPECT_EQ(find_contactor_pair("JONCx", "DISKx"), nullptr);  // roles are not symmetric
}

TEST(ContactorPairs, AliasesFoldIntoTheSeetyNames) {
  EXPECT_EQ(see_name("DISKb"), "DISKx");
  EXPECT_EQ(see_name("SPHEb"), "SPHER");
  EXPECT_EQ(see_name("POLYF"), "POLYR");
  EXPECT_EQ(see_name("PT2TL"), "PT2DL");
  EXPECT_EQ(see_name("CSpx4"), "CSxxx");
  EXPECT_EQ(see_name("ASpx3"), "ASpxx");
  EXPECT_EQ(see_name("DISKx"), "DISKx");
}

}  // namespace
}  // namespace lmgc::grammar
