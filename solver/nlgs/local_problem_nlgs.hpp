#pragma once
// Non-linear Gauss–Seidel (Siconos calls it NSGS) on a frictional contact problem given in local
// form (FrictionalContactProblem): sweep the contacts, solve each one exactly with the others'
// reactions frozen, stop on the natural-map error ÷ |q| (fc3d/FORMAT.md §3). By default it opens with
// semismooth Newton phases on the whole problem (local_problem_newton.hpp), then alternates sweeps and
// Newton by measured rate. This is the solver behind `lmgc-fc3d`; the scene NLGS of lmgc-solve works
// on bodies instead of an assembled W, as LMGC90's does.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "solver/nlgs/frictional_contact_problem.hpp"

namespace lmgc::solver {

enum class ContactOrder : unsigned char { natural, shuffled_each_sweep };

struct LocalProblemNlgsOptions {
  double tolerance = 1e-8;  // on the natural-map error ÷ |q|
  int max_sweeps = 100000;
  double max_seconds = 60.0;  // wall-clock cap per problem
  double relax = 1.0;         // r <- relax r_local + (1 - relax) r (docs/lmgc90-facts/contact-laws.md §2.4)
  ContactOrder order = ContactOrder::natural;
  // Open with up to four phases of semismooth Newton (local_problem_newton.hpp) from the given
  // reactions, raced by sweeps on a copy, before the sweeps take over.
  bool newton_first = true;
  // Share of the opening phases' time given to the sweeps that race them on a copy (0: no race).
  double race_share = 0.25;
  int opening_sweeps = 0;  // sweeps of r before the first opening phase (one more before each next)
  // When a block of sweeps stalls, switch to a Newton phase until it stalls in turn, then sweep again.
  bool newton_when_stalled = true;
  int sweeps_per_block = 50;
  int max_newton_steps_per_phase = 1000;
  std::uint64_t seed = 1;
  // Errors whose first crossing time is recorded (e.g. 1e-4, 1e-6, 1e-8).
  std::vector<double> milestones;
};

struct LocalProblemNlgsResult {
  int sweeps = 0;       // sweeps of the returned iterate's line (max_sweeps caps these)
  int race_sweeps = 0;  // sweeps of the race's copy beside the opening Newton phases
  double error = 0.0;   // natural-map error ÷ |q| at the end
  double seconds = 0.0;
  bool converged = false;
  int newton_steps = 0;                   // accepted Newton steps
  int local_failures = 0;                 // local solves that ended above their tolerance (last sweep of r)
  std::vector<double> milestone_seconds;  // -1 where never reached
  std::vector<int> milestone_sweeps;      // sweeps + race_sweeps at that time
};

// Solves from the reactions in `r` (size Dim × contacts; zeros for a cold start).
template <int Dim>
LocalProblemNlgsResult solve_local_problem_nlgs(const FrictionalContactProblem<Dim>& problem,
                                                Eigen::VectorXd& r, const LocalProblemNlgsOptions& options);

}  // namespace lmgc::solver
