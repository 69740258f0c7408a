// DOF and Vloc_Rloc files of a rigid 3D run (solver/io/state_files_3d): built from a small scene
// run with step_3d, written by the grammar writers, read back by the grammar parsers (round trip),
// checked field by field against the run state, and read back as a warm start.
// docs/lmgc90-facts/state-and-outputs.md §1.2-1.4.2.
#include "solver/io/state_files_3d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "grammar/common/diagnostic.hpp"
#include "grammar/common/source.hpp"
#include "grammar/dof/parser.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"
#include "tests/support/nlgs_options.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kH = 1e-3;
constexpr double kG = 9.81;

// Body 1: a ground PLANx (top face z = 0); body 2: a sphere resting on it; body 3: a sphere resting
// on body 2; body 4: a two-sphere cluster (SPHEb) resting on the ground. Contactors 0..4.
struct SceneRun {
  Scene3D scene;
  RunState3D state;
};

Scene3D build_scene() {
  SceneBuilder3D b;
  b.add_fixed_plane(Vector3d(0.0, 0.0, -0.05), Matrix3d::Identity(), Vector3d(1.0, 1.0, 0.05));
  b.add_sphere(Vector3d(0.0, 0.0, 0.1), 0.1, 1000.0);
  b.add_sphere(Vector3d(0.0, 0.0, 0.3), 0.1, 1000.0);
  b.add_sphere_cluster(Vector3d(0.5, 0.0, 0.05), {Vector3d(-0.05, 0.0, 0.0), Vector3d(0.05, 0.0, 0.0)}, 0.05,
                       1000.0);
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("SPHER", "BLEUx", "iqsc0", "PLANx", "VERTx", 0.01);
  b.see("SPHER", "BLEUx", "iqsc0", "SPHER", "BLEUx", 0.01);
  return b.build();
}

SceneRun run(int steps) {
  SceneRun r{build_scene(), {}};
  r.state.h = kH;
  for (int i = 0; i < steps; ++i) {
    const NlgsResult result = step_3d(r.scene, r.state, test::converged_nlgs_options(10));
    EXPECT_TRUE(result.converged);
  }
  return r;
}

grammar::VlocRlocFile parse_vloc(const std::string& text) {
  grammar::DiagnosticSink sink;
  grammar::VlocRlocFile f = grammar::parse_vloc_rloc(grammar::SourceText("Vloc_Rloc.OUT.1", text), sink);
  EXPECT_FALSE(sink.has_errors());
  return f;
}

grammar::DofFile parse_dof(const std::string& text) {
  grammar::DiagnosticSink sink;
  grammar::DofFile f = grammar::parse_dof(grammar::SourceText("DOF.OUT.1", text), sink);
  EXPECT_FALSE(sink.has_errors());
  return f;
}

// Values as D14.7 keeps them: 7 digits of a mantissa in [0.1, 1).
void expect_close(double written, double read, const std::string& what) {
  EXPECT_NEAR(read, written, 5e-7 * std::fabs(written) + 1e-300) << what;
}

void expect_close(const std::vector<grammar::Real>& a, const std::vector<grammar::Real>& b,
                  const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) expect_close(a[k].value, b[k].value, what);
}

const grammar::VlocRlocVector& vector_line(const grammar::VlocRlocInteraction& c, std::size_t line) {
  return c.vectors.at(line);
}

TEST(StateFiles3D, VlocRlocRoundTripsThroughTheGrammarWriterAndParser) {
  const SceneRun r = run(3);
  const grammar::VlocRlocFile built = vloc_rloc_file_3d(r.scene, r.state);
  const std::string text = grammar::write_vloc_rloc(built);
  const grammar::VlocRlocFile back = parse_vloc(text);
  EXPECT_EQ(grammar::write_vloc_rloc(back), text);
  EXPECT_EQ(back.step.value, 3);
  expect_close(built.time.value, back.time.value, "time");
  ASSERT_EQ(back.interactions.size(), built.interactions.size());
  for (std::size_t i = 0; i < built.interactions.size(); ++i) {
    const auto& a = built.interactions[i];
    const auto& b = back.interactions[i];
    EXPECT_EQ(b.type, a.type);
    EXPECT_EQ(b.number, a.number);
    EXPECT_EQ(b.title, a.title);
    EXPECT_EQ(b.words, a.words);
    EXPECT_EQ(b.integers, a.integers);
    ASSERT_EQ(b.vectors.size(), a.vectors.size());
    for (std::size_t v = 0; v < a.vectors.size(); ++v) {
      EXPECT_EQ(b.vectors[v].labels, a.vectors[v].labels);
      expect_close(a.vectors[v].values, b.vectors[v].values, "interaction " + std::to_string(i));
    }
    EXPECT_TRUE(b.internal_lines.empty());  // IQS_CLB: no internal variables
    EXPECT_TRUE(b.internal_comment.empty());
  }
}

TEST(StateFiles3D, VlocRlocHoldsTheRunStateInLmgc90sLayout) {
  const SceneRun r = run(3);
  const auto& contacts = r.state.contacts;
  // Sphere–ground, two cluster spheres–ground, sphere–sphere.
  ASSERT_EQ(contacts.size(), 4u);
  const grammar::VlocRlocFile f = parse_vloc(grammar::write_vloc_rloc(vloc_rloc_file_3d(r.scene, r.state)));
  ASSERT_EQ(f.interactions.size(), 4u);
  // SPPLx before SPSPx, by candidate contactor.
  EXPECT_EQ(f.interactions[0].type.value, "SPPLx");
  EXPECT_EQ(f.interactions[1].type.value, "SPPLx");
  EXPECT_EQ(f.interactions[2].type.value, "SPPLx");
  EXPECT_EQ(f.interactions[3].type.value, "SPSPx");

  const std::string text = grammar::write_vloc_rloc(vloc_rloc_file_3d(r.scene, r.state));
  EXPECT_NE(text.find("$steps        3              time= 0.3000000D-02\n"), std::string::npos) << text;
  EXPECT_NE(text.find(" cdbdy  numbr  cdtac  numbr  CDVER  behav  anbdy  numbr  antac  numbr  sttus\n"
                      " RBDY3      2  SPHER      1         iqsc0  RBDY3      1  PLANx      1  stick\n"
                      "                             rls/H"),
            std::string::npos)
      << text;
  // Cluster spheres (SPHEb) are written SPHER with their rank in the body.
  EXPECT_NE(text.find(" RBDY3      4  SPHER      2         iqsc0  RBDY3      1  PLANx      1  stick\n"),
            std::string::npos)
      << text;
  // SPSPx ends with iantac: the antagonist's rank among all spheres.
  EXPECT_NE(
      text.find(" RBDY3      2  SPHER      1         iqsc0  RBDY3      3  SPHER      1  stick      2\n"),
      std::string::npos)
      << text;

  for (const auto& block : f.interactions) {
    EXPECT_EQ(block.words.back().value, "stick");
    // Find the interaction of the run this block stands for.
    const auto it = std::find_if(contacts.begin(), contacts.end(), [&](const Interaction3D& c) {
      const Contactor3D& cd = r.scene.contactors[static_cast<std::size_t>(c.candidate)];
      const Contactor3D& an = r.scene.contactors[static_cast<std::size_t>(c.antagonist)];
      return cd.body + 1 == block.integers[0].value && cd.rank == block.integers[1].value &&
             an.body + 1 == block.integers[2].value && an.rank == block.integers[3].value;
    });
    ASSERT_NE(it, contacts.end());
    const Interaction3D& c = *it;
    EXPECT_EQ(c.status, ContactStatus::stick);
    const auto& rl = vector_line(block, 0);
    ASSERT_EQ(rl.labels, (std::vector<std::string>{"rls/H", "rlt/H", "rln/H"}));
    expect_close(c.r(2) / kH, rl.values[0].value, "rls/H");
    expect_close(c.r(0) / kH, rl.values[1].value, "rlt/H");
    expect_close(c.r(1) / kH, rl.values[2].value, "rln/H");
    const auto& vl = vector_line(block, 1);
    ASSERT_EQ(vl.labels, (std::vector<std::string>{"vls =", "vlt =", "vln ="}));
    expect_close(c.u(2), vl.values[0].value, "vls");
    expect_close(c.u(0), vl.values[1].value, "vlt");
    expect_close(c.u(1), vl.values[2].value, "vln");
    const auto& gap = vector_line(block, 2);
    ASSERT_EQ(gap.labels, (std::vector<std::string>{"gTT ="}));
    expect_close(c.gap_begin + kH * c.u(1), gap.values[0].value, "gTT");
    EXPECT_NEAR(gap.values[0].value, 0.0, 1e-12);  // resting: the end-of-step gap closes
    // Frame rows s, t, n, then the contact point.
    for (int k = 0; k < 3; ++k) {
      expect_close(c.frame(2, k), vector_line(block, 3).values[static_cast<std::size_t>(k)].value, "s");
      expect_close(c.frame(0, k), vector_line(block, 4).values[static_cast<std::size_t>(k)].value, "t");
      expect_close(c.frame(1, k), vector_line(block, 5).values[static_cast<std::size_t>(k)].value, "n");
      expect_close(c.point(k), vector_line(block, 6).values[static_cast<std::size_t>(k)].value, "coo");
    }
    EXPECT_EQ(vector_line(block, 3).labels[0], "s(1)=");
    EXPECT_EQ(vector_line(block, 6).labels[2], "coo3=");
  }
  // At rest, rln/H carries the weight: the lower sphere holds both spheres, the upper one its own.
  const double sphere_weight = 1000.0 * 4.0 / 3.0 * std::numbers::pi * 0.001 * kG;
  EXPECT_NEAR(vector_line(f.interactions[0], 0).values[2].value, 2.0 * sphere_weight, 1e-6 * sphere_weight);
  EXPECT_NEAR(vector_line(f.interactions[3], 0).values[2].value, sphere_weight, 1e-6 * sphere_weight);
}

TEST(StateFiles3D, DofRoundTripsAndHoldsTheBodies) {
  const SceneRun r = run(3);
  const grammar::DofFile built = dof_file_3d(r.scene, r.state);
  const std::string text = grammar::write_dof(built);
  const grammar::DofFile back = parse_dof(text);
  EXPECT_EQ(grammar::write_dof(back), text);
  EXPECT_EQ(back.step.value, 3);
  ASSERT_EQ(back.sections.size(), 2u);
  EXPECT_TRUE(back.sections[1].bodies.empty());
  const auto& bodies = back.sections[0].bodies;
  ASSERT_EQ(bodies.size(), r.scene.bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    EXPECT_EQ(bodies[i].body_type.value, "RBDY3");
    EXPECT_EQ(bodies[i].number.value, static_cast<std::int64_t>(i + 1));
    ASSERT_EQ(bodies[i].nodes.size(), 1u);
    const grammar::DofNode& node = bodies[i].nodes[0];
    EXPECT_EQ(node.node_type.value, "NO6xx");
    EXPECT_EQ(node.number.value, 1);
    expect_close(built.sections[0].bodies[i].nodes[0].x, node.x, "X");
    expect_close(built.sections[0].bodies[i].nodes[0].v, node.v, "V");
    expect_close(built.sections[0].bodies[i].nodes[0].frame, node.frame, "a b g");
    ASSERT_EQ(node.x.size(), 6u);
    ASSERT_EQ(node.frame.size(), 9u);
    for (int d = 0; d < 6; ++d) {
      expect_close(r.scene.bodies.displacement[i](d), node.x[static_cast<std::size_t>(d)].value, "X");
      expect_close(r.scene.bodies.velocity[i](d), node.v[static_cast<std::size_t>(d)].value, "V");
    }
    for (int axis = 0; axis < 3; ++axis)
      for (int d = 0; d < 3; ++d)
        expect_close(r.scene.bodies.frame[i](d, axis),
                     node.frame[static_cast<std::size_t>(3 * axis + d)].value, "frame");
  }
  EXPECT_NE(text.find("$bdyty\n RBDY3        4\n$nodty\n NO6xx      1                X(1)="),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("                             a(1)="), std::string::npos);
  EXPECT_NE(text.find("                             g(1)="), std::string::npos);
}

TEST(StateFiles3D, WarmStartGivesBackTheReactionsAndStatuses) {
  SceneRun r = run(3);
  const grammar::VlocRlocFile f = parse_vloc(grammar::write_vloc_rloc(vloc_rloc_file_3d(r.scene, r.state)));
  const WarmStart3D warm_start = warm_start_3d(f, r.scene, kH);
  const std::vector<Interaction3D>& warm = warm_start.interactions;
  const auto& contacts = r.state.contacts;
  ASSERT_EQ(warm.size(), contacts.size());
  for (std::size_t k = 0; k < warm.size(); ++k) {
    EXPECT_EQ(warm[k].family, contacts[k].family);
    EXPECT_EQ(warm[k].candidate, contacts[k].candidate);
    EXPECT_EQ(warm[k].antagonist, contacts[k].antagonist);
    EXPECT_EQ(warm[k].candidate_body, contacts[k].candidate_body);
    EXPECT_EQ(warm[k].antagonist_body, contacts[k].antagonist_body);
    EXPECT_EQ(warm[k].law, contacts[k].law);
    EXPECT_EQ(warm[k].status, contacts[k].status);
    for (int d = 0; d < 3; ++d) {
      expect_close(contacts[k].r(d), warm[k].r(d), "r");
      expect_close(contacts[k].u(d), warm[k].u(d), "u");
    }
  }

  // Restarting from the warm start gives the step the run itself takes next.
  SceneRun restarted{r.scene, r.state};
  store_interactions(restarted.state, warm, warm_start.law_states);
  step_3d(r.scene, r.state, test::converged_nlgs_options(10));
  step_3d(restarted.scene, restarted.state, test::converged_nlgs_options(10));
  ASSERT_EQ(restarted.state.contacts.size(), r.state.contacts.size());
  for (std::size_t k = 0; k < r.state.contacts.size(); ++k) {
    EXPECT_EQ(restarted.state.contacts[k].status, r.state.contacts[k].status);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(restarted.state.contacts[k].r(d), r.state.contacts[k].r(d), 1e-9);
  }
}

TEST(StateFiles3D, WarmStartSkipsUnknownContactorsAndOtherModules) {
  SceneRun r = run(1);
  grammar::VlocRlocFile f = vloc_rloc_file_3d(r.scene, r.state);
  ASSERT_EQ(f.interactions.size(), 4u);
  f.interactions[0].integers[0] = grammar::Integer{99};  // no body 99
  f.interactions[1].type = grammar::Word{"PRPLx"};       // not a sphere module
  f.interactions[2].integers[2] = grammar::Integer{2};   // SPPLx whose antagonist is a sphere
  const WarmStart3D warm_start = warm_start_3d(f, r.scene, kH);
  const std::vector<Interaction3D>& warm = warm_start.interactions;
  ASSERT_EQ(warm.size(), 1u);
  EXPECT_EQ(warm[0].family, PairFamily3D::SPSPx);
}

TEST(StateFiles3D, InternalVariablesOfTheLawAreWrittenWithTheirNames) {
  SceneBuilder3D b;
  b.add_fixed_plane(Vector3d(0.0, 0.0, -0.05), Matrix3d::Identity(), Vector3d(1.0, 1.0, 0.05));
  b.add_sphere(Vector3d(0.0, 0.0, 0.1), 0.1, 1000.0);
  b.add_law("gapsg", GapSgrClb{0.3});
  b.see("SPHER", "BLEUx", "gapsg", "PLANx", "VERTx", 0.01);
  Scene3D scene = b.build();
  RunState3D state;
  state.h = kH;
  step_3d(scene, state, test::converged_nlgs_options(10));
  ASSERT_EQ(state.contacts.size(), 1u);
  ASSERT_EQ(state.law_states.size(), 1u);  // GAP_SGR_CLB has 3D internals: its scene keeps law states
  state.law_states[0].internal[0] = 0.25;
  const grammar::VlocRlocFile built = vloc_rloc_file_3d(scene, state);
  ASSERT_EQ(built.interactions.size(), 1u);
  const std::string text = grammar::write_vloc_rloc(built);
  EXPECT_NE(text.find("\n#taille_ele    "), std::string::npos) << text;
  EXPECT_NE(text.find("\n  0.2500000D+00\n \n"), std::string::npos) << text;
  const grammar::VlocRlocFile back = parse_vloc(text);
  ASSERT_EQ(back.interactions.size(), 1u);
  EXPECT_EQ(back.interactions[0].internal_comment, built.interactions[0].internal_comment);
  const WarmStart3D warm_start = warm_start_3d(back, scene, kH);
  const std::vector<Interaction3D>& warm = warm_start.interactions;
  ASSERT_EQ(warm.size(), 1u);
  EXPECT_DOUBLE_EQ(warm_start.law_states[0].internal[0], 0.25);
}

TEST(StateFiles3D, EveryPairFamilyHasItsVlocRlocBlockInTheGrammar) {
  for (int k = 0; k < kPairFamily3DCount; ++k) {
    const std::string_view name = pair_family_name(static_cast<PairFamily3D>(k));
    ASSERT_FALSE(name.empty()) << "family " << k;
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(name);
    ASSERT_NE(kind, nullptr) << name;
    EXPECT_EQ(kind->dimension, 3) << name;
  }
}

// A sphere resting in a fixed drum (SPDCx) and a sphere hanging by an ELASTIC_WIRE (PTPT3): both
// blocks are written in LMGC90's layout (PTPT3: no CDVER column, trailing iantac, gapREF as its
// internal variable), parse back to the same text and warm-start the same interactions.
TEST(StateFiles3D, DrumAndPointLinkBlocksRoundTripAndWarmStart) {
  SceneBuilder3D b;
  b.add_sphere(Vector3d(0.0, 0.0, -0.4), 0.1, 1000.0);
  Matrix3d along_x;  // the drum's axis (third column) along x
  along_x << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  b.add_fixed_tube(Vector3d::Zero(), along_x, 1.0, 0.5);
  const int anchor =
      b.add_fixed_plane(Vector3d(3.0, 0.0, 0.0), Matrix3d::Identity(), Vector3d(0.1, 0.1, 0.1));
  b.add_point(anchor, Vector3d::Zero(), "ANCRx");
  const int hanging = b.add_sphere(Vector3d(3.0, 0.0, -1.0), 0.1, 1000.0);
  b.add_point(hanging, Vector3d::Zero(), "BLEUx");
  b.add_law("iqsc0", IqsClb{0.3});
  b.add_law("wire1", ElasticWire{2000.0, 0.0});
  b.see("SPHER", "BLEUx", "iqsc0", "DNLYC", "VERTx", 0.01);
  b.see("PT3Dx", "ANCRx", "wire1", "PT3Dx", "BLEUx", 2.0);
  SceneRun r{b.build(), {}};
  r.state.h = kH;
  for (int i = 0; i < 5; ++i) step_3d(r.scene, r.state, test::converged_nlgs_options(10));
  ASSERT_EQ(r.state.contacts.size(), 2u);
  const std::string text = grammar::write_vloc_rloc(vloc_rloc_file_3d(r.scene, r.state));
  EXPECT_NE(text.find("$icdan  PTPT3"), std::string::npos) << text;
  EXPECT_NE(text.find("$icdan  SPDCx"), std::string::npos) << text;
  EXPECT_NE(text.find("gapREF"), std::string::npos) << text;
  const grammar::VlocRlocFile back = parse_vloc(text);
  EXPECT_EQ(grammar::write_vloc_rloc(back), text);
  const WarmStart3D warm_start = warm_start_3d(back, r.scene, kH);
  const std::vector<Interaction3D>& warm = warm_start.interactions;
  ASSERT_EQ(warm.size(), 2u);
  for (std::size_t k = 0; k < warm.size(); ++k) {
    EXPECT_EQ(warm[k].family, r.state.contacts[k].family);
    EXPECT_EQ(warm[k].candidate, r.state.contacts[k].candidate);
    EXPECT_EQ(warm[k].antagonist, r.state.contacts[k].antagonist);
    EXPECT_EQ(warm[k].status, r.state.contacts[k].status);
    for (int d = 0; d < 3; ++d) expect_close(r.state.contacts[k].r(d), warm[k].r(d), "r");
  }
}

// Two links of one pair (directly and across a periodic side: a 0.5 m period, points 0.25 m apart
// both ways) with different reactions: written, read back and stored, each reaction goes back to
// its own link, in the order detection numbers them (PointLink3D::pair_rank, the warm-start key).
TEST(StateFiles3D, DuplicateLinksOfOnePairWarmStartInTheirOrder) {
  SceneBuilder3D b;
  b.add_point(b.add_sphere(Vector3d(0.2, 0.0, 0.0), 0.05, 1000.0), Vector3d::Zero(), "BLEUx");
  b.add_point(b.add_sphere(Vector3d(0.45, 0.0, 0.0), 0.05, 1000.0), Vector3d::Zero(), "BLEUx");
  b.add_law("rod01", ElasticRod{1000.0, 0.0});
  b.see("PT3Dx", "BLEUx", "rod01", "PT3Dx", "BLEUx", 0.3);
  b.set_gravity(Vector3d::Zero());
  SceneRun r{b.build(), {}};
  r.scene.x_period = 0.5;
  r.scene.point_links = link_points_3d(r.scene);
  ASSERT_EQ(r.scene.point_links.size(), 2u);
  r.state.h = kH;
  step_3d(r.scene, r.state, test::converged_nlgs_options(10));
  ASSERT_EQ(r.state.contacts.size(), 2u);
  r.state.contacts[0].r = Vector3d(0.0, 1.0, 0.0);
  r.state.contacts[1].r = Vector3d(0.0, -2.0, 0.0);
  EXPECT_EQ(r.state.contacts[1].vertex, 1);
  const grammar::VlocRlocFile back =
      parse_vloc(grammar::write_vloc_rloc(vloc_rloc_file_3d(r.scene, r.state)));
  const WarmStart3D warm_start = warm_start_3d(back, r.scene, kH);
  const std::vector<Interaction3D>& warm = warm_start.interactions;
  ASSERT_EQ(warm.size(), 2u);
  EXPECT_EQ(warm[0].vertex, 0);
  EXPECT_EQ(warm[1].vertex, 1);
  store_interactions(r.state, warm, warm_start.law_states);
  select_prox_tactors(r.scene, r.state);
  recup_rloc(r.state);
  ASSERT_EQ(r.state.contacts.size(), 2u);
  expect_close(r.state.contacts[0].r(1), 1.0, "direct link");
  expect_close(r.state.contacts[1].r(1), -2.0, "link across the side");
}

}  // namespace
}  // namespace lmgc::solver
