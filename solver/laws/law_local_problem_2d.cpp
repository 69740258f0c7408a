// docs/lmgc90-facts/contact-laws.md §2 (derived Signorini–Coulomb), §3.1-3.4 (laws one by one).
#include "solver/laws/law_local_problem_2d.hpp"

namespace lmgc::solver {

void prepare_local_problem_2d(const ContactLaw& law, LocalProblem2D& c, const LawStep& step) {
  c.WW = c.W;
  c.covfree.setZero();
  c.correction.setZero();
  c.cohesive_slope.setZero();
  c.inactive = false;
  c.mu = 0.0;
  prepare_law(law, c, step);  // each law's own file (solver/laws/*.hpp)
  // Guard of the tangential term for degenerate blocks (§2).
  if (c.WW(0, 0) <= 1e-6 * c.WW(1, 1)) c.WW(0, 0) = 1e-6 * c.WW(1, 1);
}

void finish_step_2d(const ContactLaw& law, Interaction2D& c, LawState2D& state, double h, double time) {
  finish_law(law, c, state, LawStep{h, time, false});
}

}  // namespace lmgc::solver
