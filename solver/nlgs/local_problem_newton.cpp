#include "solver/nlgs/local_problem_newton.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lmgc::solver {

namespace {

constexpr int kMaxLineSearchHalvings = 40;
// Merits the non-monotone line search compares with. Measured with a single Newton phase from r = 0,
// 20 s cap: monotone (1) solves 13 of the 17 FCLIB problems; of the three hardest (RockPile,
// spheres-in-a-box, fc2d_granularflowonwall_02020) 5 solves 1, 10 solves 2, 20 all three; 20 solves
// all 17 in 8 s, 40 all 17 in 26 s.
constexpr std::size_t kNonmonotoneMemory = 20;

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
AlartCurnierNewton<Dim>::AlartCurnierNewton(const FrictionalContactProblem<Dim>& problem)
    : problem_(problem) {
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

  const int size = Dim * contacts;
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(problem.blocks.size() * Dim * Dim + static_cast<std::size_t>(size));
  for (int a = 0; a < contacts; ++a)
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) pattern.emplace_back(Dim * a + i, Dim * problem.column[k] + j, 1.0);
  for (int i = 0; i < size; ++i) pattern.emplace_back(i, i, 1.0);
  jacobian_.resize(size, size);
  jacobian_.setFromTriplets(pattern.begin(), pattern.end());
  jacobian_.makeCompressed();
  const auto entry = [&](int row, int col) {
    const int* begin = jacobian_.innerIndexPtr() + jacobian_.outerIndexPtr()[col];
    const int* end = jacobian_.innerIndexPtr() + jacobian_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - jacobian_.innerIndexPtr());
  };
  block_entry_.resize(problem.blocks.size() * Dim * Dim);
  for (int a = 0; a < contacts; ++a)
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j)
          block_entry_[Dim * Dim * k + Dim * i + j] = entry(Dim * a + i, Dim * problem.column[k] + j);
  diagonal_entry_.resize(size);
  for (int i = 0; i < size; ++i) diagonal_entry_[i] = entry(i, i);
  lu_.analyzePattern(jacobian_);
}

template <int Dim>
double AlartCurnierNewton<Dim>::merit(const Eigen::VectorXd& r) const {
  const Eigen::VectorXd u = apply_delassus(problem_, r) + problem_.q;
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
  using Block = Eigen::Matrix<double, Dim, Dim>;
  const int contacts = problem_.contact_count;
  const int size = Dim * contacts;
  const Eigen::VectorXd u = apply_delassus(problem_, r) + problem_.q;
  Eigen::VectorXd phi(size);
  double* values = jacobian_.valuePtr();
  std::fill(values, values + jacobian_.nonZeros(), 0.0);
  double scale = 0.0;
  for (int a = 0; a < contacts; ++a) {
    Block A, B;
    Eigen::Matrix<double, Dim, 1> phi_a;
    alart_curnier<Dim>(r.template segment<Dim>(Dim * a), u.template segment<Dim>(Dim * a), problem_.mu(a),
                       rho_n_(a), rho_t_(a), phi_a, &A, &B);
    phi.template segment<Dim>(Dim * a) = phi_a;
    // J_ab = delta_ab A_a + B_a W_ab.
    for (int k = problem_.row_start[a]; k < problem_.row_start[a + 1]; ++k) {
      Block J = B * problem_.blocks[k];
      if (problem_.column[k] == a) J += A;
      const int* slot = &block_entry_[Dim * Dim * k];
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) values[slot[Dim * i + j]] = J(i, j);
      scale = std::max(scale, J.cwiseAbs().maxCoeff());
    }
    if (problem_.diagonal[a] < 0)
      for (int i = 0; i < Dim; ++i) values[diagonal_entry_[Dim * a + i]] = A(i, i);
  }
  const double merit_before = 0.5 * phi.squaredNorm();
  NewtonStepReport report;
  report.merit = merit_before;
  if (merit_before == 0.0) return report;

  // Regularised semismooth Newton: J + delta I with delta shrinking with the residual, so that a
  // singular J (W rank-deficient, redundant sticking contacts) still gives a bounded direction while
  // the fast local convergence is kept as phi -> 0.
  const double relative_residual = std::sqrt(2.0 * merit_before) / std::max(r.norm(), 1e-300);
  double shift = scale * std::min(1e-3, relative_residual);
  Eigen::VectorXd direction;
  double applied_shift = 0.0;
  for (int attempt = 0; attempt < 6 && direction.size() != size;
       ++attempt, shift = std::max(shift * 100.0, 1e-12 * scale)) {
    for (const int slot : diagonal_entry_) values[slot] += shift - applied_shift;
    applied_shift = shift;
    lu_.factorize(jacobian_);
    if (lu_.info() != Eigen::Success) continue;
    Eigen::VectorXd candidate = lu_.solve(-phi);
    if (lu_.info() == Eigen::Success && candidate.allFinite()) direction = std::move(candidate);
  }
  if (direction.size() != size) return report;

  if (recent_merits_.size() == kNonmonotoneMemory) recent_merits_.erase(recent_merits_.begin());
  recent_merits_.push_back(merit_before);
  const double reference = *std::max_element(recent_merits_.begin(), recent_merits_.end());
  double t = 1.0;
  for (int halving = 0; halving < kMaxLineSearchHalvings; ++halving, t *= 0.5) {
    const Eigen::VectorXd trial = r + t * direction;
    const double trial_merit = merit(trial);
    if (trial_merit <= reference - 1e-4 * t * merit_before) {
      r = trial;
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
