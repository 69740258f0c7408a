#pragma once
// NLGS over the interactions of a 2D scene where contacts touch meshes (CLALp, CLJCx, PLALp, DKALp), the
// rigid pairs of the scene included, as LMGC90's Stored_Delassus_Loops solves them
// (docs/lmgc90-facts/mailx-2d-contact.md §8): a reaction on a mesh moves every node of it, so every
// two contacts that share a body that moves are coupled by their block W_ij = H_iᵀ A H_j, with A the
// body's response to an impulse (M⁻¹ for a rigid body, K̂⁻¹ condensed on the contactor nodes for a
// mesh: DeformableBodies::contact_compliance). A sweep solves contact i's law for the local free
// velocity v_free_i + Σ_j≠i W_ij r_j, with the others' reactions as they stand.
//
// The rigid NLGS (nlgs_2d.hpp) keeps compact per-contact records and injects each reaction into the
// two bodies' velocities; with a mesh on a side, the velocity of a contact depends on every reaction
// on that mesh, hence the stored blocks. The laws, the checks (numerics.md §4.1), the post sweep and
// the end of the step are the same as there.
#include <span>

#include "solver/model/interaction_2d.hpp"
#include "solver/model/large_array.hpp"
#include "solver/model/scene_2d.hpp"
#include "solver/nlgs/nlgs_check.hpp"
#include "solver/nlgs/quick_scramble.hpp"

namespace lmgc::solver {

// Solves, then sets the rigid bodies' velocities and impulses (V = V_free + M⁻¹ H r) and the meshes'
// contact impulses (DeformableBodies states' contact_impulse: ComputeDof turns them into velocities).
NlgsResult solve_nlgs_coupled_2d(Scene2D& scene, LargeArray<Interaction2D>& contacts,
                                 std::span<LawState2D> law_states, const LawStep& step,
                                 const NlgsOptions& options, QuickScramble& scramble);

}  // namespace lmgc::solver
