// The solver's pair families are pairs of the contactor-pair table (grammar/tact_behav/contactor_pairs.hpp):
// each family's name is a module of the table in its dimension, and the table's contactors give the
// family back; every module of the table is one Vloc_Rloc files know, in its dimension.
#include <gtest/gtest.h>

#include <string>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "solver/detection/detection_2d.hpp"
#include "solver/model/interaction_3d.hpp"

namespace lmgc::solver {
namespace {

TEST(PairFamilies, EveryModuleIsAVlocRlocInteractionOfItsDimension) {
  for (const grammar::ContactorPair& p : grammar::contactor_pairs()) {
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(p.vloc_rloc_type());
    ASSERT_NE(kind, nullptr) << p.interaction;
    EXPECT_EQ(kind->dimension, p.dimension) << p.interaction;
  }
}

TEST(PairFamilies, Every2DFamilyIsAPairOfTheTable) {
  for (int f = 0; f < kPairFamily2DCount; ++f) {
    const auto family = static_cast<PairFamily2D>(f);
    const grammar::ContactorPair* pair = grammar::find_interaction_pair(pair_family_name(family));
    ASSERT_NE(pair, nullptr) << pair_family_name(family);
    EXPECT_EQ(pair->dimension, 2);
    PairFamily2D back;
    ASSERT_TRUE(contactor_pair_family_2d(pair->candidate, pair->antagonist, back));
    EXPECT_EQ(back, family);
    // The rigid detection knows the families between rigid bodies only.
    EXPECT_EQ(pair_family_of(std::string(pair->candidate), std::string(pair->antagonist), back),
              !is_mesh_family(family));
    EXPECT_EQ(is_mesh_family(family), side_on_mesh(family, 0) || side_on_mesh(family, 1));
  }
  PairFamily2D family;
  EXPECT_TRUE(pair_family_of("DISKb", "JONCx", family));  // an alias of DISKx
  EXPECT_EQ(family, PairFamily2D::DKJCx);
  EXPECT_FALSE(pair_family_of("CLxxx", "JONCx", family));  // a mesh family: mesh_detection_2d.hpp
  EXPECT_TRUE(contactor_pair_family_2d("CLxxx", "JONCx", family));
  EXPECT_EQ(family, PairFamily2D::CLJCx);
  EXPECT_TRUE(contactor_pair_family_2d("PT2DL", "PT2DL", family));
  EXPECT_EQ(family, PairFamily2D::P2P2L);
  EXPECT_TRUE(contactor_pair_family_2d("DISKx", "DISKL", family));
  EXPECT_EQ(family, PairFamily2D::DKDKL);
  EXPECT_TRUE(side_on_mesh(PairFamily2D::DKDKL, 1));
  EXPECT_FALSE(side_on_mesh(PairFamily2D::DKDKL, 0));
}

TEST(PairFamilies, Every3DFamilyIsAPairOfTheTable) {
  for (int f = 0; f < kPairFamily3DCount; ++f) {
    const auto family = static_cast<PairFamily3D>(f);
    const grammar::ContactorPair* pair = grammar::find_interaction_pair(pair_family_name(family));
    ASSERT_NE(pair, nullptr) << pair_family_name(family);
    EXPECT_EQ(pair->dimension, 3);
    PairFamily3D back;
    ASSERT_TRUE(pair_family_3d(std::string(pair->candidate), std::string(pair->antagonist), back));
    EXPECT_EQ(back, family);
  }
  PairFamily3D family;
  EXPECT_TRUE(pair_family_3d("SPHEb", "PLANx", family));
  EXPECT_EQ(family, PairFamily3D::SPPLx);
  EXPECT_FALSE(pair_family_3d("CSxxx", "POLYR", family));
}

}  // namespace
}  // namespace lmgc::solver
