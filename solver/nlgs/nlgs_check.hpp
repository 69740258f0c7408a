#pragma once
// What both NLGS (2D and 3D) share: LMGC90's convergence check of a sweep
// (numerics.md §4.1: sums over the contacts → normalised norms → the test of the chosen norm),
// and the result of a solve.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "run/nlgs_options.hpp"
#include "solver/model/contact_status.hpp"

namespace lmgc::solver {

// The options live with the other run parameters (run/nlgs_options.hpp).
using run::NlgsNorm;
using run::NlgsOptions;
using run::NlgsStorage;

// LMGC90's check quantities (numerics.md §4.1), normalised by the tolerance.
struct NlgsNorms {
  double mean_dvor = 0.0;  // MeanDVoR
  double quad_dv = 0.0;    // QuadDV
  double quad_dvr = 0.0;   // QuadDVR
  double maxm_dv = 0.0;    // MaxmDV
  double maxm_dvr = 0.0;   // MaxmDVR
  double quad_wr = 0.0;    // QuadWR
};

struct NlgsResult {
  int iterations = 0;  // sweeps done, as LMGC90 counts them (gs_it1 per block)
  // Of those, the sweeps left out because the iterates stood still: every contact's local solve
  // returned its reaction unchanged, so the rest of the block would not change a bit.
  int sweeps_skipped = 0;
  bool converged = false;
  bool diverged = false;  // NaN
  NlgsNorms norms;
  // Solver-independent error: natural-map residual of the local problems (fc3d/FORMAT.md §3),
  // absolute and divided by ‖q‖ (q = free local velocities of all interactions).
  double residual_absolute = 0.0;
  double residual_relative = 0.0;
  double free_velocity_norm = 0.0;
  std::size_t active = 0;  // interactions with a non-zero reaction
  // The statuses of the last check's local solves by nature (LMGC90's Nhover, Nstick, Nslide: DRY
  // CONTACT NATURE); a contact forecast inactive counts as hovering.
  std::size_t hover = 0, stick = 0, slide = 0;
  void count_nature(StatusNature nature) {
    hover += nature == StatusNature::hover;
    stick += nature == StatusNature::stick;
    slide += nature == StatusNature::slide;
  }
  double seconds = 0.0;  // wall time of the solve (set by the solve_contacts stage)
  // Wall time of the blocks of sweeps alone (quick scramble included; set-up, checks and the post
  // pass excluded): what LMGC90's "[NLGS2] iter" / "[NLGS3] iter" timer measures (wrap_nlgs.f90),
  // so that sweep rates compare like with like.
  double sweep_seconds = 0.0;
  // The 3D Signorini–Coulomb local solves run (solve_signorini_coulomb_3d from the sweeps, the test
  // that they stand still and the checks; nlgs_3d.cpp; the diagonal variant and the laws' own forms
  // are not counted): the work of a 3D step, which a state near convergence cuts by skipping the rest
  // of its blocks and by passing open contacts by. 0 in 2D.
  std::int64_t local_solves = 0;
};

// The sums of one check pass over the contacts (numerics.md §4.1); `active` counts the contacts
// whose mean reaction R̄ is not zero.
struct NlgsCheckSums {
  double dvdv = 0, max_dvdv = 0, dvdvrr = 0, max_dvdvrr = 0, dvor = 0, wrr = 0, wrwr = 0;
  double active = 0;
  // One contact's terms, as each dimension's check forms them from its two reactions R (current)
  // and R' (the check's solve), their mean R̄ and ΔV = W (R − R'): |ΔV|², |ΔV|² |R̄|², R̄·ΔV, the
  // mean of R·WR and of |WR|² over the two. The 2D and 3D NLGS and their checks sum here.
  void add(double dvdv_term, double dvdvrr_term, double dvor_term, double wrr_term, double wrwr_term) {
    dvdv += dvdv_term;
    max_dvdv = std::max(max_dvdv, dvdv_term);
    dvdvrr += dvdvrr_term;
    max_dvdvrr = std::max(max_dvdvrr, dvdvrr_term);
    dvor += dvor_term;
    wrr += wrr_term;
    wrwr += wrwr_term;
  }
};

// LMGC90's norms from the sums, divided by the tolerance (0.111e-11 each when nothing is active).
NlgsNorms nlgs_norms(const NlgsCheckSums& sums, double tolerance);

// The test of `norm` on the normalised norms: 'Quad '/'QuaN ', 'Maxm ' or 'QM/16'.
bool nlgs_check_passes(NlgsNorm norm, const NlgsNorms& norms);

}  // namespace lmgc::solver
