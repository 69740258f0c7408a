// Property of the 3D warm start (step_3d recup_rloc): whatever order the contacts come in, each
// takes the reaction of the first stored entry of its pair that matches it (PRPLx by candidate
// vertex, PRPRx by place), as a search of the whole stored list finds it. recup_rloc looks among the
// stored entries of the contact's candidate only; that lookup must agree with the search.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <span>
#include <vector>

#include "solver/integrator/step_3d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector3d;

Interaction3D random_interaction() {
  Interaction3D c;
  c.family = *rc::gen::element(PairFamily3D::SPSPx, PairFamily3D::PRPRx, PairFamily3D::PRPLx);
  c.candidate = *rc::gen::inRange(0, 4);
  c.antagonist = *rc::gen::inRange(0, 4);
  c.vertex = c.family == PairFamily3D::PRPLx ? *rc::gen::inRange(1, 3) : 0;
  // PRPRx points of a pair are told apart by place: two places 1 apart, far beyond the 1e-3 match.
  c.candidate_point = Vector3d(*rc::gen::inRange(0, 2), 0.0, 0.0);
  return c;
}

// The stored entry a contact should take: the first of its pair, in the stored list's order, that
// has its vertex and (PRPRx) lies within 1e-3 of its point; null when none.
const StoredInteraction3D* first_match(std::span<const StoredInteraction3D> stored, const Interaction3D& c) {
  for (const StoredInteraction3D& p : stored)
    if (p.family == c.family && p.candidate == c.candidate && p.antagonist == c.antagonist &&
        p.vertex == c.vertex &&
        (c.family != PairFamily3D::PRPRx || (p.candidate_point - c.candidate_point).squaredNorm() < 1e-6))
      return &p;
  return nullptr;
}

// With law states (a scene whose laws keep some) the internals come with the reaction; without, the
// stored internals are 0.
RC_GTEST_PROP(RecupRloc3D,
              EveryContactInAnyOrderTakesReactionAndInternalsOfTheFirstMatchingStoredEntryOfItsPair, ()) {
  RunState3D state;
  std::vector<Interaction3D> previous(*rc::gen::inRange<std::size_t>(0, 40));
  for (std::size_t k = 0; k < previous.size(); ++k) {
    previous[k] = random_interaction();
    previous[k].r = Vector3d(0.0, static_cast<double>(k + 1), 0.0);  // tells the entries apart
    previous[k].status = ContactStatus::stick;
  }
  const bool with_law_states = *rc::gen::arbitrary<bool>();
  std::vector<LawState3D> previous_law_states(with_law_states ? previous.size() : 0);
  for (std::size_t k = 0; k < previous_law_states.size(); ++k)
    previous_law_states[k].internal[2] = static_cast<double>(k + 1);
  store_interactions(state, previous, previous_law_states);
  std::vector<Interaction3D> contacts(*rc::gen::inRange<std::size_t>(0, 40));
  for (Interaction3D& c : contacts) c = random_interaction();
  // In key order (as detection lists them), or partly out of it.
  if (*rc::gen::arbitrary<bool>())
    std::stable_sort(contacts.begin(), contacts.end(), [](const Interaction3D& a, const Interaction3D& b) {
      return std::tie(a.family, a.candidate, a.antagonist) < std::tie(b.family, b.candidate, b.antagonist);
    });
  state.contacts.assign(contacts.begin(), contacts.end());
  if (with_law_states) state.law_states.assign(contacts.size(), LawState3D{});
  recup_rloc(state);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const StoredInteraction3D* match = first_match(state.previous, contacts[k]);
    const Interaction3D& c = state.contacts[k];
    RC_ASSERT(c.r == (match ? match->r : Vector3d::Zero()));
    RC_ASSERT(c.status_begin == (match ? ContactStatus::stick : ContactStatus::nknow));
    const std::array<double, 6> none{};
    if (with_law_states)
      RC_ASSERT(state.law_states[k].internal == (match ? match->internal : none));
    else if (match)
      RC_ASSERT(match->internal == none);
  }
}

}  // namespace
}  // namespace lmgc::solver
