#include "solver/nlgs/local_problem_newton.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace lmgc::solver {

namespace {

constexpr int kMaxLineSearchHalvings = 40;
// Merits the non-monotone line search compares with: a monotone search (1) leaves the hardest FCLIB
// problems (RockPile, spheres-in-a-box, fc2d_granularflowonwall_02020) unsolved from r = 0, a shorter
// memory leaves some of them, and a longer one is slower.
constexpr std::size_t kNonmonotoneMemory = 20;
// The LU keeps a diagonal pivot unless it is smaller than this share of its column's largest entry
// (SuperLU's symmetric mode): J's pattern is symmetric, the fill-reducing ordering assumes diagonal
// pivots, and J + shift I has a strong diagonal, so kept diagonal pivots cost fewer instructions
// for the same steps and errors. But RockPile, ill-conditioned, needs accurate pivots: 0.1 solves it as
// reliably as partial pivoting, a smaller threshold does not.
constexpr double kDiagonalPivotThreshold = 0.1;

// phi_a and its derivatives with respect to r_a (A) and u_a (B), normal first:
//   phi_n = r_n - max(0, r_n - rho_n u_n)
//   phi_T = r_T - P_{disc(mu r_n)}(r_T - rho_t u_T)
template <int Dim>
void alart_curnier(const Eigen::Matrix<double, Dim, 1>& r, const Eigen::Matrix<double, Dim, 1>& u, double mu,
                   double rho_n, double rho_t, Eigen::Matrix<double, Dim, 1>& phi,
                   Eigen::Matrix<double, Dim, Dim>* A, Eigen::Matrix<double, Dim, Dim>* B) {
  constexpr int T = Dim - 1;
  if (A) {
    A->setZero();
    B->setZero();
  }
  if (r(0) - rho_n * u(0) > 0.0) {
    phi(0) = rho_n * u(0);
    if (B) (*B)(0, 0) = rho_n;
  } else {
    phi(0) = r(0);
    if (A) (*A)(0, 0) = 1.0;
  }
  const Eigen::Matrix<double, T, 1> z = r.template tail<T>() - rho_t * u.template tail<T>();
  const double radius = mu * std::max(r(0), 0.0);
  const double z_norm = z.norm();
  if (z_norm <= radius || z_norm == 0.0) {
    phi.template tail<T>() = rho_t * u.template tail<T>();
    if (B) B->template bottomRightCorner<T, T>().diagonal().setConstant(rho_t);
  } else {
    const Eigen::Matrix<double, T, 1> direction = z / z_norm;
    phi.template tail<T>() = r.template tail<T>() - radius * direction;
    if (A) {
      const Eigen::Matrix<double, T, T> projector =
          (Eigen::Matrix<double, T, T>::Identity() - direction * direction.transpose()) / z_norm;
      A->template bottomRightCorner<T, T>() = Eigen::Matrix<double, T, T>::Identity() - radius * projector;
      if (r(0) > 0.0) A->template bottomLeftCorner<T, 1>() = -mu * direction;
      B->template bottomRightCorner<T, T>() = radius * rho_t * projector;
    }
  }
}

}  // namespace

template <int Dim>
AlartCurnierNewton<Dim>::AlartCurnierNewton(const FrictionalContactProblem<Dim>& problem,
                                            double pattern_slack)
    : problem_(problem), pattern_slack_(pattern_slack) {
  const int contacts = problem.contact_count;
  rho_n_.resize(contacts);
  rho_t_.resize(contacts);
  for (int a = 0; a < contacts; ++a) {
    const int k = problem.diagonal[a];
    const double wnn = k >= 0 ? problem.blocks[k](0, 0) : 0.0;
    double wtt = 0.0;
    if (k >= 0)
      for (int i = 1; i < Dim; ++i) wtt = std::max(wtt, problem.blocks[k](i, i));
    rho_n_(a) = wnn > 0.0 ? 1.0 / wnn : 1.0;
    rho_t_(a) = wtt > 0.0 ? 1.0 / wtt : rho_n_(a);
  }
  A_.resize(contacts);
  B_.resize(contacts);
  open_.assign(contacts, 0);
  pattern_index_.assign(contacts, -1);
  lu_.isSymmetric(true);
  lu_.setPivotThreshold(kDiagonalPivotThreshold);

  column_start_.assign(contacts + 1, 0);
  for (int a = 0; a < contacts; ++a) {
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
      ++column_start_[problem.column[k] + 1];
    if (problem.diagonal[a] < 0) ++column_start_[a + 1];
  }
  for (int b = 0; b < contacts; ++b) column_start_[b + 1] += column_start_[b];
  column_row_.resize(column_start_[contacts]);
  column_block_.resize(column_start_[contacts]);
  std::vector<int> next(column_start_.begin(), column_start_.end() - 1);
  std::vector<Eigen::Triplet<double>> block_pattern;
  block_pattern.reserve(column_row_.size());
  for (int a = 0; a < contacts; ++a) {
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k) {
      const int b = problem.column[k];
      column_row_[next[b]] = a;
      column_block_[next[b]++] = k;
      block_pattern.emplace_back(a, b, 1.0);
    }
    if (problem.diagonal[a] < 0) {
      column_row_[next[a]] = a;
      column_block_[next[a]++] = -1;
      block_pattern.emplace_back(a, a, 1.0);
    }
  }
  Eigen::SparseMatrix<double> pattern(contacts, contacts);
  pattern.setFromTriplets(block_pattern.begin(), block_pattern.end());
  pattern.makeCompressed();
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> ordering;
  Eigen::COLAMDOrdering<int>()(pattern, ordering);
  ordered_contacts_.resize(contacts);
  for (int b = 0; b < contacts; ++b)
    ordered_contacts_[ordering.size() == contacts ? ordering.indices()(b) : b] = b;
  // Each block column's entries in the ordering's order of their rows, the order of the LU's rows.
  std::vector<int> rank(contacts);
  for (int g = 0; g < contacts; ++g) rank[ordered_contacts_[g]] = g;
  std::vector<std::pair<int, int>> entries;
  for (int b = 0; b < contacts; ++b) {
    entries.clear();
    for (int e = column_start_[b]; e < column_start_[b + 1]; ++e)
      entries.emplace_back(column_row_[e], column_block_[e]);
    std::sort(entries.begin(), entries.end(),
              [&](const auto& x, const auto& y) { return rank[x.first] < rank[y.first]; });
    for (int e = column_start_[b]; e < column_start_[b + 1]; ++e)
      std::tie(column_row_[e], column_block_[e]) = entries[static_cast<std::size_t>(e - column_start_[b])];
  }
}

// The LU's contacts: those of the current pattern (at first, all of them) and the active ones, or the
// active ones alone when that set would hold more than pattern_slack_ times as many. A pattern with a
// few open contacts costs the LU little more (Capsules: its 30 of 286 open contacts in or out, the
// same factorisation time), while cutting it out anew at every step would; a pattern that keeps its
// old contacts is cut out less often while the active set comes and goes.
template <int Dim>
void AlartCurnierNewton<Dim>::build_pattern(int active) {
  const int contacts = problem_.contact_count;
  const auto in_old_pattern = [&](int a) { return !pattern_built_ || pattern_index_[a] >= 0; };
  int union_size = 0;
  for (int a = 0; a < contacts; ++a) union_size += !open_[a] || in_old_pattern(a);
  const bool keep_old = union_size <= pattern_slack_ * active;
  // The pattern's contacts are numbered in the ordering's order: the LU's rows and columns both
  // follow it (P^T J P), so J's diagonal stays on the LU's diagonal.
  pattern_size_ = 0;
  for (const int a : ordered_contacts_)
    pattern_index_[a] = !open_[a] || (keep_old && in_old_pattern(a)) ? pattern_size_++ : -1;
  pattern_built_ = true;

  // Row and column Dim g + i of jacobian_ are unknown i of pattern contact g.
  const int size = Dim * pattern_size_;
  int entries = 0;
  for (int b = 0; b < contacts; ++b)
    if (pattern_index_[b] >= 0)
      for (int e = column_start_[b]; e < column_start_[b + 1]; ++e)
        if (pattern_index_[column_row_[e]] >= 0) entries += column_block_[e] >= 0 ? Dim * Dim : Dim;
  jacobian_.resize(size, size);
  jacobian_.resizeNonZeros(entries);
  int* outer = jacobian_.outerIndexPtr();
  int* inner = jacobian_.innerIndexPtr();
  block_entry_.resize(problem_.blocks.size() * Dim * Dim);  // set for the pattern's blocks only
  diagonal_entry_.resize(size);
  int column = 0, entry = 0;
  outer[0] = 0;
  for (const int b : ordered_contacts_) {
    const int col_contact = pattern_index_[b];
    if (col_contact < 0) continue;
    for (int j = 0; j < Dim; ++j, ++column) {
      for (int e = column_start_[b]; e < column_start_[b + 1]; ++e) {
        const int row_contact = pattern_index_[column_row_[e]];
        if (row_contact < 0) continue;
        const int k = column_block_[e];
        if (k < 0) {  // W_bb missing: the diagonal entry alone
          diagonal_entry_[Dim * row_contact + j] = entry;
          inner[entry++] = Dim * row_contact + j;
          continue;
        }
        for (int i = 0; i < Dim; ++i) {
          if (row_contact == col_contact && i == j) diagonal_entry_[Dim * row_contact + j] = entry;
          block_entry_[Dim * Dim * k + Dim * i + j] = entry;
          inner[entry++] = Dim * row_contact + i;
        }
      }
      outer[column + 1] = entry;
    }
  }
  if (size > 0) lu_.analyzePattern(jacobian_);
}

template <int Dim>
double AlartCurnierNewton<Dim>::merit(const Eigen::VectorXd& r, Eigen::VectorXd& u) const {
  u = apply_delassus(problem_, r) + problem_.q;
  double sum = 0.0;
  Eigen::Matrix<double, Dim, 1> phi;
  for (int a = 0; a < problem_.contact_count; ++a) {
    alart_curnier<Dim>(r.template segment<Dim>(Dim * a), u.template segment<Dim>(Dim * a), problem_.mu(a),
                       rho_n_(a), rho_t_(a), phi, nullptr, nullptr);
    sum += phi.squaredNorm();
  }
  return 0.5 * sum;
}

template <int Dim>
NewtonStepReport AlartCurnierNewton<Dim>::step(Eigen::VectorXd& r) {
  using Local = Eigen::Matrix<double, Dim, 1>;
  const int contacts = problem_.contact_count;
  const int size = Dim * contacts;
  // u = W r + q, as the last accepted line-search trial computed it for this r.
  if (!u_current_) u_ = apply_delassus(problem_, r) + problem_.q;
  u_current_ = false;
  Eigen::VectorXd phi(size);
  int active = 0;
  bool outside = false;  // an active contact is outside the pattern
  for (int a = 0; a < contacts; ++a) {
    Local phi_a;
    alart_curnier<Dim>(r.template segment<Dim>(Dim * a), u_.template segment<Dim>(Dim * a), problem_.mu(a),
                       rho_n_(a), rho_t_(a), phi_a, &A_[a], &B_[a]);
    phi.template segment<Dim>(Dim * a) = phi_a;
    const bool open = B_[a].isZero(0.0);
    open_[a] = open;
    active += !open;
    outside = outside || (!open && pattern_index_[a] < 0);
  }
  const double merit_before = 0.5 * phi.squaredNorm();
  NewtonStepReport report;
  report.merit = merit_before;
  if (merit_before == 0.0) return report;

  // J's blocks go into the pattern's values (every value is written: an open row's blocks are zero
  // but for A_a); the shift's scale is the largest entry of J over W's blocks, as for the whole system.
  if (!pattern_built_ || outside || pattern_size_ > pattern_slack_ * active) build_pattern(active);
  double* values = jacobian_.valuePtr();
  double scale = 0.0;
  for (int a = 0; a < contacts; ++a) {
    const int row = pattern_index_[a];
    if (open_[a] && problem_.diagonal[a] >= 0) scale = std::max(scale, A_[a].cwiseAbs().maxCoeff());
    if (open_[a] && row < 0) continue;
    for (int k = problem_.row_start[a]; k < problem_.row_start[a + 1]; ++k) {
      Block J = open_[a] ? Block::Zero() : Block(B_[a] * problem_.blocks[k]);
      if (problem_.column[k] == a) J += A_[a];
      if (!open_[a]) scale = std::max(scale, J.cwiseAbs().maxCoeff());
      if (row < 0 || pattern_index_[problem_.column[k]] < 0) continue;
      const int* slot = &block_entry_[Dim * Dim * k];
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) values[slot[Dim * i + j]] = J(i, j);
    }
    if (row >= 0 && problem_.diagonal[a] < 0)
      for (int i = 0; i < Dim; ++i) values[diagonal_entry_[Dim * row + i]] = A_[a](i, i);
  }

  // Regularised semismooth Newton: J + delta I with delta shrinking with the residual, so that a
  // singular J (W rank-deficient, redundant sticking contacts) still gives a bounded direction while
  // the fast local convergence is kept as phi -> 0.
  const double relative_residual = std::sqrt(2.0 * merit_before) / std::max(r.norm(), 1e-300);
  double shift = scale * std::min(1e-3, relative_residual);
  Eigen::VectorXd direction(size), reduced_rhs(Dim * pattern_size_);
  bool solved = false;
  double applied_shift = 0.0;
  for (int attempt = 0; attempt < 6 && !solved; ++attempt, shift = std::max(shift * 100.0, 1e-12 * scale)) {
    for (const int slot : diagonal_entry_) values[slot] += shift - applied_shift;
    applied_shift = shift;
    // The open contacts outside the pattern first: (A_a + shift I) d_a = -phi_a (A_a's diagonal alone
    // without W_aa, as the whole system has it).
    bool finite = true;
    for (int a = 0; a < contacts; ++a) {
      if (pattern_index_[a] >= 0) continue;
      Block M = problem_.diagonal[a] >= 0 ? A_[a] : Block(A_[a].diagonal().asDiagonal());
      M.diagonal().array() += shift;
      const Local d = M.partialPivLu().solve(-phi.template segment<Dim>(Dim * a));
      finite = finite && d.allFinite();
      direction.template segment<Dim>(Dim * a) = d;
    }
    if (!finite) continue;
    // Then the pattern's, with the others' steps moved to the right: -phi_a - B_a sum_b W_ab d_b.
    for (int a = 0; a < contacts; ++a) {
      const int row = pattern_index_[a];
      if (row < 0) continue;
      Local coupling = Local::Zero();
      if (!open_[a])
        for (int k = problem_.row_start[a]; k < problem_.row_start[a + 1]; ++k)
          if (pattern_index_[problem_.column[k]] < 0)
            coupling += problem_.blocks[k] * direction.template segment<Dim>(Dim * problem_.column[k]);
      reduced_rhs.template segment<Dim>(Dim * row) = -phi.template segment<Dim>(Dim * a) - B_[a] * coupling;
    }
    if (pattern_size_ > 0) {
      lu_.factorize(jacobian_);
      if (lu_.info() != Eigen::Success) continue;
      const Eigen::VectorXd reduced = lu_.solve(reduced_rhs);
      if (lu_.info() != Eigen::Success || !reduced.allFinite()) continue;
      for (int a = 0; a < contacts; ++a)
        if (const int row = pattern_index_[a]; row >= 0)
          direction.template segment<Dim>(Dim * a) = reduced.template segment<Dim>(Dim * row);
    }
    solved = true;
  }
  if (!solved) return report;

  if (recent_merits_.size() == kNonmonotoneMemory) recent_merits_.erase(recent_merits_.begin());
  recent_merits_.push_back(merit_before);
  const double reference = *std::max_element(recent_merits_.begin(), recent_merits_.end());
  double t = 1.0;
  for (int halving = 0; halving < kMaxLineSearchHalvings; ++halving, t *= 0.5) {
    const Eigen::VectorXd trial = r + t * direction;
    const double trial_merit = merit(trial, u_);
    if (trial_merit <= reference - 1e-4 * t * merit_before) {
      r = trial;
      u_current_ = true;
      report.progressed = true;
      report.merit = trial_merit;
      return report;
    }
  }
  return report;
}

template class AlartCurnierNewton<2>;
template class AlartCurnierNewton<3>;

}  // namespace lmgc::solver
