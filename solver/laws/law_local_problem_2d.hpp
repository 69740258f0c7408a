#pragma once
// Every 2D law reduced to one Signorini–Coulomb problem in auxiliary variables
// (contact-laws.md §2): uu = ufree_loc + covfree + WW rr, r = rr + correction.
// The verbs of the 2D NLGS: prepare (once per step: each law's own `prepare`, solver/laws/*.hpp),
// solve (each sweep), residual (checks), finish (end of step: each law's own `finish`).
#include <Eigen/Core>

#include "solver/laws/contact_law.hpp"
#include "solver/model/interaction_2d.hpp"
#include "solver/nlgs/local_solver_2d.hpp"

namespace lmgc::solver {

// Sets c.WW, c.covfree, c.correction, c.cohesive_slope, c.mu, c.inactive from c.W, c.gap_begin,
// c.velocity_begin, c.status_begin and the law (contact-laws.md §3). `step`: h and the first-step
// flags (LawStep).
void prepare_local_problem_2d(const ContactLaw& law, LocalProblem2D& c, const LawStep& step);

// The law's reaction for the current local free velocity (u = ufree_loc + W r), correction included.
LocalSolution2D solve_local_problem_2d(const ContactLaw& law, const LocalProblem2D& c,
                                       const Eigen::Vector2d& ufree_loc);

// Squared residual of the law at (r, ufree_loc): the natural map of the Signorini–Coulomb problem
// in auxiliary variables for Coulomb laws, |uu| for glued dofs, |r| for inactive contacts.
double local_residual_squared_2d(const ContactLaw& law, const LocalProblem2D& c, const Eigen::Vector2d& r,
                                 const Eigen::Vector2d& ufree_loc);

// End of step: law statuses (wet, Mohr) and internal variables.
void finish_step_2d(const ContactLaw& law, Interaction2D& c, double h, double time);

}  // namespace lmgc::solver
