#pragma once
// A frictional contact problem in local form, u = W r + q with Coulomb's law per contact
// (fc3d/FORMAT.md §1.1): the Delassus operator W stored as Dim×Dim blocks in compressed block
// rows, the free velocity q and one friction coefficient per contact. Local vectors are ordered
// normal first, (n, t[, s]), as in FCLIB.
#include <Eigen/Core>
#include <span>
#include <vector>

namespace lmgc::solver {

template <int Dim>
struct FrictionalContactProblem {
  using Block = Eigen::Matrix<double, Dim, Dim>;
  using Local = Eigen::Matrix<double, Dim, 1>;

  int contact_count = 0;
  std::vector<int> row_start;  // contact_count + 1 offsets into column/blocks
  std::vector<int> column;     // block column (contact index) of each stored block
  std::vector<Block> blocks;
  std::vector<int> diagonal;  // index of W_aa in blocks, -1 when the row has none
  Eigen::VectorXd q;          // Dim × contact_count
  Eigen::VectorXd mu;         // contact_count
};

// Builds the block structure from scalar compressed rows (0-based). Entries of a row may come in
// any order; duplicates are summed. Throws std::invalid_argument on an index out of range.
template <int Dim>
FrictionalContactProblem<Dim> problem_from_scalar_rows(int size, std::span<const int> row_pointer,
                                                       std::span<const int> column_index,
                                                       std::span<const double> value, Eigen::VectorXd q,
                                                       Eigen::VectorXd mu);

// W r.
template <int Dim>
Eigen::VectorXd apply_delassus(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r);

// F_a(r) = r_a - P_K(r_a - u_a - mu_a |u_T,a| e_n) of one contact (fc3d/FORMAT.md §3).
template <int Dim>
Eigen::Matrix<double, Dim, 1> natural_map(const Eigen::Matrix<double, Dim, 1>& r,
                                          const Eigen::Matrix<double, Dim, 1>& u, double mu);

// sqrt(sum_a |F_a(r)|^2) / |q| — the error every run reports (fc3d/FORMAT.md §3, measure 1).
template <int Dim>
double natural_map_error(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r);
// The same with u = W r + q already computed (bit for bit the same value).
template <int Dim>
double natural_map_error(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r,
                         const Eigen::VectorXd& u);

}  // namespace lmgc::solver
