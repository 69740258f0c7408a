// fc3d_siconos_peer: the peer benchmark for lmgc-fc3d. Runs Siconos' own frictional-contact solvers
// (libsiconos_numerics, C API: fc3d_driver / fc2d_driver) on FCLIB problems (fc3d/README.md) and
// reports, next to Siconos' own iteration count, time and error, OUR error on the reaction Siconos
// returns: the natural-map residual / |q| (fc3d/FORMAT.md §3), as lmgc-fc3d reports it.
//
// W is handed to Siconos as a sparse block matrix (NM_SPARSE_BLOCK, Dim×Dim blocks), the storage Siconos
// itself uses for these problems when it reads FCLIB files; --storage dense gives a column-major NM_DENSE
// matrix instead, as a cross-check of the block build (small problems only).
//
// Every solve runs in a forked child: a wall-clock cap can then be enforced (Siconos has no time
// limit of its own, only an iteration cap) and a crash inside Siconos costs one table row, not the run.
// The time reported covers the driver call only (steady_clock around fc3d_driver / fc2d_driver).
// Exit: 0 every solve returned (converged or not), 2 usage, 3 a file unreadable or a solve killed/crashed.
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "solver/io/fclib/fclib_reader.hpp"
#include "solver/nlgs/frictional_contact_problem.hpp"

// Siconos numerics, C API (the headers wrap themselves in extern "C").
#include <siconos/numerics/FrictionContactProblem.h>
#include <siconos/numerics/Friction_cst.h>
#include <siconos/numerics/NonSmoothDrivers.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/NumericsVerbose.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/SparseBlockMatrix.h>

namespace {

using namespace lmgc::solver;

enum class Storage { sparse_block, dense };

struct PeerOptions {
  double tolerance = 1e-8;  // Siconos' own error measure
  int max_iterations = 100000;
  double max_seconds = 60.0;  // wall-clock cap per solve, enforced by killing the child
  Storage storage = Storage::sparse_block;
};

// What a child reports back through its pipe (plain data, written in one piece).
struct SolveOutcome {
  int driver_info = -1;  // 0: Siconos reports convergence
  int iterations = 0;    // iparam[SICONOS_IPARAM_ITER_DONE]
  double seconds = 0.0;
  double siconos_error = NAN;      // dparam[SICONOS_DPARAM_RESIDU]
  double our_error = NAN;          // natural-map residual / |q| of Siconos' reaction
  double velocity_mismatch = NAN;  // |u_siconos - (W r + q)| / |q|: checks that Siconos saw our W
};

// Written by the Siconos per-iteration callback into memory shared with the parent, so that a
// solve killed at the time cap still tells how far it got.
struct Progress {
  int calls = 0;
  double last_error = NAN;
};

void record_progress(void* env, int /*size*/, double* /*reaction*/, double* /*velocity*/, double error,
                     void* /*extra*/) {
  auto* progress = static_cast<Progress*>(env);
  ++progress->calls;
  progress->last_error = error;
}

// W as a Siconos sparse block matrix pointing into storage owned by this object. Blocks are
// Eigen's column-major Dim×Dim matrices, which is the Fortran order Siconos expects.
template <int Dim>
struct SiconosBlockMatrix {
  std::vector<typename FrictionalContactProblem<Dim>::Block> blocks;  // a copy: Siconos gets non-const data
  std::vector<double*> block_pointers;
  std::vector<unsigned int> cumulative_sizes;
  std::vector<std::size_t> row_offsets, block_columns;
  SparseBlockStructuredMatrix sbm;

  SiconosBlockMatrix(const SiconosBlockMatrix&) = delete;  // sbm points into this object's vectors
  SiconosBlockMatrix& operator=(const SiconosBlockMatrix&) = delete;

  explicit SiconosBlockMatrix(const FrictionalContactProblem<Dim>& problem) : blocks(problem.blocks) {
    const int contacts = problem.contact_count;
    for (auto& block : blocks) block_pointers.push_back(block.data());
    for (int a = 1; a <= contacts; ++a) cumulative_sizes.push_back(static_cast<unsigned int>(Dim * a));
    row_offsets.assign(problem.row_start.begin(), problem.row_start.end());
    block_columns.assign(problem.column.begin(), problem.column.end());  // sorted within each row
    SBM_null(&sbm);
    sbm.nbblocks = static_cast<unsigned int>(blocks.size());
    sbm.block = block_pointers.data();
    sbm.blocknumber0 = sbm.blocknumber1 = static_cast<unsigned int>(contacts);
    sbm.blocksize0 = sbm.blocksize1 = cumulative_sizes.data();
    sbm.filled1 = row_offsets.size();  // block rows + 1, as in the header's example
    sbm.filled2 = block_columns.size();
    sbm.index1_data = row_offsets.data();
    sbm.index2_data = block_columns.data();
    sbm.diagonal_blocks = nullptr;  // Siconos fills it on demand
  }
};

// W as a dense column-major matrix (Siconos NM_DENSE layout).
template <int Dim>
std::vector<double> dense_column_major(const FrictionalContactProblem<Dim>& problem) {
  const std::size_t n = problem.q.size();
  std::vector<double> dense(n * n, 0.0);
  for (int a = 0; a < problem.contact_count; ++a)
    for (int k = problem.row_start[a]; k < problem.row_start[a + 1]; ++k)
      for (int j = 0; j < Dim; ++j)
        for (int i = 0; i < Dim; ++i)
          dense[(Dim * problem.column[k] + j) * n + Dim * a + i] = problem.blocks[k](i, j);
  return dense;
}

// Runs one Siconos solve (in the child process) and measures it.
template <int Dim>
SolveOutcome solve_with_siconos(const FrictionalContactProblem<Dim>& problem, int solver_id,
                                const PeerOptions& options, Progress* progress) {
  const int n = static_cast<int>(problem.q.size());
  NumericsMatrix* w = nullptr;
  std::vector<double> dense;
  std::optional<SiconosBlockMatrix<Dim>> block_matrix;
  if (options.storage == Storage::dense) {
    dense = dense_column_major(problem);
    w = NM_create_from_data(NM_DENSE, n, n, dense.data());
  } else {
    block_matrix.emplace(problem);
    w = NM_new_SBM(n, n, &block_matrix->sbm);
  }
  Eigen::VectorXd q = problem.q, mu = problem.mu;  // Siconos takes non-const pointers
  FrictionContactProblem siconos_problem{};
  siconos_problem.dimension = Dim;
  siconos_problem.numberOfContacts = problem.contact_count;
  siconos_problem.M = w;
  siconos_problem.q = q.data();
  siconos_problem.mu = mu.data();

  SolverOptions* solver_options = solver_options_create(solver_id);  // Siconos' defaults, incl. local solver
  solver_options->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
  solver_options->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
  Callback callback{progress, &record_progress};
  solver_options->callback = &callback;

  Eigen::VectorXd reaction = Eigen::VectorXd::Zero(n), velocity = Eigen::VectorXd::Zero(n);
  const auto start = std::chrono::steady_clock::now();
  const int info = Dim == 3 ? fc3d_driver(&siconos_problem, reaction.data(), velocity.data(), solver_options)
                            : fc2d_driver(&siconos_problem, reaction.data(), velocity.data(), solver_options);
  const auto stop = std::chrono::steady_clock::now();

  SolveOutcome outcome;
  outcome.driver_info = info;
  outcome.iterations = solver_options->iparam[SICONOS_IPARAM_ITER_DONE];
  outcome.seconds = std::chrono::duration<double>(stop - start).count();
  outcome.siconos_error = solver_options->dparam[SICONOS_DPARAM_RESIDU];
  outcome.our_error = natural_map_error(problem, reaction);
  const double q_norm = problem.q.norm() > 0.0 ? problem.q.norm() : 1.0;
  outcome.velocity_mismatch = (velocity - (apply_delassus(problem, reaction) + problem.q)).norm() / q_norm;

  solver_options->callback = nullptr;  // stack object: not Siconos' to free
  solver_options_delete(solver_options);
  if (options.storage == Storage::dense)
    NM_free_not_dense(w);  // the dense array belongs to this function
  else
    NM_free_not_SBM(w);  // the block storage belongs to block_matrix
  return outcome;
}

enum class RunStatus { finished, timed_out, crashed };

struct RunReport {
  RunStatus status = RunStatus::crashed;
  SolveOutcome outcome;
  Progress progress;  // last callback state, meaningful when timed out
  std::string detail;
};

// Forks, solves in the child, waits at most options.max_seconds for its answer.
template <int Dim>
RunReport run_isolated(const FrictionalContactProblem<Dim>& problem, int solver_id,
                       const PeerOptions& options) {
  RunReport report;
  auto* progress = static_cast<Progress*>(
      mmap(nullptr, sizeof(Progress), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  if (progress == MAP_FAILED) throw std::runtime_error("mmap failed");
  *progress = Progress{};
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  std::fflush(stdout);
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(pipe_fds[0]);
    const SolveOutcome outcome = solve_with_siconos<Dim>(problem, solver_id, options, progress);
    const ssize_t written = write(pipe_fds[1], &outcome, sizeof outcome);
    _exit(written == static_cast<ssize_t>(sizeof outcome) ? 0 : 1);
  }
  close(pipe_fds[1]);
  pollfd waiting{pipe_fds[0], POLLIN, 0};
  const int ready = poll(&waiting, 1, static_cast<int>(options.max_seconds * 1000.0));
  if (ready == 0) {
    kill(child, SIGKILL);
    report.status = RunStatus::timed_out;
  } else if (read(pipe_fds[0], &report.outcome, sizeof report.outcome) ==
             static_cast<ssize_t>(sizeof report.outcome)) {
    report.status = RunStatus::finished;
  }
  int wait_status = 0;
  waitpid(child, &wait_status, 0);
  if (report.status == RunStatus::crashed)
    report.detail = WIFSIGNALED(wait_status) ? fmt::format("signal {}", WTERMSIG(wait_status))
                                             : fmt::format("exit {}", WEXITSTATUS(wait_status));
  report.progress = *progress;
  close(pipe_fds[0]);
  munmap(progress, sizeof(Progress));
  return report;
}

struct SolverChoice {
  std::string label;
  int id_3d, id_2d;  // -1: not available in that dimension
};

std::string table_row(const std::string& problem_name, int contacts, const std::string& solver,
                      const RunReport& report, double max_seconds) {
  const std::string head = fmt::format("{:<50} {:>5} {:<8}", problem_name, contacts, solver);
  switch (report.status) {
    case RunStatus::finished: {
      const SolveOutcome& o = report.outcome;
      return fmt::format("{} {:>4} {:>7} {:>10.4f} {:>10.2e} {:>10.2e} {:>9.1e}", head, o.driver_info,
                         o.iterations, o.seconds, o.siconos_error, o.our_error, o.velocity_mismatch);
    }
    case RunStatus::timed_out:
      return fmt::format("{} {:>4} {:>7} {:>10} {:>10.2e} {:>10} {:>9}  killed at the {:.0f} s cap", head,
                         "cap", report.progress.calls > 0 ? fmt::format(">={}", report.progress.calls) : "?",
                         fmt::format(">{:.0f}", max_seconds), report.progress.last_error, "-", "-",
                         max_seconds);
    case RunStatus::crashed:
      return fmt::format("{} {:>4} {:>7} {:>10} {:>10} {:>10} {:>9}  Siconos crashed ({})", head, "crash",
                         "-", "-", "-", "-", "-", report.detail);
  }
  return head;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fc3d_siconos_peer: solve FCLIB problems with Siconos' NSGS (and NSN-AC) for comparison"};
  std::vector<std::string> files, skipped_names, solver_labels{"nsgs", "nsn_ac"};
  PeerOptions options;
  std::string storage = "sbm";
  app.add_option("FILE", files, "FCLIB problem files (.hdf5)")->required()->check(CLI::ExistingFile);
  app.add_option("--tol", options.tolerance, "Siconos tolerance (its own error measure)")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-iter", options.max_iterations, "Siconos iteration cap")->check(CLI::PositiveNumber);
  app.add_option("--max-seconds", options.max_seconds, "wall-clock cap per solve (the child is killed)")
      ->check(CLI::PositiveNumber);
  app.add_option("--solvers", solver_labels, "nsgs and/or nsn_ac (3D only)")
      ->check(CLI::IsMember({"nsgs", "nsn_ac"}))
      ->delimiter(',');
  app.add_option("--skip", skipped_names, "problem file names (no directory) not to run")->delimiter(',');
  app.add_option("--storage", storage, "how W is given to Siconos: sbm (sparse block) or dense")
      ->check(CLI::IsMember({"sbm", "dense"}));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  options.storage = storage == "dense" ? Storage::dense : Storage::sparse_block;
  numerics_set_verbose(0);

  const std::vector<SolverChoice> all_solvers{{"nsgs", SICONOS_FRICTION_3D_NSGS, SICONOS_FRICTION_2D_NSGS},
                                              {"nsn_ac", SICONOS_FRICTION_3D_NSN_AC, -1}};
  std::vector<SolverChoice> solvers;
  for (const SolverChoice& choice : all_solvers)
    if (std::find(solver_labels.begin(), solver_labels.end(), choice.label) != solver_labels.end())
      solvers.push_back(choice);

  fmt::print("{:<50} {:>5} {:<8} {:>4} {:>7} {:>10} {:>10} {:>10} {:>9}\n", "problem", "nc", "solver", "info",
             "iter", "time[s]", "sic.error", "our error", "u check");
  int failures = 0;
  for (const std::string& file : files) {
    const std::string name = std::filesystem::path(file).filename().string();
    if (std::find(skipped_names.begin(), skipped_names.end(), name) != skipped_names.end()) {
      fmt::print("{:<50} skipped (--skip)\n", name);
      continue;
    }
    FclibLocalProblem input;
    try {
      input = read_fclib_local(file);
    } catch (const std::exception& error) {
      std::cerr << "fc3d_siconos_peer: " << error.what() << "\n";
      ++failures;
      continue;
    }
    for (const SolverChoice& choice : solvers) {
      const int solver_id = input.space_dimension == 3 ? choice.id_3d : choice.id_2d;
      if (solver_id < 0) continue;
      RunReport report;
      int contacts = 0;
      if (input.space_dimension == 3) {
        const auto problem = problem_from_scalar_rows<3>(input.size, input.row_pointer, input.column_index,
                                                         input.value, input.q, input.mu);
        contacts = problem.contact_count;
        report = run_isolated<3>(problem, solver_id, options);
      } else {
        const auto problem = problem_from_scalar_rows<2>(input.size, input.row_pointer, input.column_index,
                                                         input.value, input.q, input.mu);
        contacts = problem.contact_count;
        report = run_isolated<2>(problem, solver_id, options);
      }
      if (report.status != RunStatus::finished) ++failures;
      fmt::print("{}\n", table_row(name, contacts, choice.label, report, options.max_seconds));
      std::fflush(stdout);
    }
  }
  return failures == 0 ? 0 : 3;
}
