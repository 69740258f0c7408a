#pragma once
// The NLGS parameters of a run (LMGC90's ExSolver and nlgs_* calls, COMMAND.DAT's NLGS keywords).
#include <cstddef>
#include <cstdint>

namespace lmgc::run {

enum class NlgsNorm { quad, quad_normal, maxm, qm16 };  // 'Quad ', 'QuaN ', 'Maxm ', 'QM/16'
enum class NlgsStorage { exchange_local_global, stored_delassus_loops };

struct NlgsOptions {
  NlgsStorage storage = NlgsStorage::stored_delassus_loops;
  NlgsNorm norm = NlgsNorm::quad;
  double tolerance = 1.666e-4;
  double relax = 1.0;
  int gs_it1 = 50;   // sweeps between two convergence checks
  int gs_it2 = 500;  // maximum number of checks
  bool quick_scramble = false;
  std::uint64_t scramble_seed = 1;  // quick_scramble.hpp
  // 2D: plain updates four at a time where the processor has AVX2 (sweep_group_2d.hpp), the same
  // iterates bit for bit; false runs every update alone (tests compare both).
  bool vector_sweeps = true;
  // 2D: from this many contacts up, the sweeps that run no groups visit only the contacts their
  // open-contact schedules make due, found in bitmaps (open_contact_visits.hpp), instead of walking
  // every contact and branching on its schedule. The same iterates bit for bit (tests compare both:
  // 0 always, SIZE_MAX never). Below it the walk is as fast or faster: the branch predictor learns
  // a short list's pattern, repeated at every sweep.
  std::size_t due_visits_from = 16384;
  // 3D: nlgs_3D_DiagonalResolution — each contact solved with the diagonal of its block only (its
  // own off-diagonal couplings kept at the previous iterate), then projected on the Coulomb cone.
  bool diagonal_resolution = false;
  // Extra stopping rule of ours: stop when the natural-map residual ÷ ‖q‖ is below this (0 = off).
  double residual_target = 0.0;
};

}  // namespace lmgc::run
