#pragma once
// Every 2D law reduced to one Signorini–Coulomb problem in auxiliary variables
// (contact-laws.md §2): uu = ufree_loc + covfree + WW rr, r = rr + correction.
// The verbs of the 2D NLGS around its sweeps: prepare (once per step: each law's own `prepare`,
// solver/laws/*.hpp) and finish (end of step: each law's own `finish`). The sweeps and checks solve
// and measure the problem from the terms the set-up extracts (solver/nlgs/nlgs_2d.cpp).
#include <Eigen/Core>

#include "solver/laws/contact_law.hpp"
#include "solver/model/interaction_2d.hpp"

namespace lmgc::solver {

// Sets c.WW, c.covfree, c.correction, c.cohesive_slope, c.mu, c.inactive from c.W, c.gap_begin,
// c.velocity_begin, c.status_begin and the law (contact-laws.md §3). `step`: h and the first-step
// flags (LawStep).
void prepare_local_problem_2d(const ContactLaw& law, LocalProblem2D& c, const LawStep& step);

// End of step: law statuses (wet, Mohr) and internal variables (the interaction's `state`).
void finish_step_2d(const ContactLaw& law, Interaction2D& c, LawState2D& state, double h, double time);

}  // namespace lmgc::solver
