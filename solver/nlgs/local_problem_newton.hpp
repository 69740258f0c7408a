#pragma once
// Semismooth Newton on the Alart–Curnier map of a whole frictional contact problem, with a
// backtracking line search on ½|phi|² (Alart & Curnier 1991; Christensen & Pang 1998). Gauss–Seidel
// stalls on stacks and piles, where information must cross many contacts per sweep; Newton couples
// them all in one sparse linear solve (local_problem_nlgs.hpp decides when).
//
// The line search is non-monotone (Grippo, Lampariello & Lucidi 1986): a step is accepted when it
// lowers the merit below the largest of the last kNonmonotoneMemory merits, not below the current one.
// On piles and granular flows (RockPile, spheres-in-a-box, the FC2D granular flows) a monotone search
// crawls along the kinks of the merit with steps of 1e-4 or less and never finishes; allowed to rise
// for a few steps, the iterates leave the kink and Newton converges.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <vector>

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
  // One Newton step from r (updated in place). Successive calls share the line search's memory of
  // recent merits, so r must not be changed between them (start a new object after sweeps).
  NewtonStepReport step(Eigen::VectorXd& r);

 private:
  const FrictionalContactProblem<Dim>& problem_;
  Eigen::VectorXd rho_n_, rho_t_;
  std::vector<double> recent_merits_;  // at most kNonmonotoneMemory, oldest first
  // The Jacobian keeps one sparsity pattern (every block of W, and the diagonal) for the object's
  // life, so the LU's fill-reducing ordering is computed once: on the FC2D granular flows the ordering
  // was a fifth of the time of a step.
  Eigen::SparseMatrix<double> jacobian_;
  std::vector<int> block_entry_;     // value index of entry (i, j) of blocks[k]: Dim*Dim*k + Dim*i + j
  std::vector<int> diagonal_entry_;  // value index of the diagonal entry of each row
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  double merit(const Eigen::VectorXd& r) const;
};

}  // namespace lmgc::solver
