#pragma once
// Four plain Signorini–Coulomb updates at once, one per lane of a 256-bit vector (AVX2, chosen at
// run time). The four share no movable body (nlgs_2d.cpp forms them in the wavefront order of
// sweep_wavefront.hpp, whose levels share none), so running them side by side gives each the
// velocities it would have read in turn: the reactions and velocities are the scalar sweep's bit
// for bit. Each lane computes the
// scalar formulas of nlgs_2d.cpp in the same order (no fused multiply-add: the kernel is compiled for
// AVX2 alone), and a lane that cannot take the plain path is left to the scalar update. The scalar
// sweep spends about 175 instructions per update and is bound by what it executes; siloDK_hoperJC's
// updates are nearly all of contacts with a reaction, the ones a group takes.
#include <Eigen/Core>
#include <cstdint>

#include "solver/nlgs/open_contact_visits.hpp"

namespace lmgc::solver {

// The 2D sweeps' reaction record, written by every update: 24 bytes. The status is not kept here:
// the post pass, which solves every contact, gives each its final one.
struct ContactReaction2D {
  double rt = 0, rn = 0;  // impulse
  OpenContactSchedule visits;
};

// The sweep record of four contacts, field by field (lane k: the update at execution position
// position[k]). Only plain contacts (Signorini–Coulomb on W, a zero tangential shift) form groups.
struct alignas(32) SweepGroup2D {
  double nx[4], ny[4];                  // normal; t = (ny, -nx)
  double lever_cd_t[4], lever_cd_n[4];  // candidate's ℓ×t, ℓ×n
  double lever_an_t[4], lever_an_n[4];  // antagonist's
  double wtt[4], wtn[4], wnn[4];        // Delassus block
  double cov_n[4];                      // law shift of the normal free velocity
  double mu[4];
  double inverse_det[4], inverse_forward[4], inverse_backward[4];  // SignoriniCoulombReciprocals2D
  // Each body's inverse mass, translation (the same along x and y: a lane whose body has one of the
  // two driven is left to the scalar update) and rotation: 16 bytes a lane, not 24 for (x, y, ω).
  double inverse_mass_cd[4], inverse_inertia_cd[4], inverse_mass_an[4], inverse_inertia_an[4];
  std::int32_t cd[4], an[4];  // body indices
  std::uint32_t position[4];
  // No tangential law shift: a plain contact's is +0 or -0 (SweepContact2D::zero_shift_t), which only
  // decides the sign of a zero q_t, and no result keeps that sign (sweep_group_2d.cpp).
};
// The sweeps stream the groups from memory on large scenes (nlgs_2d.cpp prefetches them): 640 bytes
// for four updates.
static_assert(sizeof(SweepGroup2D) == 640);

// Whether this processor runs the AVX2 kernel.
bool sweep_groups_available();

// The updates of `group` on `velocity` and `reaction` (indexed by execution position), as the scalar
// sweep (relax = 1 when `relaxed` is false) would make them. Returns the lanes done (bit k: lane k).
// A lane left undone has nothing of its own written: it is without reaction (the open-contact
// schedule decides its visit) or its local solve leaves the plain cases (a singular block, NaN), and
// the caller runs its scalar update, after or before the others (they share no movable body).
int sweep_group_2d(const SweepGroup2D& group, ContactReaction2D* reaction, Eigen::Vector3d* velocity,
                   bool relaxed, double relax, double keep);

}  // namespace lmgc::solver
