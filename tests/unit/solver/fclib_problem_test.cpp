// The block-sparse frictional contact problem in local form, its natural-map error, the NLGS on it,
// and the FCLIB reader (fc3d/FORMAT.md) on files of ../shared/fc3d.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/io/fclib/fclib_reader.hpp"
#include "solver/nlgs/frictional_contact_problem.hpp"
#include "solver/nlgs/local_problem_newton.hpp"
#include "solver/nlgs/local_problem_nlgs.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;

fs::path fc3d_dir() {
  return lmgc::test::shared_dir() / "fc3d" / "problems";
}

#define REQUIRE_FC3D()                                                              \
  do {                                                                              \
    if (!fs::is_directory(fc3d_dir()))                                              \
      GTEST_SKIP() << "FCLIB problem set not found at " << fc3d_dir()               \
                   << " (set LMGC_SHARED_DIR or place shared/ beside the project)"; \
  } while (0)

// Scalar compressed rows of a dense matrix, entries of every row in decreasing column order (so not
// sorted), exact zeros dropped.
struct ScalarRows {
  std::vector<int> row_pointer{0};
  std::vector<int> column_index;
  std::vector<double> value;
};

ScalarRows unsorted_rows_of(const Eigen::MatrixXd& W) {
  ScalarRows rows;
  for (int i = 0; i < W.rows(); ++i) {
    for (int j = static_cast<int>(W.cols()) - 1; j >= 0; --j)
      if (W(i, j) != 0.0) {
        rows.column_index.push_back(j);
        rows.value.push_back(W(i, j));
      }
    rows.row_pointer.push_back(static_cast<int>(rows.column_index.size()));
  }
  return rows;
}

template <int Dim>
FrictionalContactProblem<Dim> problem_of(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& mu) {
  const ScalarRows rows = unsorted_rows_of(W);
  return problem_from_scalar_rows<Dim>(static_cast<int>(W.rows()), rows.row_pointer, rows.column_index,
                                       rows.value, q, mu);
}

// Two 3D contacts; block (0, 1) absent, block (1, 0) present (W not symmetric).
Eigen::MatrixXd two_contact_matrix() {
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(6, 6);
  W.topLeftCorner<3, 3>() << 4.0, 0.5, -0.25, 0.5, 3.0, 0.125, -0.25, 0.125, 2.0;
  W.bottomLeftCorner<3, 3>() << 0.75, 0.0, -1.5, 0.0, 0.25, 0.0, 1.0, -0.5, 0.0;
  W.bottomRightCorner<3, 3>() << 5.0, -1.0, 0.0, -1.0, 6.0, 0.5, 0.0, 0.5, 7.0;
  return W;
}

TEST(FrictionalContactProblem, BlocksFromUnsortedScalarRowsWithADuplicateAndAMissingBlock) {
  const Eigen::MatrixXd W = two_contact_matrix();
  ScalarRows rows = unsorted_rows_of(W);
  // W(4, 4) = 6 stored as two entries of row 4, 4 (first) and 2 (in its place): they must be summed.
  {
    const int begin = rows.row_pointer[4], end = rows.row_pointer[5];
    int k = begin;
    while (k < end && rows.column_index[k] != 4) ++k;
    ASSERT_LT(k, end);
    rows.value[k] = 2.0;
    rows.column_index.insert(rows.column_index.begin() + begin, 4);
    rows.value.insert(rows.value.begin() + begin, 4.0);
    for (std::size_t r = 5; r < rows.row_pointer.size(); ++r) ++rows.row_pointer[r];
  }
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(6, -1.0, 1.0);
  const Eigen::VectorXd mu = Eigen::Vector2d(0.3, 0.5);
  const FrictionalContactProblem<3> p =
      problem_from_scalar_rows<3>(6, rows.row_pointer, rows.column_index, rows.value, q, mu);

  EXPECT_EQ(p.contact_count, 2);
  EXPECT_EQ(p.row_start, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(p.column, (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(p.diagonal, (std::vector<int>{0, 2}));
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[0], Eigen::Matrix3d(W.topLeftCorner<3, 3>()));
  EXPECT_EQ(p.blocks[1], Eigen::Matrix3d(W.bottomLeftCorner<3, 3>()));
  EXPECT_EQ(p.blocks[2], Eigen::Matrix3d(W.bottomRightCorner<3, 3>()));
  EXPECT_EQ(p.q, q);
  EXPECT_EQ(p.mu, mu);

  const Eigen::VectorXd r = (Eigen::VectorXd(6) << 1.0, -2.0, 0.5, 3.0, 0.25, -1.0).finished();
  EXPECT_LE((apply_delassus(p, r) - W * r).norm(), 1e-14 * (W * r).norm());
}

TEST(FrictionalContactProblem, BlockRowWithoutDiagonalBlockIsMarkedMinusOne) {
  Eigen::MatrixXd W = two_contact_matrix();
  W.bottomRightCorner<3, 3>().setZero();
  const FrictionalContactProblem<3> p = problem_of<3>(W, Eigen::VectorXd::Zero(6), Eigen::Vector2d(0.3, 0.3));
  EXPECT_EQ(p.diagonal, (std::vector<int>{0, -1}));
  EXPECT_EQ(p.row_start, (std::vector<int>{0, 1, 2}));
}

TEST(FrictionalContactProblem, InvalidScalarRowsThrowInvalidArgument) {
  const Eigen::MatrixXd W = two_contact_matrix();
  const ScalarRows rows = unsorted_rows_of(W);
  const Eigen::VectorXd q = Eigen::VectorXd::Ones(6);
  const Eigen::VectorXd mu = Eigen::Vector2d(0.3, 0.3);

  ScalarRows out_of_range = rows;
  out_of_range.column_index[3] = 6;
  EXPECT_THROW(problem_from_scalar_rows<3>(6, out_of_range.row_pointer, out_of_range.column_index,
                                           out_of_range.value, q, mu),
               std::invalid_argument);
  out_of_range.column_index[3] = -1;
  EXPECT_THROW(problem_from_scalar_rows<3>(6, out_of_range.row_pointer, out_of_range.column_index,
                                           out_of_range.value, q, mu),
               std::invalid_argument);

  EXPECT_THROW(problem_from_scalar_rows<3>(6, rows.row_pointer, rows.column_index, rows.value,
                                           Eigen::VectorXd::Ones(5), mu),
               std::invalid_argument);
  EXPECT_THROW(problem_from_scalar_rows<3>(6, rows.row_pointer, rows.column_index, rows.value, q,
                                           Eigen::VectorXd::Ones(3)),
               std::invalid_argument);
  EXPECT_THROW(problem_from_scalar_rows<3>(5, std::span(rows.row_pointer).first(6), rows.column_index,
                                           rows.value, Eigen::VectorXd::Ones(5), mu),
               std::invalid_argument);  // 5 is not a multiple of 3

  ScalarRows bad_pointer = rows;
  bad_pointer.row_pointer.back() = static_cast<int>(rows.value.size()) + 1;
  EXPECT_THROW(problem_from_scalar_rows<3>(6, bad_pointer.row_pointer, bad_pointer.column_index,
                                           bad_pointer.value, q, mu),
               std::invalid_argument);
}

// --- natural-map error on hand-made solutions ---

// Three 3D contacts with W = I (so q = u - r) and binary-exact numbers, one of each regime:
//   take-off  r = 0,                 u = (1, 3, 0)
//   stick     r = (2, 0.5, 0.25),     u = 0                       (mu = 0.5: |r_T| < 1)
//   slide     r = (2.5, -0.75, -1),   u = (0, 0.375, 0.5)        (mu = 0.5: |r_T| = 1.25 = mu r_n,
//                                                                  r_T = -mu r_n u_T / |u_T|)
TEST(NaturalMapError, ExactHandMadeSolutionIn3DHasZeroErrorAndAPerturbationDoesNot) {
  Eigen::VectorXd r(9), u(9);
  r << 0.0, 0.0, 0.0, 2.0, 0.5, 0.25, 2.5, -0.75, -1.0;
  u << 1.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.375, 0.5;
  const Eigen::MatrixXd W = Eigen::MatrixXd::Identity(9, 9);
  const FrictionalContactProblem<3> p = problem_of<3>(W, u - r, Eigen::Vector3d(0.5, 0.5, 0.5));
  EXPECT_EQ(natural_map_error(p, r), 0.0);

  for (int k = 0; k < 9; ++k) {
    Eigen::VectorXd perturbed = r;
    perturbed(k) += 0.125;
    EXPECT_GT(natural_map_error(p, perturbed), 0.0) << "component " << k;
  }
  // r = 0 with a compressing contact: F = -P_K(-q - mu |q_T| e_n) != 0.
  EXPECT_GT(natural_map_error(p, Eigen::VectorXd::Zero(9)), 0.0);
}

TEST(NaturalMapError, CoupledExactSolutionIn3DHasRoundOffError) {
  const Eigen::MatrixXd W = two_contact_matrix();
  Eigen::VectorXd r(6), u(6);
  r << 2.0, 0.5, 0.25, 2.5, -0.75, -1.0;  // stick, slide (mu = 0.5)
  u << 0.0, 0.0, 0.0, 0.0, 0.375, 0.5;
  const FrictionalContactProblem<3> p = problem_of<3>(W, u - W * r, Eigen::Vector2d(0.5, 0.5));
  EXPECT_LE(natural_map_error(p, r), 1e-15);
  // Same r with mu = 0.4: the sliding contact is now outside its cone.
  const FrictionalContactProblem<3> p2 = problem_of<3>(W, u - W * r, Eigen::Vector2d(0.5, 0.4));
  EXPECT_GT(natural_map_error(p2, r), 1e-3);
}

// 2D, ordering (n, t), W = I:
//   take-off r = 0,        u = (1, 3)
//   stick    r = (2, 0.5), u = 0          (mu = 0.5)
//   slide    r = (2, -1),  u = (0, 0.5)   (mu = 0.5: r_t = -mu r_n sign(u_t))
TEST(NaturalMapError, ExactHandMadeSolutionIn2DHasZeroErrorAndAPerturbationDoesNot) {
  Eigen::VectorXd r(6), u(6);
  r << 0.0, 0.0, 2.0, 0.5, 2.0, -1.0;
  u << 1.0, 3.0, 0.0, 0.0, 0.0, 0.5;
  const Eigen::MatrixXd W = Eigen::MatrixXd::Identity(6, 6);
  const FrictionalContactProblem<2> p = problem_of<2>(W, u - r, Eigen::Vector3d(0.5, 0.5, 0.5));
  EXPECT_EQ(p.contact_count, 3);
  EXPECT_EQ(natural_map_error(p, r), 0.0);
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd perturbed = r;
    perturbed(k) -= 0.25;
    EXPECT_GT(natural_map_error(p, perturbed), 0.0) << "component " << k;
  }
  // Sliding the wrong way (r_t = +mu r_n while u_t > 0) is not a solution.
  Eigen::VectorXd wrong_way = r;
  wrong_way(5) = 1.0;
  const FrictionalContactProblem<2> p2 = problem_of<2>(W, u - wrong_way, Eigen::Vector3d(0.5, 0.5, 0.5));
  EXPECT_GT(natural_map_error(p2, wrong_way), 0.1);
}

// --- NLGS on a random well-conditioned problem ---

// W = Hᵀ M⁻¹ H with H (n × m, n > m) random and M diagonal positive: symmetric positive definite,
// every block coupled.
FrictionalContactProblem<3> random_problem(int contacts, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const int m = 3 * contacts, n = m + 6;
  Eigen::MatrixXd H(n, m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) H(i, j) = uniform(random);
  Eigen::VectorXd inverse_mass(n);
  for (int i = 0; i < n; ++i) inverse_mass(i) = 1.0 + 0.5 * uniform(random);
  const Eigen::MatrixXd W = H.transpose() * inverse_mass.asDiagonal() * H;
  Eigen::VectorXd q(m), mu(contacts);
  for (int a = 0; a < contacts; ++a) {
    q(3 * a) = -0.5 + 0.75 * uniform(random);  // mostly approaching; small q_T: some contacts stick
    q(3 * a + 1) = 0.1 * uniform(random);
    q(3 * a + 2) = 0.1 * uniform(random);
    mu(a) = 0.3 + 0.2 * uniform(random);
  }
  return problem_of<3>(W, q, mu);
}

TEST(LocalProblemNlgs, RandomWellConditionedProblemConvergesInEveryVariant) {
  const FrictionalContactProblem<3> p = random_problem(6, 7);
  ASSERT_EQ(p.blocks.size(), 36u);
  struct Variant {
    const char* name;
    double relax;
    ContactOrder order;
  };
  for (const Variant& v :
       {Variant{"plain", 1.0, ContactOrder::natural}, Variant{"relax 0.8", 0.8, ContactOrder::natural},
        Variant{"shuffled", 1.0, ContactOrder::shuffled_each_sweep},
        Variant{"relax 0.8 shuffled", 0.8, ContactOrder::shuffled_each_sweep}}) {
    LocalProblemNlgsOptions options;
    options.newton_first = false;  // the sweeps are under test
    options.tolerance = 1e-10;
    options.max_sweeps = 20000;
    options.relax = v.relax;
    options.order = v.order;
    options.seed = 3;
    options.milestones = {1e-4, 1e-8};
    Eigen::VectorXd r;
    const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
    EXPECT_TRUE(result.converged) << v.name << ": error " << result.error << " after " << result.sweeps;
    EXPECT_LE(result.error, 1e-10) << v.name;
    EXPECT_NEAR(natural_map_error(p, r), result.error, 1e-15) << v.name;
    EXPECT_GT(result.sweeps, 0) << v.name;
    EXPECT_EQ(result.local_failures, 0) << v.name;
    ASSERT_EQ(result.milestone_sweeps.size(), 2u);
    EXPECT_GE(result.milestone_sweeps[0], 0) << v.name;
    EXPECT_LE(result.milestone_sweeps[0], result.milestone_sweeps[1]) << v.name;
    for (int a = 0; a < p.contact_count; ++a) {
      EXPECT_GE(r(3 * a), 0.0) << v.name << " contact " << a;
      EXPECT_LE(r.segment<2>(3 * a + 1).norm(), p.mu(a) * r(3 * a) * (1.0 + 1e-9) + 1e-14)
          << v.name << " contact " << a;
    }
  }
}

// The sweeps compute the exact error only now and then (at a block's end, every tenth sweep, and once
// their own estimate nears the tolerance): a cap that stops them in between still returns the exact
// error of the reactions it returns, and never the last exact error of an earlier iterate.
TEST(LocalProblemNlgs, ASweepCapBetweenExactErrorsReturnsTheExactErrorOfTheReturnedReactions) {
  const FrictionalContactProblem<3> p = random_problem(6, 7);
  for (const int cap : {1, 3, 7, 13, 23}) {
    LocalProblemNlgsOptions options;
    options.newton_first = false;
    options.newton_when_stalled = false;
    options.tolerance = 0.0;  // never reached: the cap ends every run
    options.max_sweeps = cap;
    Eigen::VectorXd r;
    const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
    EXPECT_EQ(result.sweeps, cap);
    EXPECT_EQ(natural_map_error(p, r), result.error) << cap << " sweeps";
  }
}

TEST(LocalProblemNlgs, NewtonFirstSolvesARandomWellConditionedProblemInAFewNewtonSteps) {
  const FrictionalContactProblem<3> p = random_problem(6, 7);
  LocalProblemNlgsOptions options;
  options.tolerance = 1e-12;
  options.race_share = 0.0;  // Newton alone: the race's sweeps depend on timing
  Eigen::VectorXd r;
  const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
  EXPECT_TRUE(result.converged) << "error " << result.error;
  EXPECT_GT(result.newton_steps, 0);
  EXPECT_EQ(result.sweeps, 0);
  EXPECT_EQ(result.race_sweeps, 0);
  EXPECT_LT(result.newton_steps, 30);  // semismooth Newton on an SPD W: a few steps, not a crawl
  EXPECT_NEAR(natural_map_error(p, r), result.error, 1e-15);
}

// A chain of bodies, contact a between bodies a and a + 1 (H block-sparse, so W_ab = 0 unless the
// contacts share a body), two contacts in three separating fast (q_n of about 5 W_nn).
FrictionalContactProblem<3> chain_problem(int contacts, std::uint64_t seed) {
  const int bodies = contacts + 1;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(6 * bodies, 3 * contacts);
  for (int a = 0; a < contacts; ++a)
    for (int body : {a, a + 1})
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 3; ++j) H(6 * body + i, 3 * a + j) = uniform(random);
  const Eigen::MatrixXd W = H.transpose() * H;
  Eigen::VectorXd q(3 * contacts), mu(contacts);
  for (int a = 0; a < contacts; ++a) {
    q(3 * a) = a % 3 == 0 ? -0.5 : 20.0 + uniform(random);  // W_nn is about 4
    q(3 * a + 1) = 0.1 * uniform(random);
    q(3 * a + 2) = 0.1 * uniform(random);
    mu(a) = 0.3;
  }
  return problem_of<3>(W, q, mu);
}

// Newton solves the open contacts on their own and only the others in the sparse LU, with the open
// ones' steps moved to the right (local_problem_newton.hpp). From reactions that pull the separating
// contacts (r_n < 0, r_T != 0: open, B = 0, with steps that are not zero) and press the others, each
// step must be the whole system's: the same iterates as with the whole system in the LU (pattern
// slack infinity), to round-off.
TEST(AlartCurnierNewton, StepsWithOpenContactsCutOutOfTheLuEqualTheWholeSystemsSteps) {
  const int contacts = 30;
  const FrictionalContactProblem<3> p = chain_problem(contacts, 11);
  ASSERT_EQ(p.blocks.size(), 3u * contacts - 2);  // block tridiagonal
  Eigen::VectorXd cut = Eigen::VectorXd::Zero(3 * contacts);
  for (int a = 0; a < contacts; ++a)
    cut.segment<3>(3 * a) = a % 3 == 0 ? Eigen::Vector3d(1.0, 0.0, 0.0) : Eigen::Vector3d(-0.5, 0.25, -0.25);
  Eigen::VectorXd whole = cut;
  AlartCurnierNewton<3> cutting(p), keeping_all(p, std::numeric_limits<double>::infinity());
  for (int step = 0; step < 4; ++step) {
    const NewtonStepReport a = cutting.step(cut), b = keeping_all.step(whole);
    EXPECT_EQ(a.progressed, b.progressed) << "step " << step;
    EXPECT_LE((cut - whole).norm(), 1e-10 * whole.norm()) << "step " << step;
  }
  int open = 0;
  for (int a = 0; a < contacts; ++a) open += cut(3 * a) < 1e-9;
  EXPECT_GE(open, contacts / 2);  // the cut was exercised
  EXPECT_LT(open, contacts);      // and so was the LU
}

TEST(LocalProblemNlgs, NewtonWithMostContactsOpenSolvesABlockSparseChainInAFewNewtonSteps) {
  const FrictionalContactProblem<3> p = chain_problem(30, 11);
  LocalProblemNlgsOptions options;
  options.tolerance = 1e-12;
  options.race_share = 0.0;
  Eigen::VectorXd r;
  const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
  EXPECT_TRUE(result.converged) << "error " << result.error;
  EXPECT_EQ(result.sweeps, 0);
  EXPECT_LT(result.newton_steps, 20);
}

TEST(LocalProblemNlgs, ExactSolutionAsStartNeedsNoSweep) {
  Eigen::VectorXd r(6), u(6);
  r << 2.0, 0.5, 0.25, 2.5, -0.75, -1.0;
  u << 0.0, 0.0, 0.0, 0.0, 0.375, 0.5;
  const Eigen::MatrixXd W = Eigen::MatrixXd::Identity(6, 6);
  const FrictionalContactProblem<3> p = problem_of<3>(W, u - r, Eigen::Vector2d(0.5, 0.5));
  Eigen::VectorXd start = r;
  const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, start, LocalProblemNlgsOptions{});
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.sweeps, 0);
  EXPECT_EQ(start, r);
}

// --- FCLIB reader on ../shared/fc3d ---

TEST(FclibReader, ConfetiFourContactHasTheDocumentedShape) {
  REQUIRE_FC3D();
  const FclibLocalProblem f = read_fclib_local(fc3d_dir() / "fc3d" / "Confeti-ex13-4contact-Fc3D-SBM.hdf5");
  EXPECT_EQ(f.space_dimension, 3);
  EXPECT_EQ(f.size, 12);
  EXPECT_EQ(f.row_pointer.size(), 13u);
  EXPECT_EQ(f.row_pointer.back(), 144);
  EXPECT_EQ(f.column_index.size(), 144u);
  EXPECT_EQ(f.value.size(), 144u);
  ASSERT_EQ(f.q.size(), 12);
  EXPECT_NEAR(f.q.norm(), 9.92, 0.005);  // README table
  ASSERT_EQ(f.mu.size(), 4);
  for (int a = 0; a < 4; ++a) EXPECT_DOUBLE_EQ(f.mu(a), 0.04);
  const FrictionalContactProblem<3> p =
      problem_from_scalar_rows<3>(f.size, f.row_pointer, f.column_index, f.value, f.q, f.mu);
  EXPECT_EQ(p.contact_count, 4);
  EXPECT_EQ(p.blocks.size(), 16u);  // README: 16 blocks, W fully coupled
  for (int a = 0; a < 4; ++a) EXPECT_GE(p.diagonal[a], 0);
}

TEST(FclibReader, NESpheresHas44ContactsWithMu08) {
  REQUIRE_FC3D();
  const FclibLocalProblem f = read_fclib_local(fc3d_dir() / "fc3d" / "NESpheres_30_1.hdf5");
  EXPECT_EQ(f.space_dimension, 3);
  EXPECT_EQ(f.size, 132);
  ASSERT_EQ(f.mu.size(), 44);
  for (int a = 0; a < 44; ++a) EXPECT_DOUBLE_EQ(f.mu(a), 0.8);
  EXPECT_EQ(f.column_index.size(), 1384u);  // README table
  EXPECT_NEAR(f.q.norm(), 65.6, 0.05);
}

TEST(FclibReader, TwoDimensionalProblemHasSpacedim2And367Contacts) {
  REQUIRE_FC3D();
  const FclibLocalProblem f = read_fclib_local(fc3d_dir() / "fc2d" / "FrictionContactProblem00727.hdf5");
  EXPECT_EQ(f.space_dimension, 2);
  EXPECT_EQ(f.size, 734);
  EXPECT_EQ(f.mu.size(), 367);
  EXPECT_EQ(f.q.size(), 734);
  const FrictionalContactProblem<2> p =
      problem_from_scalar_rows<2>(f.size, f.row_pointer, f.column_index, f.value, f.q, f.mu);
  EXPECT_EQ(p.contact_count, 367);
  EXPECT_EQ(p.blocks.size(), 1589u);  // README table
}

TEST(FclibReader, NonHdf5FileThrowsFclibErrorNamingThePath) {
  const fs::path path =
      fs::temp_directory_path() / ("lmgc_fclib_not_hdf5_" + std::to_string(::getpid()) + ".hdf5");
  {
    std::ofstream out(path);
    out << "this is not an HDF5 file\n";
  }
  try {
    (void)read_fclib_local(path);
    ADD_FAILURE() << "no exception";
  } catch (const FclibError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  fs::remove(path);
  const fs::path missing = fs::temp_directory_path() / "lmgc_fclib_no_such_file.hdf5";
  EXPECT_THROW((void)read_fclib_local(missing), FclibError);
}

TEST(FclibReader, NlgsSolvesConfetiFourContactTo1e8) {
  REQUIRE_FC3D();
  const FclibLocalProblem f = read_fclib_local(fc3d_dir() / "fc3d" / "Confeti-ex13-4contact-Fc3D-SBM.hdf5");
  const FrictionalContactProblem<3> p =
      problem_from_scalar_rows<3>(f.size, f.row_pointer, f.column_index, f.value, f.q, f.mu);
  LocalProblemNlgsOptions options;
  options.tolerance = 1e-8;
  options.max_seconds = 30.0;
  Eigen::VectorXd r;
  const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
  EXPECT_TRUE(result.converged) << "error " << result.error << " after " << result.sweeps << " sweeps";
  EXPECT_LE(natural_map_error(p, r), 1e-8);
}

// spheres-in-a-box: the sweeps stall near 1e-6 (Siconos' NSGS too: 2.5e-6 after 100000 iterations);
// Newton with its non-monotone line search solves it to 1e-8 in a few tens of steps.
TEST(FclibReader, NewtonSolvesSpheresInABoxWhereTheSweepsStall) {
  REQUIRE_FC3D();
  const FclibLocalProblem f =
      read_fclib_local(fc3d_dir() / "fc3d" / "spheres-in-a-box-98-i10000-256-10_local.hdf5");
  const FrictionalContactProblem<3> p =
      problem_from_scalar_rows<3>(f.size, f.row_pointer, f.column_index, f.value, f.q, f.mu);
  LocalProblemNlgsOptions sweeps_only;
  sweeps_only.newton_first = false;
  sweeps_only.newton_when_stalled = false;
  sweeps_only.max_sweeps = 2000;
  Eigen::VectorXd r_sweeps;
  const LocalProblemNlgsResult swept = solve_local_problem_nlgs(p, r_sweeps, sweeps_only);
  EXPECT_FALSE(swept.converged) << "error " << swept.error;
  EXPECT_GT(swept.error, 1e-7);

  LocalProblemNlgsOptions options;
  options.max_seconds = 60.0;
  Eigen::VectorXd r;
  const LocalProblemNlgsResult result = solve_local_problem_nlgs(p, r, options);
  EXPECT_TRUE(result.converged) << "error " << result.error;
  EXPECT_LE(natural_map_error(p, r), 1e-8);
  EXPECT_LT(result.newton_steps, 200);
}

}  // namespace
}  // namespace lmgc::solver
