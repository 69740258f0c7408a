// The 2D warm start between steps (solver/integrator/step_2d recup_rloc): each interaction takes the
// reaction, status and internals of the previous step's interaction with its key (family,
// candidate, antagonist, candidate vertex), and a PLPLx pair whose roles turned over (two parallel
// faces) those of the previous point at the same place, with r_t and a cohesive jump turned over.
#include <gtest/gtest.h>

#include "solver/integrator/step_2d.hpp"

namespace lmgc::solver {
namespace {

Interaction2D plplx(int candidate, int antagonist, int vertex, Eigen::Vector2d point) {
  Interaction2D c;
  c.family = PairFamily2D::PLPLx;
  c.candidate = candidate;
  c.antagonist = antagonist;
  c.candidate_vertex = vertex;
  c.point = point;
  return c;
}

TEST(RecupRloc2D, SameKeyTakesTheReactionStatusAndInternals) {
  RunState2D state;
  Interaction2D p = plplx(0, 1, 2, Eigen::Vector2d(1.0, 0.0));
  p.r = Eigen::Vector2d(0.1, 2.0);
  p.status = ContactStatus::Cstck;
  state.previous = {p};
  state.previous_law_states = {LawState2D{{0.0, 0.0, 0.0, 1.0, 0.0, 0.0}}};
  state.contacts = {plplx(0, 1, 2, Eigen::Vector2d(1.0, 0.0)), plplx(0, 1, 3, Eigen::Vector2d(1.0, 1.0))};
  state.law_states.resize(2);  // a scene whose laws have internals: as detection leaves them, 0
  recup_rloc(state);
  EXPECT_EQ(state.contacts[0].r, p.r);
  EXPECT_EQ(state.contacts[0].status_begin, ContactStatus::Cstck);
  EXPECT_EQ(state.law_states[0].internal[3], 1.0);
  EXPECT_EQ(state.contacts[1].r, Eigen::Vector2d::Zero());  // another vertex: a new contact
  EXPECT_EQ(state.law_states[1].internal[3], 0.0);
  EXPECT_EQ(state.contacts[1].status_begin, ContactStatus::nknow);
}

TEST(RecupRloc2D, SwappedFaceAgainstFacePairMatchesByPositionAndTurnsTangentialOver) {
  RunState2D state;
  // Previous step: polygon 1's vertices 2 and 3 on polygon 0's face, cohesive (β = 1, δt = 0.01).
  Interaction2D p1 = plplx(1, 0, 2, Eigen::Vector2d(0.0, 0.0)),
                p2 = plplx(1, 0, 3, Eigen::Vector2d(1.0, 0.0));
  for (Interaction2D* p : {&p1, &p2}) {
    p->r = Eigen::Vector2d(0.2, 3.0);
    p->status = ContactStatus::Cstck;
    p->cohesive = true;
  }
  p2.r(1) = 4.0;
  state.previous = {p1, p2};
  const LawState2D cohesive{{0.0, 0.01, 0.0, 1.0, 0.0, 0.0}};
  state.previous_law_states = {cohesive, cohesive};
  // This step: polygon 0's vertices 1 and 4 on polygon 1's face, at the same two places (to 1e-5).
  state.contacts = {plplx(0, 1, 1, Eigen::Vector2d(1.0, 1e-5)), plplx(0, 1, 4, Eigen::Vector2d(1e-5, 0.0)),
                    plplx(0, 1, 5, Eigen::Vector2d(0.5, 0.0))};
  state.law_states.resize(3);
  recup_rloc(state);
  EXPECT_EQ(state.contacts[0].r, Eigen::Vector2d(-0.2, 4.0));  // p2's, r_t turned over
  EXPECT_EQ(state.law_states[0].internal[1], -0.01);
  EXPECT_EQ(state.law_states[0].internal[3], 1.0);
  EXPECT_EQ(state.contacts[0].status_begin, ContactStatus::Cstck);
  EXPECT_EQ(state.contacts[1].r, Eigen::Vector2d(-0.2, 3.0));       // p1's
  EXPECT_EQ(state.contacts[2].status_begin, ContactStatus::nknow);  // between the two: new
}

// stock_rloc stores the step's list in place (the next detection swaps it into `previous`): a warm
// start with no detection in between finds each interaction its own previous one, as a copy would.
TEST(RecupRloc2D, AfterStockWithoutDetectionEachInteractionIsItsOwnPrevious) {
  RunState2D state;
  Interaction2D p = plplx(0, 1, 2, Eigen::Vector2d(1.0, 0.0));
  p.r = Eigen::Vector2d(0.1, 2.0);
  p.status = ContactStatus::Cstck;
  p.status_begin = ContactStatus::nknow;
  state.previous = {plplx(0, 1, 2, Eigen::Vector2d(1.0, 0.0))};  // an older list, superseded
  state.previous_law_states = {LawState2D{}};
  state.contacts = {p};
  state.law_states = {LawState2D{{0.0, 0.0, 0.0, 1.0, 0.0, 0.0}}};
  stock_rloc(state);
  recup_rloc(state);
  EXPECT_EQ(state.contacts[0].r, p.r);
  EXPECT_EQ(state.contacts[0].status_begin, ContactStatus::Cstck);
  EXPECT_EQ(state.contacts[0].status, ContactStatus::Cstck);
  EXPECT_EQ(state.law_states[0].internal[3], 1.0);
  // A warm start's list stored afterwards replaces it.
  const std::vector<Interaction2D> warm_start = {plplx(0, 1, 2, Eigen::Vector2d(1.0, 0.0))};
  store_interactions(state, warm_start, std::vector<LawState2D>(1));
  recup_rloc(state);
  EXPECT_EQ(state.contacts[0].r, Eigen::Vector2d::Zero());
  EXPECT_EQ(state.contacts[0].status_begin, ContactStatus::nknow);
  EXPECT_EQ(state.law_states[0].internal[3], 0.0);  // the warm start's
}

}  // namespace
}  // namespace lmgc::solver
