#pragma once
// Semismooth Newton on the Alart–Curnier map of a whole frictional contact problem, with a
// backtracking line search on ½|phi|² (Alart & Curnier 1991; Christensen & Pang 1998). Gauss–Seidel
// stalls on stacks and piles, where information must cross many contacts per sweep; Newton couples
// them all in one sparse linear solve. Used to finish what NLGS started (local_problem_nlgs.hpp).
#include <Eigen/Core>

#include "solver/nlgs/frictional_contact_problem.hpp"

namespace lmgc::solver {

struct NewtonStepReport {
  bool progressed = false;  // the line search accepted a step
  double merit = 0.0;       // ½|phi|² after the step
};

template <int Dim>
class AlartCurnierNewton {
 public:
  explicit AlartCurnierNewton(const FrictionalContactProblem<Dim>& problem);
  // One Newton step from r (updated in place).
  NewtonStepReport step(Eigen::VectorXd& r);

 private:
  const FrictionalContactProblem<Dim>& problem_;
  Eigen::VectorXd rho_n_, rho_t_;
  double merit(const Eigen::VectorXd& r) const;
};

}  // namespace lmgc::solver
