#include "solver/nlgs/frictional_contact_problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/nlgs/local_solver_2d.hpp"
#include "solver/nlgs/local_solver_3d.hpp"

namespace lmgc::solver {

template <int Dim>
FrictionalContactProblem<Dim> problem_from_scalar_rows(int size, std::span<const int> row_pointer,
                                                       std::span<const int> column_index,
                                                       std::span<const double> value, Eigen::VectorXd q,
                                                       Eigen::VectorXd mu) {
  if (size < 0 || size % Dim != 0)
    throw std::invalid_argument("matrix size is not a multiple of the dimension");
  if (row_pointer.size() != static_cast<std::size_t>(size) + 1)
    throw std::invalid_argument("row pointer array has the wrong length");
  if (q.size() != size) throw std::invalid_argument("q does not match the size of W");
  const int contacts = size / Dim;
  if (mu.size() != contacts) throw std::invalid_argument("mu does not have one value per contact");
  FrictionalContactProblem<Dim> problem;
  problem.contact_count = contacts;
  problem.q = std::move(q);
  problem.mu = std::move(mu);
  problem.row_start.assign(contacts + 1, 0);
  problem.diagonal.assign(contacts, -1);
  std::vector<int> slot(contacts, -1);  // block column -> position in this block row
  for (int a = 0; a < contacts; ++a) {
    const int first_block = static_cast<int>(problem.blocks.size());
    for (int row = a * Dim; row < (a + 1) * Dim; ++row) {
      const int begin = row_pointer[row], end = row_pointer[row + 1];
      if (begin < 0 || end < begin || static_cast<std::size_t>(end) > column_index.size() ||
          static_cast<std::size_t>(end) > value.size())
        throw std::invalid_argument("row pointer out of range");
      for (int k = begin; k < end; ++k) {
        const int col = column_index[k];
        if (col < 0 || col >= size) throw std::invalid_argument("column index out of range");
        const int b = col / Dim;
        if (slot[b] < 0) {
          slot[b] = static_cast<int>(problem.blocks.size());
          problem.blocks.push_back(FrictionalContactProblem<Dim>::Block::Zero());
          problem.column.push_back(b);
        }
        problem.blocks[slot[b]](row - a * Dim, col - b * Dim) += value[k];
      }
    }
    // Sort the row's blocks by column so that sweeps read memory in order.
    const int last_block = static_cast<int>(problem.blocks.size());
    std::vector<int> order(last_block - first_block);
    for (int k = 0; k < last_block - first_block; ++k) order[k] = first_block + k;
    std::sort(order.begin(), order.end(),
              [&](int x, int y) { return problem.column[x] < problem.column[y]; });
    std::vector<typename FrictionalContactProblem<Dim>::Block> sorted_blocks;
    std::vector<int> sorted_columns;
    for (int k : order) {
      sorted_blocks.push_back(problem.blocks[k]);
      sorted_columns.push_back(problem.column[k]);
      slot[problem.column[k]] = -1;
    }
    for (int k = 0; k < last_block - first_block; ++k) {
      problem.blocks[first_block + k] = sorted_blocks[k];
      problem.column[first_block + k] = sorted_columns[k];
      if (sorted_columns[k] == a) problem.diagonal[a] = first_block + k;
    }
    problem.row_start[a + 1] = last_block;
  }
  return problem;
}

template <int Dim>
Eigen::VectorXd apply_delassus(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.q.size());
  for (int a = 0; a < problem.contact_count; ++a) {
    Eigen::Matrix<double, Dim, 1> sum = Eigen::Matrix<double, Dim, 1>::Zero();
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
      sum.noalias() += problem.blocks[k] * r.template segment<Dim>(Dim * problem.column[k]);
    u.template segment<Dim>(Dim * a) = sum;
  }
  return u;
}

template <>
Eigen::Matrix<double, 3, 1> natural_map<3>(const Eigen::Vector3d& r, const Eigen::Vector3d& u, double mu) {
  return natural_map_3d(r, u, mu);
}

template <>
Eigen::Matrix<double, 2, 1> natural_map<2>(const Eigen::Vector2d& r, const Eigen::Vector2d& u, double mu) {
  // FCLIB's components are (n, t); the 2D NLGS's map takes (t, n).
  const Eigen::Vector2d f = natural_map_2d(Eigen::Vector2d(r(1), r(0)), Eigen::Vector2d(u(1), u(0)), mu);
  return Eigen::Vector2d(f(1), f(0));
}

template <int Dim>
double natural_map_error(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r) {
  return natural_map_error(problem, r, apply_delassus(problem, r) + problem.q);
}

template <int Dim>
double natural_map_error(const FrictionalContactProblem<Dim>& problem, const Eigen::VectorXd& r,
                         const Eigen::VectorXd& u) {
  double sum = 0.0;
  for (int a = 0; a < problem.contact_count; ++a)
    sum += natural_map<Dim>(r.template segment<Dim>(Dim * a), u.template segment<Dim>(Dim * a), problem.mu(a))
               .squaredNorm();
  const double q_norm = problem.q.norm();
  return std::sqrt(sum) / (q_norm > 0.0 ? q_norm : 1.0);
}

template FrictionalContactProblem<2> problem_from_scalar_rows<2>(int, std::span<const int>,
                                                                 std::span<const int>,
                                                                 std::span<const double>, Eigen::VectorXd,
                                                                 Eigen::VectorXd);
template FrictionalContactProblem<3> problem_from_scalar_rows<3>(int, std::span<const int>,
                                                                 std::span<const int>,
                                                                 std::span<const double>, Eigen::VectorXd,
                                                                 Eigen::VectorXd);
template Eigen::VectorXd apply_delassus<2>(const FrictionalContactProblem<2>&, const Eigen::VectorXd&);
template Eigen::VectorXd apply_delassus<3>(const FrictionalContactProblem<3>&, const Eigen::VectorXd&);
template double natural_map_error<2>(const FrictionalContactProblem<2>&, const Eigen::VectorXd&);
template double natural_map_error<3>(const FrictionalContactProblem<3>&, const Eigen::VectorXd&);
template double natural_map_error<2>(const FrictionalContactProblem<2>&, const Eigen::VectorXd&,
                                     const Eigen::VectorXd&);
template double natural_map_error<3>(const FrictionalContactProblem<3>&, const Eigen::VectorXd&,
                                     const Eigen::VectorXd&);

}  // namespace lmgc::solver
