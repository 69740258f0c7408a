#include "solver/nlgs/local_problem_nlgs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>

#include "solver/nlgs/local_problem_newton.hpp"
#include "solver/nlgs/local_solver_2d.hpp"
#include "solver/nlgs/local_solver_3d.hpp"

namespace lmgc::solver {

namespace {

constexpr double kSteadySweepBlocks = 40.0;
// A block of sweeps that leaves more than this fraction of the error has stalled.
constexpr double kStalledBlockRatio = 0.8;
// A Newton phase is kept when it divides the error by at least 10.
constexpr double kNewtonPhaseGain = 0.1;

// One contact's exact solve, in the problem's normal-first ordering.
bool solve_one_contact(const Eigen::Matrix3d& W, const Eigen::Vector3d& q, double mu, Eigen::Vector3d& r,
                       double tolerance) {
  const LocalSolution3D s = solve_signorini_coulomb_3d(W, q, mu, r, tolerance);
  r = s.r;
  return !s.failed;
}

bool solve_one_contact(const Eigen::Matrix2d& W, const Eigen::Vector2d& q, double mu, Eigen::Vector2d& r,
                       double /*tolerance*/) {
  // The 2D enumeration works in LMGC90's (t, n) order.
  Eigen::Matrix2d W_tn;
  W_tn << W(1, 1), W(1, 0), W(0, 1), W(0, 0);
  const LocalSolution2D s = solve_signorini_coulomb_2d(W_tn, Eigen::Vector2d(q(1), q(0)), mu);
  if (s.failed) return false;
  r = Eigen::Vector2d(s.r(1), s.r(0));
  return true;
}

}  // namespace

template <int Dim>
LocalProblemNlgsResult solve_local_problem_nlgs(const FrictionalContactProblem<Dim>& problem,
                                                Eigen::VectorXd& r, const LocalProblemNlgsOptions& options) {
  using Clock = std::chrono::steady_clock;
  using Local = Eigen::Matrix<double, Dim, 1>;
  const auto start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  LocalProblemNlgsResult result;
  result.milestone_seconds.assign(options.milestones.size(), -1.0);
  result.milestone_sweeps.assign(options.milestones.size(), -1);
  const int contacts = problem.contact_count;
  if (r.size() != Dim * contacts) r = Eigen::VectorXd::Zero(Dim * contacts);

  const double q_norm = problem.q.norm();
  // Each local solve is asked for much less than the global tolerance allots to one contact.
  const double local_tolerance =
      1e-2 * options.tolerance * (q_norm > 0.0 ? q_norm : 1.0) / std::sqrt(std::max(contacts, 1));

  std::vector<int> order(contacts);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 random(options.seed);

  const auto record = [&](double error, int sweeps) {
    for (std::size_t m = 0; m < options.milestones.size(); ++m)
      if (result.milestone_seconds[m] < 0.0 && error <= options.milestones[m]) {
        result.milestone_seconds[m] = elapsed();
        result.milestone_sweeps[m] = sweeps;
      }
  };

  const auto sweep = [&] {
    if (options.order == ContactOrder::shuffled_each_sweep) std::shuffle(order.begin(), order.end(), random);
    int failures = 0;
    for (const int a : order) {
      const int diagonal = problem.diagonal[a];
      if (diagonal < 0) {
        ++failures;
        continue;
      }
      // Local free velocity: q_a + sum over b != a of W_ab r_b.
      Local q_local = problem.q.template segment<Dim>(Dim * a);
      for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
        if (k != diagonal)
          q_local.noalias() += problem.blocks[k] * r.template segment<Dim>(Dim * problem.column[k]);
      Local r_a = r.template segment<Dim>(Dim * a);
      const Local r_old = r_a;
      if (!solve_one_contact(problem.blocks[diagonal], q_local, problem.mu(a), r_a, local_tolerance))
        ++failures;
      if (options.relax != 1.0) r_a = options.relax * r_a + (1.0 - options.relax) * r_old;
      r.template segment<Dim>(Dim * a) = r_a;
    }
    result.local_failures = failures;
  };

  // The best iterate so far is what the caller gets: Newton's merit is not the natural map.
  Eigen::VectorXd best = r;
  double best_error = natural_map_error(problem, r);
  result.error = best_error;
  record(result.error, 0);
  const auto evaluate = [&] {
    result.error = natural_map_error(problem, r);
    record(result.error, result.sweeps);
    if (result.error < best_error) {
      best_error = result.error;
      best = r;
    }
  };
  const auto running = [&] {
    return std::isfinite(result.error) && result.error > options.tolerance &&
           result.sweeps < options.max_sweeps && elapsed() < options.max_seconds;
  };

  // Method switching by measured convergence rate, log(error drop) per second: sweep in blocks; when a
  // block stalls (error down by less than 20%), run a phase of Newton steps (until its line search stalls).
  // When that phase gained less per second than the sweeps, the next block of sweeps is twice as long, so a
  // problem where Newton never pays spends a shrinking share of its time in it.
  std::unique_ptr<AlartCurnierNewton<Dim>> newton;
  int block_sweeps = options.sweeps_per_block;
  const auto rate = [](double before, double after, double seconds) {
    return std::log(before / std::max(after, 1e-300)) / std::max(seconds, 1e-9);
  };
  while (running()) {
    const double error_at_block_start = result.error;
    const double block_start = elapsed();
    for (int s = 0; s < block_sweeps && running(); ++s) {
      sweep();
      ++result.sweeps;
      evaluate();
    }
    if (!options.newton_when_stalled || !running() ||
        result.error < kStalledBlockRatio * error_at_block_start)
      continue;
    const double sweep_rate = rate(error_at_block_start, result.error, elapsed() - block_start);
    // Sweeps still converging steadily: keep sweeping while they would reach the tolerance within
    // another kSteadySweepBlocks blocks at their present rate.
    const double decades_per_block = std::log10(error_at_block_start / std::max(result.error, 1e-300));
    if (decades_per_block > 0.0 &&
        std::log10(result.error / options.tolerance) / decades_per_block < kSteadySweepBlocks)
      continue;
    if (!newton) newton = std::make_unique<AlartCurnierNewton<Dim>>(problem);
    const double error_before_newton = result.error;
    const Eigen::VectorXd r_before_newton = r;
    const double newton_start = elapsed();
    for (int k = 0; k < options.max_newton_steps_per_block && running(); ++k) {
      if (!newton->step(r).progressed) break;
      ++result.newton_steps;
      evaluate();
    }
    // A phase that did not gain a decade is discarded: Newton can leave an iterate that is slightly
    // better in the natural map but from which the sweeps converge much more slowly (seen on
    // Capsules). Otherwise resume from the best iterate (Newton's merit is not the natural map).
    if (best_error > kNewtonPhaseGain * error_before_newton) {
      r = r_before_newton;
      result.error = error_before_newton;
    } else if (best_error < result.error) {
      r = best;
      result.error = best_error;
    }
    const double newton_rate = rate(error_before_newton, result.error, elapsed() - newton_start);
    block_sweeps = newton_rate > sweep_rate ? options.sweeps_per_block : 2 * block_sweeps;
  }
  if (best_error < result.error || !std::isfinite(result.error)) {
    r = best;
    result.error = best_error;
  }
  result.seconds = elapsed();
  result.converged = result.error <= options.tolerance;
  return result;
}

template LocalProblemNlgsResult solve_local_problem_nlgs<2>(const FrictionalContactProblem<2>&,
                                                            Eigen::VectorXd&, const LocalProblemNlgsOptions&);
template LocalProblemNlgsResult solve_local_problem_nlgs<3>(const FrictionalContactProblem<3>&,
                                                            Eigen::VectorXd&, const LocalProblemNlgsOptions&);

}  // namespace lmgc::solver
