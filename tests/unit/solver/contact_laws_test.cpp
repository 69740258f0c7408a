// The contact-law catalogue (solver/laws/): every law read from its TACT_BEHAV keyword, then one test
// suite per law checking the derived Signorini–Coulomb problem it poses (contact-laws.md §2, §3):
// covfree, μ, correction, inactivity and statuses, in 2D and, where the law has one, in 3D.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "solver/laws/contact_law.hpp"

namespace lmgc::solver {
namespace {

constexpr double h = 1e-3;

// A card's values in the law catalogue's order, by parameter name (0 for the others), as
// grammar::TactLaw holds them.
std::vector<double> card_values(std::string_view keyword, const std::map<std::string, double>& by_name = {}) {
  std::vector<double> values;
  const grammar::LawKind* kind = grammar::find_law_kind(keyword);
  if (!kind) return values;
  for (std::string_view listed : kind->parameters) {
    listed = listed.substr(0, listed.find_last_not_of(' ') + 1);
    const auto it = by_name.find(std::string(listed));
    values.push_back(it == by_name.end() ? 0.0 : it->second);
  }
  return values;
}

// Every parameter a law's table names is one the law catalogue lists for the law's keyword, so that
// no parameter is read from a name its card does not have.
template <std::size_t... I>
void expect_parameters_on_their_cards(std::index_sequence<I...>) {
  const auto one = [&]<std::size_t K>() {
    using Law = std::variant_alternative_t<K, ContactLaw>;
    const grammar::LawKind* kind = grammar::find_law_kind(Law::keyword);
    ASSERT_NE(kind, nullptr) << Law::keyword;
    for (const LawParameter<Law>& parameter : Law::parameters) {
      bool listed = false;
      for (std::string_view name : kind->parameters)
        listed = listed || name.substr(0, name.find_last_not_of(' ') + 1) == parameter.name;
      EXPECT_TRUE(listed) << Law::keyword << " has no parameter '" << parameter.name << "'";
    }
  };
  (one.template operator()<I>(), ...);
}

LocalProblem2D contact_2d(double gap, ContactStatus begin = ContactStatus::nknow) {
  LocalProblem2D c;
  c.gap_begin = gap;
  c.status_begin = begin;
  c.velocity_begin = Eigen::Vector2d(0.3, -2.0);
  c.W << 2.0, 0.5, 0.5, 1.0;
  c.WW = c.W;
  return c;
}

// The end of a 2D step on a local problem's internals, as the NLGS keeps them: in the
// interaction's LawState2D.
void finish_law(const ContactLaw& law, LocalProblem2D& c, const LawStep& step) {
  LawState2D state{c.internal};
  solver::finish_law(law, c, state, step);
  c.internal = state.internal;
}

// A 3D interaction with its law state, as the step keeps them side by side.
struct Contact3D : Interaction3D {
  LawState3D state;
};
bool prepare_law(const ContactLaw& law, Contact3D& c, const LawStep& step) {
  return solver::prepare_law(law, c, c.state, step);
}
void finish_law(const ContactLaw& law, Contact3D& c, const LawStep& step) {
  solver::finish_law(law, c, c.state, step);
}
bool update_law_at_check(const ContactLaw& law, Contact3D& c, const Eigen::Vector3d& u, const LawStep& step) {
  return solver::update_law_at_check(law, c, c.state, u, step);
}

Contact3D contact_3d(double gap, ContactStatus begin = ContactStatus::nknow) {
  Contact3D c;
  c.gap_begin = gap;
  c.status_begin = begin;
  c.velocity_begin = Eigen::Vector3d(0.3, -2.0, 0.1);
  c.W = Eigen::Matrix3d::Identity();
  c.state.surface = 0.5;
  return c;
}

TEST(ContactLawTable, EveryKeywordReadsBackToItsLaw) {
  const char* keywords[] = {"IQS_CLB",        "IQS_DS_CLB",         "IQS_CLB_g0",      "RST_CLB",
                            "RST_DS_CLB",     "GAP_SGR_CLB",        "GAP_SGR_DS_CLB",  "VEL_SGR_CLB",
                            "VEL_SGR_DS_CLB", "ELASTIC_REPELL_CLB", "IQS_MOHR_DS_CLB", "IQS_WET_DS_CLB",
                            "IQS_MAC_CZM",    "COUPLED_DOF",        "MD_JKRs",         "ELASTIC_ROD",
                            "ELASTIC_WIRE"};
  for (const char* keyword : keywords) {
    ContactLaw law;
    ASSERT_TRUE(law_from_card(keyword, card_values(keyword), law)) << keyword;
    EXPECT_EQ(law_keyword(law), keyword);
  }
  ContactLaw law;
  EXPECT_FALSE(law_from_card("NOT_A_LAW", {}, law));
  ASSERT_TRUE(law_from_card(
      "RST_DS_CLB",
      card_values("RST_DS_CLB", {{"restn", 0.5}, {"restt", 0.1}, {"dfric", 0.2}, {"sfric", 0.3}}), law));
  const auto& rst = std::get<RstDsClb>(law);
  EXPECT_EQ(rst.restn, 0.5);
  EXPECT_EQ(rst.dfric, 0.2);
}

TEST(ContactLawTable, EveryParameterIsOnItsCatalogueCard) {
  expect_parameters_on_their_cards(std::make_index_sequence<std::variant_size_v<ContactLaw>>{});
}

// Each value lands in the member its name says, whatever the order of the members: IQS_MAC_CZM's
// card lists its six values in another order than the struct.
TEST(ContactLawTable, EachValueFillsTheMemberOfItsName) {
  ContactLaw law;
  ASSERT_TRUE(law_from_card(
      "IQS_MAC_CZM",
      card_values("IQS_MAC_CZM",
                  {{"dfric", 0.1}, {"sfric", 0.2}, {"cn", 3.0}, {"ct", 4.0}, {"visco", 5.0}, {"dupre", 6.0}}),
      law));
  const auto& czm = std::get<IqsMacCzm>(law);
  EXPECT_EQ(czm.dfric, 0.1);
  EXPECT_EQ(czm.sfric, 0.2);
  EXPECT_EQ(czm.cn, 3.0);
  EXPECT_EQ(czm.ct, 4.0);
  EXPECT_EQ(czm.visco, 5.0);
  EXPECT_EQ(czm.dupre, 6.0);
}

TEST(ContactLawTable, ThreeDimensionalFormsAreTheDocumentedOnes) {
  EXPECT_TRUE(provided_in_3d(IqsClb{0.3}));
  EXPECT_TRUE(provided_in_3d(IqsMohrDsClb{1.0, 1.0, 0.3, 0.3}));
  EXPECT_TRUE(provided_in_3d(IqsMacCzm{}));
  EXPECT_TRUE(provided_in_3d(ElasticRepellClb{}));
  EXPECT_TRUE(provided_in_3d(IqsClbG0{}));
  EXPECT_FALSE(provided_in_3d(NoNlgsBranch{}));  // MD_JKRs: a smooth law, no NLGS branch in 3D
  EXPECT_TRUE(provided_in_3d(ElasticWire{}));
  EXPECT_TRUE(provided_in_3d(ElasticRod{}));
  // Rods and wires link PTPT3 points only: no 2D form (the 2D scene refuses them).
  EXPECT_FALSE(provided_in_2d(ElasticWire{}));
  EXPECT_FALSE(provided_in_2d(ElasticRod{}));
  EXPECT_TRUE(provided_in_2d(IqsMacCzm{}));
  Contact3D c = contact_3d(0.0);
  EXPECT_FALSE(prepare_law(NoNlgsBranch{0.3}, c, LawStep{h, 0.0, true}));
}

// A 3D scene keeps a LawState3D beside each interaction only for a law whose code reads or writes
// one, or for which LMGC90 writes 3D internals (carried from a Vloc_Rloc.INI to the outputs).
TEST(ContactLawTable, OnlyLawsWithInternalsCohesionOrAReferenceLengthKeepA3DLawState) {
  EXPECT_FALSE(keeps_law_state_3d(IqsClb{0.3}));
  EXPECT_FALSE(keeps_law_state_3d(IqsDsClb{0.2, 0.3}));
  EXPECT_FALSE(keeps_law_state_3d(RstClb{0.5, 0.0, 0.3}));
  EXPECT_FALSE(keeps_law_state_3d(IqsWetDsClb{}));
  EXPECT_FALSE(keeps_law_state_3d(ElasticRepellClb{}));
  EXPECT_FALSE(keeps_law_state_3d(CoupledDof{}));
  EXPECT_TRUE(keeps_law_state_3d(IqsMohrDsClb{}));  // reads the contact surface
  EXPECT_TRUE(keeps_law_state_3d(IqsMacCzm{}));
  EXPECT_TRUE(keeps_law_state_3d(IqsClbG0{}));
  EXPECT_TRUE(keeps_law_state_3d(ElasticWire{}));
  EXPECT_TRUE(keeps_law_state_3d(ElasticRod{}));
  EXPECT_TRUE(keeps_law_state_3d(GapSgrClb{0.3}));  // LMGC90 writes its 3D internal
}

// In 2D a law keeps a LawState2D (its internal variables) beside each interaction when it has
// internals, or when LMGC90 writes 2D internals for it.
TEST(ContactLawTable, OnlyLawsWithInternalsKeepA2DLawState) {
  EXPECT_FALSE(keeps_law_state_2d(IqsClb{0.3}));
  EXPECT_FALSE(keeps_law_state_2d(IqsDsClb{0.2, 0.3}));
  EXPECT_FALSE(keeps_law_state_2d(RstClb{0.5, 0.0, 0.3}));
  EXPECT_FALSE(keeps_law_state_2d(IqsMohrDsClb{}));
  EXPECT_FALSE(keeps_law_state_2d(IqsWetDsClb{}));
  EXPECT_FALSE(keeps_law_state_2d(NoNlgsBranch{0.3}));  // MD_JKRs
  EXPECT_TRUE(keeps_law_state_2d(IqsMacCzm{}));
  EXPECT_TRUE(keeps_law_state_2d(IqsClbG0{}));
  EXPECT_TRUE(keeps_law_state_2d(GapSgrClb{0.3}));
  EXPECT_TRUE(keeps_law_state_2d(VelSgrDsClb{0.2, 0.3}));
}

TEST(IqsClb, ClosesAnOpenGapWithinTheStepButNeverPushesOut) {
  LocalProblem2D open = contact_2d(0.002), sunk = contact_2d(-0.002);
  prepare_law(IqsClb{0.4}, open, LawStep{h});
  prepare_law(IqsClb{0.4}, sunk, LawStep{h});
  EXPECT_DOUBLE_EQ(open.covfree(1), 0.002 / h);
  EXPECT_EQ(sunk.covfree(1), 0.0);
  EXPECT_EQ(open.mu, 0.4);
  Contact3D c3 = contact_3d(0.001);
  ASSERT_TRUE(prepare_law(IqsClb{0.4}, c3, LawStep{h}));
  EXPECT_DOUBLE_EQ(c3.covfree(1), 1.0);
}

TEST(IqsDsClb, UsesDynamicFrictionOnlyAfterSliding) {
  LocalProblem2D sticking = contact_2d(0.0, ContactStatus::stick),
                 sliding = contact_2d(0.0, ContactStatus::slide);
  prepare_law(IqsDsClb{0.2, 0.5}, sticking, LawStep{h});
  prepare_law(IqsDsClb{0.2, 0.5}, sliding, LawStep{h});
  EXPECT_EQ(sticking.mu, 0.5);
  EXPECT_EQ(sliding.mu, 0.2);
}

TEST(IqsClbG0, MeasuresTheGapFromItsValueAtTheFirstStep) {
  LocalProblem2D c = contact_2d(0.004);
  prepare_law(IqsClbG0{0.3}, c, LawStep{h, h, true, true});
  EXPECT_EQ(c.internal[0], 0.004);
  EXPECT_EQ(c.covfree(1), 0.0);
  c.status_begin = ContactStatus::stick;
  c.gap_begin = 0.005;
  prepare_law(IqsClbG0{0.3}, c, LawStep{h, 2 * h, false});
  EXPECT_NEAR(c.covfree(1), 0.001 / h, 1e-9);
  // 3D alike; a contact created after the first step keeps g_ref = 0 (plain IQS_CLB).
  Contact3D c3 = contact_3d(0.004);
  ASSERT_TRUE(prepare_law(IqsClbG0{0.3}, c3, LawStep{h, h, true, true}));
  EXPECT_EQ(c3.state.internal[0], 0.004);
  EXPECT_EQ(c3.covfree(1), 0.0);
  Contact3D late = contact_3d(0.004);
  ASSERT_TRUE(prepare_law(IqsClbG0{0.3}, late, LawStep{h, 5 * h, false}));
  EXPECT_NEAR(late.covfree(1), 0.004 / h, 1e-9);
}

TEST(RstClb, ScalesTheIncomingVelocityAndIgnoresOpenContacts) {
  Contact3D c = contact_3d(0.0);
  ASSERT_TRUE(prepare_law(RstClb{0.8, 0.5, 0.3}, c, LawStep{h}));
  EXPECT_DOUBLE_EQ(c.covfree(1), 0.8 * -2.0);
  EXPECT_DOUBLE_EQ(c.covfree(0), 0.5 * 0.3);
  EXPECT_DOUBLE_EQ(c.covfree(2), 0.5 * 0.1);
  LocalProblem2D open = contact_2d(0.01);
  prepare_law(RstClb{0.8, 0.5, 0.3}, open, LawStep{h});
  EXPECT_TRUE(open.inactive);
}

TEST(RstDsClb, RestitutionWithDynamicFrictionAfterSliding) {
  LocalProblem2D c = contact_2d(-0.001, ContactStatus::slide);
  prepare_law(RstDsClb{0.5, 0.0, 0.1, 0.6}, c, LawStep{h});
  EXPECT_DOUBLE_EQ(c.covfree(1), 0.5 * -2.0);
  EXPECT_EQ(c.mu, 0.1);
}

TEST(GapSgrClb, CorrectsAPenetrationWithinOneStep) {
  LocalProblem2D c = contact_2d(-0.002);
  prepare_law(GapSgrClb{0.3}, c, LawStep{h});
  EXPECT_DOUBLE_EQ(c.covfree(1), -0.002 / h);
}

TEST(GapSgrDsClb, GapFormWithStaticFrictionWhileSticking) {
  Contact3D c = contact_3d(-0.001, ContactStatus::stick);
  ASSERT_TRUE(prepare_law(GapSgrDsClb{0.1, 0.6}, c, LawStep{h}));
  EXPECT_DOUBLE_EQ(c.covfree(1), -1.0);
  EXPECT_EQ(c.mu, 0.6);
}

TEST(VelSgrClb, ActsOnlyOnceTheGapIsClosed) {
  LocalProblem2D open = contact_2d(0.001), closed = contact_2d(0.0);
  prepare_law(VelSgrClb{0.3}, open, LawStep{h});
  prepare_law(VelSgrClb{0.3}, closed, LawStep{h});
  EXPECT_TRUE(open.inactive);
  EXPECT_FALSE(closed.inactive);
  EXPECT_EQ(closed.covfree(1), 0.0);
}

TEST(VelSgrDsClb, VelocitySignoriniWithDynamicFrictionAfterSliding) {
  Contact3D c = contact_3d(-0.001, ContactStatus::slide);
  ASSERT_TRUE(prepare_law(VelSgrDsClb{0.1, 0.6}, c, LawStep{h}));
  EXPECT_FALSE(c.inactive);
  EXPECT_EQ(c.mu, 0.1);
}

TEST(ElasticRepellClb, AddsTheSpringComplianceToTheNormalBlock) {
  LocalProblem2D c = contact_2d(-0.001);
  prepare_law(ElasticRepellClb{1e6, 0.3}, c, LawStep{h});
  EXPECT_DOUBLE_EQ(c.WW(1, 1), 1.0 + 1.0 / (1e6 * h * h));
  EXPECT_DOUBLE_EQ(c.covfree(1), -1.0);
}

TEST(IqsMohrDsClb, IsCohesiveFromTheFirstStepUntilItStopsSticking) {
  Contact3D c = contact_3d(0.0);
  ASSERT_TRUE(prepare_law(IqsMohrDsClb{100.0, 50.0, 0.2, 0.3}, c, LawStep{h, 0.0, true}));
  EXPECT_EQ(c.status_begin, ContactStatus::Mstck);
  EXPECT_DOUBLE_EQ(c.correction, -100.0 * 0.5 * h);  // cohesion × contact surface
  EXPECT_EQ(c.mu, 0.5);                              // cohet / cohen
  c.status = ContactStatus::stick;
  finish_law(IqsMohrDsClb{100.0, 50.0, 0.2, 0.3}, c, LawStep{h});
  EXPECT_EQ(c.status, ContactStatus::Mstck);
  // Born after the first step: never cohesive (mod_nlgs_3D).
  Contact3D late = contact_3d(0.0);
  ASSERT_TRUE(prepare_law(IqsMohrDsClb{100.0, 50.0, 0.2, 0.3}, late, LawStep{h, 0.0, false}));
  EXPECT_EQ(late.correction, 0.0);
  // 2D: cohesion × contact length, shifted through W; also from step 1 only.
  LocalProblem2D c2 = contact_2d(0.0);
  c2.length = 2.0;
  prepare_law(IqsMohrDsClb{100.0, 50.0, 0.2, 0.3}, c2, LawStep{h, 0.0, true});
  EXPECT_EQ(c2.status_begin, ContactStatus::Mstck);
  EXPECT_DOUBLE_EQ(c2.correction(1), -200.0 * h);
  EXPECT_DOUBLE_EQ(c2.covfree(0), -200.0 * h * 0.5);
  LocalProblem2D late2 = contact_2d(0.0);
  prepare_law(IqsMohrDsClb{100.0, 50.0, 0.2, 0.3}, late2, LawStep{h, 0.0, false});
  EXPECT_EQ(late2.correction(1), 0.0);
}

TEST(IqsWetDsClb, IsCohesiveInsideTheWetHaloOnly) {
  Contact3D wet = contact_3d(0.0005, ContactStatus::stick), dry = contact_3d(0.002, ContactStatus::stick);
  const IqsWetDsClb law{10.0, 0.0, 0.001, 0.2, 0.3};
  ASSERT_TRUE(prepare_law(law, wet, LawStep{h}));
  ASSERT_TRUE(prepare_law(law, dry, LawStep{h}));
  EXPECT_EQ(wet.status_begin, ContactStatus::Wstck);
  EXPECT_DOUBLE_EQ(wet.correction, -10.0 * h);
  EXPECT_EQ(dry.status_begin, ContactStatus::noctc);
  EXPECT_EQ(dry.correction, 0.0);
}

// 2D: a contact ends the step in its W status only where prepare added a nonzero cohesion (inside
// the halo, cohen != 0); finish reads that from the gap and the law.
TEST(IqsWetDsClb, EndsWetOnlyWhereItsPreparationAddedACohesion2D) {
  const IqsWetDsClb law{10.0, 0.0, 0.001, 0.2, 0.3}, without_cohesion{0.0, 0.0, 0.001, 0.2, 0.3};
  LocalProblem2D wet = contact_2d(0.0005, ContactStatus::stick),
                 dry = contact_2d(0.002, ContactStatus::stick),
                 uncohesive = contact_2d(0.0005, ContactStatus::stick);
  prepare_law(law, wet, LawStep{h});
  prepare_law(law, dry, LawStep{h});
  prepare_law(without_cohesion, uncohesive, LawStep{h});
  EXPECT_EQ(wet.correction(1), -10.0 * h);
  EXPECT_EQ(dry.correction(1), 0.0);
  EXPECT_EQ(uncohesive.correction(1), 0.0);
  for (LocalProblem2D* c : {&wet, &dry, &uncohesive}) c->status = ContactStatus::Wstck;
  finish_law(law, wet, LawStep{h});
  finish_law(law, dry, LawStep{h});
  finish_law(without_cohesion, uncohesive, LawStep{h});
  EXPECT_EQ(wet.status, ContactStatus::Wstck);
  EXPECT_EQ(dry.status, ContactStatus::stick);
  EXPECT_EQ(uncohesive.status, ContactStatus::stick);
}

TEST(IqsMacCzm, StartsUndamagedAndDamagesUnderOpening) {
  const IqsMacCzm law{0.3, 0.3, 1e6, 1e6, 0.0, 10.0};
  LocalProblem2D c = contact_2d(0.0);
  prepare_law(law, c, LawStep{h, h, true, true});
  EXPECT_EQ(c.internal[3], 1.0);  // β
  EXPECT_TRUE(c.cohesive);
  EXPECT_EQ(c.mu, 0.0);              // friction × (1 − β)
  c.u = Eigen::Vector2d(0.0, 10.0);  // opening 1 cm in the step
  finish_law(law, c, LawStep{h, 0.5, false});
  EXPECT_LT(c.internal[3], 1.0);
  EXPECT_EQ(c.internal[4], 0.5);  // TPSini: time of the first damage
}

TEST(IqsMacCzm, TwoDimensionalBetaIsReEvaluatedAtEachCheckAndTheChecksBetaIsStored) {
  const IqsMacCzm law{0.3, 0.4, 2e6, 1e6, 0.0, 10.0};
  LocalProblem2D c = contact_2d(0.0);
  prepare_law(law, c, LawStep{h, h, true, true});
  c.length = 0.5;
  prepare_law(law, c, LawStep{h, h, false, false});  // L = 0.5
  EXPECT_EQ(c.internal[5], 1.0);                     // the β in use
  EXPECT_FALSE(update_law_at_check(law, c, Eigen::Vector2d(0.0, 1.0), LawStep{h, h, false, false}));
  // Opening 8 mm: cn δn² = 128 > w = 10, β = w / (cn δn²).
  ASSERT_TRUE(update_law_at_check(law, c, Eigen::Vector2d(0.0, 8.0), LawStep{h, h, false, false}));
  const double beta = 10.0 / 128.0;
  EXPECT_DOUBLE_EQ(c.internal[5], beta);
  EXPECT_EQ(c.internal[3], 1.0);
  EXPECT_DOUBLE_EQ(c.mu, 0.4 * (1.0 - beta));
  EXPECT_DOUBLE_EQ(c.cohesive_slope(1), -0.5 * beta * beta * h * h * 2e6);
  // The final velocity stores less than w: the checks' β is stored.
  c.u = Eigen::Vector2d(0.0, 1.0);
  finish_law(law, c, LawStep{h, h, false, false});
  EXPECT_DOUBLE_EQ(c.internal[3], beta);
  EXPECT_EQ(c.internal[5], 0.0);  // not carried over
}

TEST(IqsMacCzm, ContactsCreatedAfterTheFirstStepStartBroken) {
  // LMGC90 makes the interface sound (β = 1) only at the run's first step (init_CZM, Nstep = 1).
  const IqsMacCzm law{0.3, 0.4, 1e6, 1e6, 0.0, 10.0};
  LocalProblem2D c2 = contact_2d(0.0);
  prepare_law(law, c2, LawStep{h, 2 * h, false});
  EXPECT_EQ(c2.internal[3], 0.0);
  EXPECT_FALSE(c2.cohesive);
  EXPECT_EQ(c2.mu, 0.4);
  Contact3D c3 = contact_3d(0.0);
  ASSERT_TRUE(prepare_law(law, c3, LawStep{h, 2 * h, false}));
  EXPECT_EQ(c3.state.internal[4], 0.0);
  EXPECT_EQ(c3.form, LocalForm3D::coulomb);
  EXPECT_EQ(c3.mu, 0.4);
}

TEST(IqsMacCzm, ThreeDimensionalFormIsTheCohesiveZoneOnTheContactSurface) {
  const IqsMacCzm law{0.3, 0.4, 2e6, 1e6, 0.0, 10.0};
  Contact3D c = contact_3d(0.002);  // surface 0.5
  ASSERT_TRUE(prepare_law(law, c, LawStep{h, h, true, true}));
  EXPECT_EQ(c.status_begin, ContactStatus::Cnnow);
  EXPECT_EQ(c.form, LocalForm3D::cohesive);
  EXPECT_EQ(c.state.internal[0], 0.5);    // L = surface
  EXPECT_EQ(c.state.internal[2], 0.002);  // δn = (γ)+
  EXPECT_EQ(c.state.internal[4], 1.0);    // β
  EXPECT_DOUBLE_EQ(c.covfree(1), 0.002 / h);
  EXPECT_EQ(c.mu, 0.0);  // sfric (1 − β)
  // k = −L β² h² C, radh = −L β² h C δ (tangential jumps 0 at the start).
  EXPECT_DOUBLE_EQ(c.state.cohesive_slope(0), -0.5 * h * h * 1e6);
  EXPECT_DOUBLE_EQ(c.state.cohesive_slope(1), -0.5 * h * h * 2e6);
  EXPECT_DOUBLE_EQ(c.state.cohesive_slope(2), -0.5 * h * h * 1e6);
  EXPECT_EQ(c.state.cohesive_shift, Eigen::Vector3d::Zero());
  // Opening 1 cm and sliding 1 cm in the step: β drops, jumps and TPSini are stored.
  c.u = Eigen::Vector3d(10.0, 8.0, 0.0);
  c.status = ContactStatus::stick;
  finish_law(law, c, LawStep{h, 0.25, true});
  EXPECT_LT(c.state.internal[4], 1.0);
  EXPECT_DOUBLE_EQ(c.state.internal[1], 0.01);
  EXPECT_DOUBLE_EQ(c.state.internal[2], 0.002 + 0.008);
  EXPECT_EQ(c.state.internal[5], 0.25);
  EXPECT_EQ(c.status, ContactStatus::Cstck);
  // Next step: the tangential jump feeds radh_t.
  c.status_begin = c.status;
  const double beta = c.state.internal[4];
  ASSERT_TRUE(prepare_law(law, c, LawStep{h, 2 * h, false}));
  EXPECT_DOUBLE_EQ(c.state.cohesive_shift(0), -0.5 * beta * beta * h * 1e6 * 0.01);
  EXPECT_DOUBLE_EQ(c.mu, 0.4 * (1.0 - beta));
}

// LMGC90's solve_nlgs re-evaluates β at each convergence check (updt_CZM_3D(.false.)) from the
// check's velocity, and the sweeps after it use that β; the end of the step stores β from the
// final velocity when the damage rule takes it, else the checks' β.
TEST(IqsMacCzm, ThreeDimensionalBetaIsReEvaluatedAtEachCheckFromTheStepsStart) {
  const IqsMacCzm law{0.3, 0.4, 2e6, 1e6, 0.0, 10.0};
  Contact3D c = contact_3d(0.0);  // surface 0.5, closed
  ASSERT_TRUE(prepare_law(law, c, LawStep{h, h, true, true}));
  ASSERT_TRUE(updates_at_check(law));
  EXPECT_FALSE(updates_at_check(IqsClb{0.3}));
  EXPECT_EQ(c.state.law_working, 1.0);
  // A check velocity that stores less than w: β stays, nothing changes.
  EXPECT_FALSE(update_law_at_check(law, c, Eigen::Vector3d(0.0, 1.0, 0.0), LawStep{h, h, true, true}));
  EXPECT_EQ(c.form, LocalForm3D::cohesive);
  // Opening 8 mm in the step: cn δn² = 2e6 × 6.4e-5 = 128 > w = 10, β = w / (cn δn²) (no viscosity).
  ASSERT_TRUE(update_law_at_check(law, c, Eigen::Vector3d(0.0, 8.0, 0.0), LawStep{h, h, true, true}));
  const double beta = 10.0 / 128.0;
  EXPECT_DOUBLE_EQ(c.state.law_working, beta);
  EXPECT_EQ(c.state.internal[4], 1.0);  // stored only at the end of the step
  EXPECT_DOUBLE_EQ(c.mu, 0.4 * (1.0 - beta));
  EXPECT_DOUBLE_EQ(c.state.cohesive_slope(1), -0.5 * beta * beta * h * h * 2e6);
  // A later check computes from the step's starting β again, not from the last check's.
  ASSERT_TRUE(update_law_at_check(law, c, Eigen::Vector3d(0.0, 16.0, 0.0), LawStep{h, h, true, true}));
  EXPECT_DOUBLE_EQ(c.state.law_working, 10.0 / 512.0);
  // The final velocity stores less than w: the rule does not take it, the checks' β is stored.
  c.u = Eigen::Vector3d(0.0, 1.0, 0.0);
  c.status = ContactStatus::stick;
  finish_law(law, c, LawStep{h, h, true, true});
  EXPECT_DOUBLE_EQ(c.state.internal[4], 10.0 / 512.0);
  // Fully broken at a check (β below 1e-12 → 0): the contact turns to plain IQS with full friction.
  Contact3D d = contact_3d(0.0);
  ASSERT_TRUE(prepare_law(IqsMacCzm{0.3, 0.4, 2e6, 1e6, 0.0, 1e-12}, d, LawStep{h, h, true, true}));
  ASSERT_TRUE(update_law_at_check(IqsMacCzm{0.3, 0.4, 2e6, 1e6, 0.0, 1e-12}, d,
                                  Eigen::Vector3d(0.0, 1e3, 0.0), LawStep{h, h, true, true}));
  EXPECT_EQ(d.state.law_working, 0.0);
  EXPECT_EQ(d.form, LocalForm3D::coulomb);
  EXPECT_EQ(d.mu, 0.4);
  EXPECT_EQ(d.state.cohesive_slope, Eigen::Vector3d::Zero());
}

// The GAP cohesive zones of deformable pairs: the normal free velocity is γ/h even when penetrated
// (IQS_MAC_CZM: its positive part), the stored normal jump is γ, and L is the CLxxx point's length on
// CLALp and CLJCx, LMGC90's 0.35 on PLALp and DKALp.
TEST(MacCzm, HasAGapNormalPartAndTheLengthOfItsPair) {
  const MacCzm law{0.3, 0.4, 2e6, 1e6, 0.0, 10.0};
  LocalProblem2D c = contact_2d(-1e-4);
  c.family = PairFamily2D::CLALp;
  c.length = 0.05;
  prepare_law(law, c, LawStep{h, h, true, true});
  EXPECT_DOUBLE_EQ(c.covfree(1), -1e-4 / h);
  EXPECT_EQ(c.internal[2], -1e-4);
  EXPECT_EQ(c.internal[0], 0.05);
  EXPECT_EQ(c.internal[3], 1.0);
  EXPECT_DOUBLE_EQ(c.cohesive_slope(1), -0.05 * h * h * 2e6);  // β² = 1
  LocalProblem2D d = contact_2d(-1e-4);
  d.family = PairFamily2D::PLALp;
  prepare_law(law, d, LawStep{h, h, true, true});
  EXPECT_EQ(d.internal[0], 0.35);
  LocalProblem2D i = contact_2d(-1e-4);
  prepare_law(IqsMacCzm{0.3, 0.4, 2e6, 1e6, 0.0, 10.0}, i, LawStep{h, h, true, true});
  EXPECT_EQ(i.covfree(1), 0.0);
}

// MAL_CZM's traction is β C δ (β, not β²), and its β follows the bilinear-softening envelope: 1 up to
// dc = S1/cn in pure opening, then (dc/d)(1 − ((d − dc)/dt)²), dt = 1.5 (G1 G2 − ½ dc² G2 cn)/(dc G2 cn),
// 0 past dc + dt; never growing back.
TEST(MalCzm, DamagesAlongItsBilinearEnvelopeWithALinearStiffnessInBeta) {
  const double cn = 1e9, ct = 5e8, s1 = 4e4, s2 = 2e4, g = 6.0;
  const MalCzm law{0.3, 0.5, cn, ct, s1, s2, g, g};
  LocalProblem2D c = contact_2d(0.0);
  c.family = PairFamily2D::CLALp;
  c.length = 0.05;
  prepare_law(law, c, LawStep{h, h, true, true});
  const double dc = s1 / cn, dt = 1.5 * (g * g - 0.5 * dc * dc * g * cn) / (dc * g * cn);
  EXPECT_FALSE(update_law_at_check(law, c, Eigen::Vector2d(0.0, 0.9 * dc / h), LawStep{h, h, false, false}));
  const double d = dc + 0.5 * dt;
  ASSERT_TRUE(update_law_at_check(law, c, Eigen::Vector2d(0.0, d / h), LawStep{h, h, false, false}));
  const double beta = (dc / d) * (1.0 - 0.25);
  EXPECT_NEAR(c.internal[5], beta, 1e-12);
  EXPECT_NEAR(c.cohesive_slope(1), -0.05 * beta * h * h * cn, 1e-12 * 0.05 * h * h * cn);
  c.u = Eigen::Vector2d(0.0, (dc + 1.01 * dt) / h);
  finish_law(law, c, LawStep{h, 0.25, false, false});
  EXPECT_EQ(c.internal[3], 0.0);   // broken
  EXPECT_EQ(c.internal[4], 0.25);  // TPSini
  c.gap_begin = 0.0;
  prepare_law(law, c, LawStep{h, 2 * h, false, false});
  EXPECT_FALSE(c.cohesive);
  EXPECT_EQ(c.mu, 0.5);  // sticking friction × (1 − β)
}

// GAP_MOHR_DS_CLB is IQS_MOHR_DS_CLB's cohesion with the GAP normal part.
TEST(GapMohrDsClb, IsCohesiveFromTheFirstStepWithAGapNormalPart) {
  const GapMohrDsClb law{1e4, 5e3, 0.3, 0.5};
  LocalProblem2D c = contact_2d(-2e-5);
  c.length = 0.05;
  prepare_law(law, c, LawStep{h, h, true, true});
  EXPECT_EQ(c.status_begin, ContactStatus::Mstck);
  EXPECT_DOUBLE_EQ(c.correction(1), -1e4 * 0.05 * h);
  EXPECT_DOUBLE_EQ(c.covfree(1), -1e4 * 0.05 * h * c.WW(1, 1) - 2e-5 / h);
  EXPECT_DOUBLE_EQ(c.mu, 0.5);  // cohet / cohen
  c.status = ContactStatus::stick;
  finish_law(law, c, LawStep{h, h, true, true});
  EXPECT_EQ(c.status, ContactStatus::Mstck);
  LocalProblem2D later = contact_2d(-2e-5);
  prepare_law(law, later, LawStep{h, 2 * h, false, false});
  EXPECT_EQ(later.correction(1), 0.0);  // created after step 1: never cohesive
}

// GAP_WET_DS_CLB: cohesion in the halo with a GAP normal part; out of it the status is kept, and a
// contact that began the step wet ends it in a W status (LMGC90's writes Wnctc for a wet contact
// that has left the halo).
TEST(GapWetDsClb, StaysWetOnceWettedAndHasAGapNormalPart) {
  const GapWetDsClb law{200.0, 100.0, 2e-4, 0.3, 0.5};
  LocalProblem2D c = contact_2d(-1e-5, ContactStatus::noctc);
  prepare_law(law, c, LawStep{h, h, false, false});
  EXPECT_EQ(c.status_begin, ContactStatus::Wnctc);
  EXPECT_DOUBLE_EQ(c.correction(1), -200.0 * h);
  EXPECT_DOUBLE_EQ(c.covfree(1), -200.0 * h * c.WW(1, 1) - 1e-5 / h);
  LocalProblem2D out = contact_2d(1e-3, ContactStatus::Wstck);
  prepare_law(law, out, LawStep{h, h, false, false});
  EXPECT_EQ(out.status_begin, ContactStatus::Wstck);  // IQS_WET_DS_CLB would force noctc
  EXPECT_EQ(out.correction(1), 0.0);
  EXPECT_DOUBLE_EQ(out.covfree(1), 1e-3 / h);
  out.status = ContactStatus::noctc;
  finish_law(law, out, LawStep{h, h, false, false});
  EXPECT_EQ(out.status, ContactStatus::Wnctc);
  LocalProblem2D dry = contact_2d(1e-3, ContactStatus::noctc);
  prepare_law(law, dry, LawStep{h, h, false, false});
  dry.status = ContactStatus::noctc;
  finish_law(law, dry, LawStep{h, h, false, false});
  EXPECT_EQ(dry.status, ContactStatus::noctc);
}

TEST(ElasticWire, IsATensionOnlySpringOnTheReferenceLength) {
  const ElasticWire law{2000.0, 0.1};
  Contact3D c = contact_3d(1.3);
  c.state.reference_gap = 1.0;
  ASSERT_TRUE(prepare_law(law, c, LawStep{h}));
  EXPECT_EQ(c.form, LocalForm3D::wire);
  EXPECT_EQ(c.state.internal[0], 1.0);  // gapREF
  EXPECT_DOUBLE_EQ(c.normal_compliance, 1.0 / (2000.0 * h * h));
  EXPECT_DOUBLE_EQ(c.covfree(1), (1.3 - 1.1) / h);
  EXPECT_EQ(c.mu, 0.0);
  Contact3D unlinked = contact_3d(1.3);  // no reference length: no link (LMGC90 stops)
  ASSERT_TRUE(prepare_law(law, unlinked, LawStep{h}));
  EXPECT_TRUE(unlinked.inactive);
}

TEST(ElasticRod, IsTheBilateralSpring) {
  Contact3D c = contact_3d(0.9);
  c.state.reference_gap = 1.0;
  ASSERT_TRUE(prepare_law(ElasticRod{500.0, 0.0}, c, LawStep{h}));
  EXPECT_EQ(c.form, LocalForm3D::rod);
  EXPECT_DOUBLE_EQ(c.covfree(1), -0.1 / h);
  EXPECT_DOUBLE_EQ(c.normal_compliance, 1.0 / (500.0 * h * h));
}

TEST(ElasticRepellClb, ThreeDimensionalFormAddsTheSpringComplianceOnTheNormal) {
  Contact3D c = contact_3d(-0.001);
  ASSERT_TRUE(prepare_law(ElasticRepellClb{1e6, 0.4}, c, LawStep{h}));
  EXPECT_EQ(c.form, LocalForm3D::coulomb);
  EXPECT_DOUBLE_EQ(c.normal_compliance, 1.0 / (1e6 * h * h));
  EXPECT_DOUBLE_EQ(c.covfree(1), -0.001 / h);  // gap form: the penetration is pushed out
  EXPECT_EQ(c.mu, 0.4);
}

TEST(CoupledDof, ThreeDimensionalFormGluesEveryComponent) {
  Contact3D c = contact_3d(0.002);
  ASSERT_TRUE(prepare_law(CoupledDof{}, c, LawStep{h}));
  EXPECT_EQ(c.form, LocalForm3D::glued);
  EXPECT_EQ(c.covfree, Eigen::Vector3d::Zero());
}

TEST(CoupledDof, HasNoFriction) {
  LocalProblem2D c = contact_2d(0.0);
  c.mu = 1.0;
  prepare_law(CoupledDof{}, c, LawStep{h});
  EXPECT_EQ(c.mu, 0.0);
}

TEST(NoNlgsBranch, IsVelocitySignoriniWithoutGapTerm) {
  LocalProblem2D c = contact_2d(0.003);
  prepare_law(NoNlgsBranch{0.25}, c, LawStep{h});
  EXPECT_EQ(c.covfree(1), 0.0);
  EXPECT_EQ(c.mu, 0.25);
}

}  // namespace
}  // namespace lmgc::solver
