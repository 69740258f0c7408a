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
#include <Eigen/LU>
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
  // pattern_slack: how many contacts the sparse LU's pattern may hold per active contact before it
  // is cut down to them (see build_pattern); infinity keeps the whole system in the LU.
  static constexpr double kDefaultPatternSlack = 1.5;
  explicit AlartCurnierNewton(const FrictionalContactProblem<Dim>& problem,
                              double pattern_slack = kDefaultPatternSlack);
  // One Newton step from r (updated in place). Successive calls share the line search's memory of
  // recent merits, so r must not be changed between them (start a new object after sweeps).
  NewtonStepReport step(Eigen::VectorXd& r);
  // u = W r + q for the r the last step returned, when that step progressed.
  const Eigen::VectorXd& velocity() const { return u_; }

 private:
  using Block = Eigen::Matrix<double, Dim, Dim>;
  const FrictionalContactProblem<Dim>& problem_;
  double pattern_slack_;
  Eigen::VectorXd rho_n_, rho_t_;
  std::vector<double> recent_merits_;  // at most kNonmonotoneMemory, oldest first
  Eigen::VectorXd u_;
  bool u_current_ = false;  // u_ = W r + q for the r the last step returned
  // phi's derivatives of the current step: J_ab = delta_ab A_a + B_a W_ab.
  std::vector<Block> A_, B_;
  // A contact whose B is zero (open: phi_a = r_a) has the row J_a = [0 … A_a … 0]: its step is
  // -A_a⁻¹ phi_a, known without the others. The sparse LU solves for the pattern's contacts, a set
  // that holds every active one (see build_pattern); the open ones outside it are solved alone. Near a
  // solution most contacts of a granular problem are open (Confeti-ex13: 67 of 107).
  std::vector<char> open_;
  std::vector<int> pattern_index_;  // position of each contact in the LU's system, -1 if left out
  int pattern_size_ = 0;            // contacts in the LU's system
  bool pattern_built_ = false;
  // W's blocks by block column: the row contact and block index of each, rows in the ordering's
  // order, with a block index of -1 where W_bb is missing (the diagonal is always in the pattern).
  std::vector<int> column_start_, column_row_, column_block_;
  // A fill-reducing ordering of the contacts (COLAMD), computed once on W's block pattern. The LU's
  // system is cut out of the whole one with its rows and columns in this order, so a new pattern
  // costs one pass over W's blocks, not an ordering. For a symmetric pattern such as a Delassus operator's, a
  // principal submatrix eliminated in the induced order fills in no more than the whole system.
  std::vector<int> ordered_contacts_;
  // The pattern's system.
  Eigen::SparseMatrix<double> jacobian_;
  std::vector<int> block_entry_;     // value index of entry (i, j) of blocks[k] in the pattern
  std::vector<int> diagonal_entry_;  // value index of the diagonal entry of each unknown
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::NaturalOrdering<int>> lu_;
  void build_pattern(int active);
  // ½|phi(r)|², and u = W r + q on the way.
  double merit(const Eigen::VectorXd& r, Eigen::VectorXd& u) const;
};

}  // namespace lmgc::solver
