// lmgc-fc3d: solves FCLIB frictional contact problems (fc3d/README.md) with the project's NLGS and
// reports, per problem, what it cost and how accurately it was solved: the natural-map error ÷ |q|
// (fc3d/FORMAT.md §3), never Siconos' max(|q|, |r|, |u|) normalisation.
// Exit: 0 every problem solved to --tol, 1 a file could not be read, 2 usage, 3 some problem unsolved.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <span>

#include "lmgc_revision.hpp"
#include "solver/io/fclib/fclib_reader.hpp"
#include "solver/nlgs/frictional_contact_problem.hpp"
#include "solver/nlgs/local_problem_nlgs.hpp"

namespace {

using namespace lmgc::solver;

struct ProblemReport {
  std::string name;
  int dimension = 3, contacts = 0, sweeps = 0, newton_steps = 0;
  double seconds = 0.0, error = 0.0;
  std::vector<double> milestone_seconds;
  std::string verification;
  bool solved = false;
};

template <int Dim>
ProblemReport solve(const FclibLocalProblem& input, const LocalProblemNlgsOptions& options) {
  const FrictionalContactProblem<Dim> problem = problem_from_scalar_rows<Dim>(
      input.size, input.row_pointer, input.column_index, input.value, input.q, input.mu);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(input.size);
  const LocalProblemNlgsResult result = solve_local_problem_nlgs<Dim>(problem, r, options);
  ProblemReport report;
  report.dimension = Dim;
  report.contacts = problem.contact_count;
  report.sweeps = result.sweeps + result.race_sweeps;  // all sweeps done, the race's included
  report.newton_steps = result.newton_steps;
  report.seconds = result.seconds;
  report.error = natural_map_error(problem, r);  // recomputed independently of the solver's test
  report.milestone_seconds = result.milestone_seconds;
  report.solved = std::isfinite(report.error) && report.error <= options.tolerance;
  // The file's own solution, where present: its error in the same measure, and how far our u is from it
  // (r need not be unique when W is singular; u is compared instead).
  if (input.solution_r && input.solution_r->size() == input.size) {
    const double stored_error = natural_map_error(problem, *input.solution_r);
    const Eigen::VectorXd u = apply_delassus(problem, r) + problem.q;
    const Eigen::VectorXd u_stored = apply_delassus(problem, *input.solution_r) + problem.q;
    const double scale = std::max(u_stored.norm(), problem.q.norm());
    report.verification = fmt::format("stored solution: error {:.1e}, |u - u_stored|/|q| {:.1e}",
                                      stored_error, (u - u_stored).norm() / (scale > 0.0 ? scale : 1.0));
  } else {
    report.verification = "no stored solution";
  }
  return report;
}

std::string seconds_or_dash(double seconds) {
  return seconds < 0.0 ? "-" : fmt::format("{:.4f}", seconds);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lmgc-fc3d: solve FCLIB frictional contact problems (HDF5, /fclib_local) with NLGS"};
  app.set_version_flag("--version",
                       std::string("lmgc-fc3d ") + LMGC_VERSION + " (revision " + LMGC_REVISION + ")");
  std::vector<std::string> files;
  LocalProblemNlgsOptions options;
  options.milestones = {1e-4, 1e-6, 1e-8};
  std::string order = "natural", csv_path;
  app.add_option("FILE", files, "FCLIB problem files (.hdf5)")->required()->check(CLI::ExistingFile);
  app.add_option("--tol", options.tolerance, "target natural-map error / |q|")->check(CLI::PositiveNumber);
  app.add_option("--max-sweeps", options.max_sweeps, "NLGS sweep cap per problem")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-seconds", options.max_seconds, "wall-clock cap per problem")
      ->check(CLI::PositiveNumber);
  app.add_option("--relax", options.relax, "NLGS relaxation")->check(CLI::Range(0.0, 2.0));
  app.add_option("--order", order, "contact order: natural or shuffled (reshuffled every sweep)")
      ->check(CLI::IsMember({"natural", "shuffled"}));
  std::string method = "newton+nlgs";
  app.add_option(
         "--method", method,
         "nlgs: Gauss-Seidel sweeps only; nlgs+newton: sweeps first, semismooth Newton when they stall; "
         "newton+nlgs: Newton phases first, raced by sweeps, then as nlgs+newton")
      ->check(CLI::IsMember({"nlgs", "nlgs+newton", "newton+nlgs"}));
  app.add_option("--newton-steps", options.max_newton_steps_per_phase,
                 "Newton steps per phase, at most (a phase ends earlier when it stalls)")
      ->check(CLI::PositiveNumber);
  app.add_option(
         "--race-share", options.race_share,
         "newton+nlgs: share of the opening Newton phases' time given to sweeps racing them (0: none)")
      ->check(CLI::Range(0.0, 10.0));
  app.add_option(
         "--opening-sweeps", options.opening_sweeps,
         "newton+nlgs: sweeps before the first of the opening Newton phases (one more before each next)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--csv", csv_path, "also write the per-problem table to this CSV file");
  app.footer(
      "Error measure: natural-map residual / |q| (fc3d/FORMAT.md section 3), recomputed after the solve.\n"
      "Exit: 0 every problem solved to --tol, 1 a file could not be read, 2 usage, 3 some problem unsolved.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  options.newton_when_stalled = method != "nlgs";
  options.newton_first = method == "newton+nlgs";
  options.order = order == "shuffled" ? ContactOrder::shuffled_each_sweep : ContactOrder::natural;

  std::vector<ProblemReport> reports;
  bool read_failure = false;
  fmt::print("{:<50} {:>2} {:>5} {:>7} {:>6} {:>9} {:>9} {:>9} {:>9} {:>9}  {}\n", "problem", "d", "nc",
             "sweeps", "newton", "time[s]", "error", "t(1e-4)", "t(1e-6)", "t(1e-8)", "check");
  for (const std::string& file : files) {
    FclibLocalProblem input;
    try {
      input = read_fclib_local(file);
    } catch (const std::exception& error) {
      std::cerr << "lmgc-fc3d: " << error.what() << "\n";
      read_failure = true;
      continue;
    }
    ProblemReport report;
    try {
      report = input.space_dimension == 3 ? solve<3>(input, options) : solve<2>(input, options);
    } catch (const std::exception& error) {
      std::cerr << "lmgc-fc3d: " << file << ": " << error.what() << "\n";
      read_failure = true;
      continue;
    }
    report.name = std::filesystem::path(file).filename().string();
    fmt::print("{:<50} {:>2} {:>5} {:>7} {:>6} {:>9.4f} {:>9.2e} {:>9} {:>9} {:>9}  {}\n", report.name,
               report.dimension, report.contacts, report.sweeps, report.newton_steps, report.seconds,
               report.error, seconds_or_dash(report.milestone_seconds[0]),
               seconds_or_dash(report.milestone_seconds[1]), seconds_or_dash(report.milestone_seconds[2]),
               report.verification);
    std::fflush(stdout);
    reports.push_back(std::move(report));
  }
  int solved = 0;
  double total = 0.0;
  for (const ProblemReport& report : reports) {
    solved += report.solved ? 1 : 0;
    total += report.seconds;
  }
  fmt::print("solved {}/{} to {:.0e}, total {:.3f} s\n", solved, files.size(), options.tolerance, total);
  if (!csv_path.empty()) {
    std::ofstream csv(csv_path);
    csv << "problem,dimension,contacts,sweeps,newton_steps,seconds,error,seconds_to_1e-4,seconds_to_1e-6,"
           "seconds_to_1e-8\n";
    for (const ProblemReport& report : reports)
      csv << fmt::format("{},{},{},{},{},{:.6f},{:.3e},{:.6f},{:.6f},{:.6f}\n", report.name, report.dimension,
                         report.contacts, report.sweeps, report.newton_steps, report.seconds, report.error,
                         report.milestone_seconds[0], report.milestone_seconds[1],
                         report.milestone_seconds[2]);
  }
  if (read_failure) return 1;
  return solved == static_cast<int>(files.size()) ? 0 : 3;
}
