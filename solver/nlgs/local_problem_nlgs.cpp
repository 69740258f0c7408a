#include "solver/nlgs/local_problem_nlgs.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
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
// The race waits after a Newton step that divides the error by at least 100 (newton_phase).
constexpr double kRaceWaitGain = 0.01;
// A Newton phase ends after this many steps without halving its best error. Newton from r = 0 on
// fc2d_granularflowonwall_02020 wanders between 1e-6 and 1e-5 for 320 steps before it finds the active
// set and converges in one step; with a single opening phase, a window of 100 or 200 stopped it first
// and left the problem unsolved.
constexpr int kNewtonStallWindow = 400;
// Opening Newton phases, each from the caller's reactions after one more sweep than the last.
constexpr int kOpeningNewtonAttempts = 4;
// The exact error of an iterate costs a product with the whole Delassus operator, nearly a sweep's
// work. A sweep measures instead, for
// free, the natural map of each contact just before its local solve: the Gauss–Seidel residual of
// the iterate it works on, one sweep behind. The error after the sweep is predicted from the last
// three estimates: the last rate, times its own improvement where the convergence speeds up (the last
// sweeps of LMGC_GlobalFrictionContactProblem00046 divide the error by 1e2, then 1e8). The exact error
// is computed when that prediction comes within kExactBelow × tolerance, after a line's first sweep,
// and every kExactEvery sweeps (the race's best, a NaN). The milestones (time to 1e-4, ...) are
// taken from the estimates as well: the sweep whose estimate first falls below one, at most one sweep
// after the iterate that did.
constexpr double kExactBelow = 10.0;
constexpr int kExactEvery = 10;

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

  // One sweep over the contacts of reactions x in the given order (r's, or the race's below); returns
  // the number of local solves that failed. The natural-map error ÷ |q| of the contacts as the sweep
  // found them (each before its own solve) goes first into the line's last three `estimates`, and to
  // the milestones (`sweeps`: this sweep's count over both lines).
  const double q_scale = q_norm > 0.0 ? q_norm : 1.0;
  const auto sweep_over = [&](Eigen::VectorXd& x, std::vector<int>& sweep_order, std::mt19937_64& shuffle,
                              std::array<double, 3>& estimates, int sweeps) {
    if (options.order == ContactOrder::shuffled_each_sweep)
      std::shuffle(sweep_order.begin(), sweep_order.end(), shuffle);
    int failures = 0;
    double estimate_squared = 0.0;
    for (const int a : sweep_order) {
      const int diagonal = problem.diagonal[a];
      if (diagonal < 0) {
        ++failures;
        continue;
      }
      // Local free velocity: q_a + sum over b != a of W_ab r_b.
      Local q_local = problem.q.template segment<Dim>(Dim * a);
      for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
        if (k != diagonal)
          q_local.noalias() += problem.blocks[k] * x.template segment<Dim>(Dim * problem.column[k]);
      Local r_a = x.template segment<Dim>(Dim * a);
      const Local r_old = r_a;
      estimate_squared +=
          natural_map<Dim>(r_old, q_local + problem.blocks[diagonal] * r_old, problem.mu(a)).squaredNorm();
      if (!solve_one_contact(problem.blocks[diagonal], q_local, problem.mu(a), r_a, local_tolerance))
        ++failures;
      if (options.relax != 1.0) r_a = options.relax * r_a + (1.0 - options.relax) * r_old;
      x.template segment<Dim>(Dim * a) = r_a;
    }
    const double estimate = std::sqrt(estimate_squared) / q_scale;
    estimates = {estimate, estimates[0], estimates[1]};
    record(estimate, sweeps);
    return failures;
  };
  // Whether the sweep that ended with `estimate`, the n-th of its line, computes the exact error.
  // `estimates`: the line's last three, newest first.
  const auto exact_after = [&](const std::array<double, 3>& estimates, int n) {
    const double rate = estimates[1] > 0.0 ? std::min(1.0, estimates[0] / estimates[1]) : 1.0;
    const double earlier_rate = estimates[2] > 0.0 ? std::min(1.0, estimates[1] / estimates[2]) : 1.0;
    const double speed_up = earlier_rate > 0.0 ? std::min(1.0, rate / earlier_rate) : 1.0;
    const double predicted = estimates[0] * rate * speed_up;
    return !(predicted > kExactBelow * options.tolerance) || n == 1 || n % kExactEvery == 0;
  };
  std::array<double, 3> sweep_estimates{}, race_estimates{};
  bool error_stale = false;  // r has moved since result.error was computed
  // After r jumps (a Newton step, a restart), its earlier estimates say nothing of its rate.
  const auto r_jumped = [&] {
    sweep_estimates = {};
    error_stale = false;
  };
  const auto sweep = [&] {
    result.local_failures =
        sweep_over(r, order, random, sweep_estimates, result.sweeps + result.race_sweeps + 1);
    error_stale = true;
  };

  // The best iterate so far is what the caller gets: Newton's merit is not the natural map.
  Eigen::VectorXd best = r;
  double best_error = natural_map_error(problem, r);
  result.error = best_error;
  record(result.error, 0);
  // Records the error of iterate x (r, or the race's copy) and keeps it when it is the best so far.
  const auto consider = [&](const Eigen::VectorXd& x, double error) {
    record(error, result.sweeps + result.race_sweeps);
    if (error < best_error) {
      best_error = error;
      best = x;
    }
  };
  // u: W r + q when the caller has it (a Newton step computed it for its line search).
  const auto evaluate = [&](const Eigen::VectorXd* u = nullptr) {
    result.error = u ? natural_map_error(problem, r, *u) : natural_map_error(problem, r);
    error_stale = false;
    consider(r, result.error);
  };
  const auto running = [&] {
    return std::isfinite(result.error) && best_error > options.tolerance &&
           result.sweeps < options.max_sweeps && elapsed() < options.max_seconds;
  };

  // A Newton phase: steps until the tolerance, the step cap, a line search that finds no step, or
  // kNewtonStallWindow steps in a row without halving the phase's best error. Each phase starts a new
  // Newton object: the line search's memory of merits belongs to one unbroken run of steps.
  //
  // While `racing`, sweeps from the caller's reactions run beside the Newton steps on their own copy
  // (own order and shuffle too), given options.race_share of the time Newton has taken: where the sweeps
  // alone would finish first (NESpheres in one sweep, FrictionContactProblem00727 in 679), they do, at the
  // price of up to a quarter more time where Newton wins (the race waits after a Newton step that cut
  // the error a hundredfold); where they win, the Newton steps they waited for
  // can cost several times their own time.
  // The budget is wall-clock time, so how many race sweeps run (not what the solve converges to
  // within its tolerance) varies from run to run.
  Eigen::VectorXd race = r;
  std::vector<int> race_order = order;
  std::mt19937_64 race_shuffle(options.seed + 1);
  double race_seconds = 0.0, newton_seconds = 0.0;
  bool racing = false, race_started = false, race_stale = false;
  // The race's first sweep is free: a problem one sweep solves never waits for a Newton step.
  const auto race_sweeps = [&] {
    while (racing && running() && (race_seconds < options.race_share * newton_seconds || !race_started)) {
      const double sweep_start = elapsed();
      sweep_over(race, race_order, race_shuffle, race_estimates, result.sweeps + result.race_sweeps + 1);
      race_started = true;
      ++result.race_sweeps;
      race_stale = !exact_after(race_estimates, result.race_sweeps);
      if (!race_stale) consider(race, natural_map_error(problem, race));
      race_seconds += elapsed() - sweep_start;
    }
  };
  // Returns the lowest error of r the phase reached.
  const auto newton_phase = [&] {
    AlartCurnierNewton<Dim> newton(problem);
    double error_at_last_halving = result.error, phase_best = result.error;
    int steps_without_gain = 0;
    for (int k = 0; k < options.max_newton_steps_per_phase && running(); ++k) {
      const double step_start = elapsed(), error_before = result.error;
      const bool progressed = newton.step(r).progressed;
      newton_seconds += elapsed() - step_start;
      if (!progressed) {
        race_sweeps();
        break;
      }
      ++result.newton_steps;
      r_jumped();
      evaluate(&newton.velocity());
      // A step that cut the error a hundredfold is in Newton's fast local convergence, which the
      // sweeps will not overtake: the race waits (its time budget still grows).
      if (!(result.error < kRaceWaitGain * error_before)) race_sweeps();
      phase_best = std::min(phase_best, result.error);
      if (result.error < 0.5 * error_at_last_halving) {
        error_at_last_halving = result.error;
        steps_without_gain = 0;
      } else if (++steps_without_gain >= kNewtonStallWindow) {
        break;
      }
    }
    return phase_best;
  };
  const auto resume_from_best = [&] {
    if (best_error < result.error) {
      r = best;
      result.error = best_error;
      r_jumped();
    }
  };

  // Sweeps still converging steadily: they would reach the tolerance within another kSteadySweepBlocks
  // blocks at the rate of the block that took the error from `before` to `after`.
  const auto sweeps_steady = [&](double before, double after) {
    const double decades_per_block = std::log10(before / std::max(after, 1e-300));
    return decades_per_block > 0.0 &&
           std::log10(after / options.tolerance) / decades_per_block < kSteadySweepBlocks;
  };
  // The exact error after the block's last sweep always (the callers compare blocks by it).
  const auto sweep_block = [&](int sweeps) {
    for (int s = 0; s < sweeps && running(); ++s) {
      sweep();
      ++result.sweeps;
      if (s == sweeps - 1 || exact_after(sweep_estimates, result.sweeps)) evaluate();
    }
  };

  // Opening Newton phases. Where Newton converges it beats the sweeps by one to two orders of magnitude
  // (bench/results/debian12-2core/fc3d_newton_nlgs.txt), but on the granular problems whether a phase
  // finds the active set depends on its start: from r = 0 after 0 to 4 sweeps, a single phase solved
  // fc2d_granularflowonwall_02020 in 2 of 5 starts and RockPile in 4 of 5; four phases from successive
  // starts solved both in 5 of 5. Between phases a block of sweeps from the best iterate tells whether
  // the sweeps alone would finish (FrictionContactProblem00727, where Newton wanders at 1e-3): then the
  // switching loop below takes over at once.
  if (options.newton_first && running()) {
    const Eigen::VectorXd start = r;
    const double start_error = result.error;
    racing = options.race_share > 0.0;
    race_sweeps();
    for (int attempt = 0; attempt < kOpeningNewtonAttempts && running(); ++attempt) {
      if (attempt > 0) {
        resume_from_best();
        const double before = result.error;
        sweep_block(options.sweeps_per_block);
        if (!running() || sweeps_steady(before, result.error)) break;
        r = start;
        result.error = start_error;
        r_jumped();
      }
      sweep_block(options.opening_sweeps + attempt);
      if (running()) newton_phase();
    }
    racing = false;
    if (race_stale) consider(race, natural_map_error(problem, race));
    resume_from_best();
  }

  // Method switching by measured convergence rate, log(error drop) per second: sweep in blocks; when a
  // block stalls (error down by less than 20%), run a Newton phase. When that phase gained less per
  // second than the sweeps, the next block of sweeps is twice as long, so a problem where Newton never
  // pays spends a shrinking share of its time in it.
  int block_sweeps = options.sweeps_per_block;
  const auto rate = [](double before, double after, double seconds) {
    return std::log(before / std::max(after, 1e-300)) / std::max(seconds, 1e-9);
  };
  while (running()) {
    const double error_at_block_start = result.error;
    const double block_start = elapsed();
    sweep_block(block_sweeps);
    if (!options.newton_when_stalled || !running() ||
        result.error < kStalledBlockRatio * error_at_block_start)
      continue;
    const double sweep_rate = rate(error_at_block_start, result.error, elapsed() - block_start);
    if (sweeps_steady(error_at_block_start, result.error)) continue;
    const double error_before_newton = result.error;
    const Eigen::VectorXd r_before_newton = r;
    const double newton_start = elapsed();
    const double phase_best = newton_phase();
    // A phase that neither converged nor gained a decade on its own start is discarded: Newton can
    // leave an iterate that is slightly better in the natural map but from which the sweeps converge
    // much more slowly (seen on Capsules). Otherwise resume from the best iterate (Newton's merit is
    // not the natural map).
    if (best_error > options.tolerance && phase_best > kNewtonPhaseGain * error_before_newton) {
      r = r_before_newton;
      result.error = error_before_newton;
      r_jumped();
    } else {
      resume_from_best();
    }
    const double newton_rate = rate(error_before_newton, result.error, elapsed() - newton_start);
    block_sweeps = newton_rate > sweep_rate ? options.sweeps_per_block : 2 * block_sweeps;
  }
  if (error_stale) evaluate();  // a cap ended a block between two exact errors
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
