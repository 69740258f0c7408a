// MatLib's neo-Hookean material as lmgc evaluates it (solver/fem/neo_hookean.hpp): the values
// LMGC90 2025 wrote at a Gauss point of mecaMAILx_2D/1Q4-traction, and the tangent against finite
// differences of the stress.
#include "solver/fem/neo_hookean.hpp"

#include <gtest/gtest.h>

namespace lmgc::solver::fem {
namespace {

// 1Q4-traction's material (EYng 1.3e8, EPss 0.3) at its last step: GPV.LAST writes
// P = (−2400.155, 0, 0, 639340.2, 191227.2), F = diag(0.9980619, 1.0045, 1) and W = 1442.605.
// F's printed 7 digits are not enough for P11 (a difference of nearly equal terms): F11 and F22 are
// those that give the printed P11 and P22, and P33 and W, computed from them, are compared with what
// LMGC90 printed (1e-6 relative; they agree to 1e-7).
TEST(NeoHookean, StressAndEnergyAreMatLibsAtLmgc90sGaussPoint) {
  const NeoHookeanConstants c = neo_hookean_constants(1.3e8, 0.3);
  EXPECT_DOUBLE_EQ(c.mu, 5.0e7);
  EXPECT_NEAR(c.lambda, 7.5e7, 1e-6);
  const Eigen::Matrix3d f = Eigen::Vector3d(0.998061895, 1.004499775, 1.0).asDiagonal();
  const NeoHookeanPoint p = neo_hookean_stress(c, f);
  ASSERT_TRUE(p.admissible);
  EXPECT_NEAR(p.stress(0, 0), -2400.155, 2e-6 * 639340.2);
  EXPECT_NEAR(p.stress(1, 1), 639340.2, 1e-6 * 639340.2);
  EXPECT_NEAR(p.stress(2, 2), 191227.2, 1e-6 * 191227.2);
  EXPECT_NEAR(p.energy, 1442.605, 1e-6 * 1442.605);
  EXPECT_EQ(p.stress(0, 1), 0.0);
}

TEST(NeoHookean, TangentIsTheDerivativeOfTheStress) {
  const NeoHookeanConstants c = neo_hookean_constants(2.0e5, 0.33);
  Eigen::Matrix3d f;
  f << 1.2, 0.3, 0.0, -0.1, 0.9, 0.0, 0.0, 0.0, 1.05;
  constexpr int kAll[9][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}, {2, 0}, {2, 1}, {2, 2}};
  const Eigen::Matrix<double, 9, 9> t = neo_hookean_tangent<9>(c, f, kAll);
  const double step = 1e-6;
  double scale = t.cwiseAbs().maxCoeff(), worst = 0.0;
  for (int b = 0; b < 9; ++b) {
    Eigen::Matrix3d plus = f, minus = f;
    plus(kAll[b][0], kAll[b][1]) += step;
    minus(kAll[b][0], kAll[b][1]) -= step;
    const Eigen::Matrix3d derivative =
        (neo_hookean_stress(c, plus).stress - neo_hookean_stress(c, minus).stress) / (2.0 * step);
    for (int a = 0; a < 9; ++a)
      worst = std::max(worst, std::abs(derivative(kAll[a][0], kAll[a][1]) - t(a, b)));
  }
  EXPECT_LT(worst, 1e-7 * scale);
  // Hyperelastic: the tangent is symmetric.
  EXPECT_LT((t - t.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST(NeoHookean, AtRestTheTangentIsLinearElasticity) {
  const NeoHookeanConstants c = neo_hookean_constants(1.3e8, 0.3);
  constexpr int k2D[5][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}};
  const Eigen::Matrix<double, 5, 5> t = neo_hookean_tangent<5>(c, Eigen::Matrix3d::Identity(), k2D);
  EXPECT_NEAR(t(0, 0), c.lambda + 2.0 * c.mu, 1e-6);
  EXPECT_NEAR(t(0, 3), c.lambda, 1e-6);
  EXPECT_NEAR(t(1, 1), c.mu, 1e-6);
  EXPECT_NEAR(t(1, 2), c.mu, 1e-6);
  const NeoHookeanPoint rest = neo_hookean_stress(c, Eigen::Matrix3d::Identity());
  EXPECT_EQ(rest.stress.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(rest.energy, 0.0);
}

TEST(NeoHookean, AnInvertedGradientIsNotAdmissible) {
  const NeoHookeanConstants c = neo_hookean_constants(1.0e6, 0.3);
  EXPECT_FALSE(neo_hookean_stress(c, Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal()).admissible);
  EXPECT_FALSE(neo_hookean_stress(c, Eigen::Vector3d(0.0, 1.0, 1.0).asDiagonal()).admissible);
}

}  // namespace
}  // namespace lmgc::solver::fem
