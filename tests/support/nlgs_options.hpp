#pragma once
// NLGS options under which the tests' small scenes are solved to convergence, so that what they
// compare is the model's answer and not the solver's stopping point.
#include "solver/nlgs/nlgs_check.hpp"

namespace lmgc::test {

// Quad norm at 1e-10, checked every `gs_it1` sweeps for up to 500 blocks; with a natural-map residual
// target (relative, fc3d/FORMAT.md §3) a block whose residual reaches it passes too (0: none).
inline solver::NlgsOptions converged_nlgs_options(int gs_it1, double residual_target = 0.0) {
  solver::NlgsOptions o;
  o.norm = solver::NlgsNorm::quad;
  o.tolerance = 1e-10;
  o.gs_it1 = gs_it1;
  o.gs_it2 = 500;
  o.residual_target = residual_target;
  return o;
}

}  // namespace lmgc::test
