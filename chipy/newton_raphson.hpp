#pragma once
// LMGC90's Newton–Raphson control of a command.py (chipy NewtonRaphson_*, mod_overall's
// check_newton_convergence and Compute_newton_time_step; docs/lmgc90-facts/mailx-2d-large-strain.md
// §4): the convergence test of each iteration and the adaptive time step of each step.
#include <cmath>

namespace lmgc::chipy {

struct NewtonRaphson {
  // Set-up, with LMGC90's defaults: its min and max steps are deliberately unusable until set.
  double final_time = 0.0;  // TPSendall
  double min_step = 1e24;   // H_min
  double max_step = 1e-24;  // H_max
  int max_iterations = 50;  // bulk_itermax
  int good_iterations = 10;
  int bad_iterations = 30;
  int patience = 3;  // numincconv: consecutive good (or bad) steps before h grows (or shrinks)

  // The step in progress.
  double tolerance = 0.0;  // critconv, set by Initialize
  int iterations = 0;      // bulk_iter: convergence checks made in the step
  // Kept from step to step; reset at step 1.
  int good_streak = 0, bad_streak = 0;

  enum Convergence { converged = 0, iterate = 1, diverged = 2 };
  enum StepState { go_on = 0, redo = 1, stop = 2 };
  struct TimeStep {
    StepState state = go_on;
    double h = 0.0;                   // the next step's h
    bool final_time_reached = false;  // stop: at the final time (else h fell below the minimum)
  };

  void initialize(double tol) {
    tolerance = tol;
    iterations = 0;
  }

  // One check: converged when norm < tol; diverged at the max_iterations-th check without it.
  Convergence check(double norm) {
    ++iterations;
    if (norm < tolerance) return converged;
    return iterations == max_iterations ? diverged : iterate;
  }

  // After the Newton loop of a step ending at `time` with time step h (step number `step`): redo
  // with h/√2 when the loop used every iteration; otherwise h × √2 after `patience` good steps in a
  // row (capped at max_step), h/√2 after `patience` bad ones; the last step cut to end at the final
  // time; stop when the next h would be below min_step.
  TimeStep compute(double time, double h, long step) {
    if (step == 1) good_streak = bad_streak = 0;
    TimeStep out;
    out.h = h;
    if (iterations == max_iterations) {
      out.h = h / std::sqrt(2.0);
      out.state = redo;
      good_streak = bad_streak = 0;
    } else {
      if (iterations <= good_iterations) {
        ++good_streak;
        bad_streak = 0;
      } else if (iterations >= bad_iterations) {
        ++bad_streak;
        good_streak = 0;
      } else {
        good_streak = bad_streak = 0;
      }
      if (good_streak == patience) {
        out.h = std::min(h * std::sqrt(2.0), max_step);
        good_streak = bad_streak = 0;
      } else if (bad_streak == patience) {
        out.h = h / std::sqrt(2.0);
        good_streak = bad_streak = 0;
      }
    }
    const double margin = 1e-4 * h;
    if (time + out.h - final_time > margin) out.h = final_time - time;
    if (out.h < min_step) {
      out.state = stop;
      out.final_time_reached = std::abs(final_time - (time + out.h)) <= margin;
    }
    return out;
  }
};

}  // namespace lmgc::chipy
