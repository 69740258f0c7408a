#pragma once
// The compressible neo-Hookean material that LMGC90 runs for 'mater neoh_' (MODELS.DAT, 'isext MatL_',
// 'kine_ large', 'form_ TotaL'): MatLib's NeohookeanPotential without an equation of state
// (MatLib4-LMGC-2021-1, src/matl/meca/hyper/NeohookeanPotential.h), with μ = E/(2(1 + ν)) and
// λ = K − 2μ/3, K = E/(3(1 − 2ν)):
//   W(C) = ½λ (ln J)² − μ ln J + ½μ (tr C − 3),   J = det F, C = FᵀF (the 3D trace),
//   S = μ I − (μ − λ ln J) C⁻¹,   P = F S = μ F + (λ ln J − μ) F⁻ᵀ,
//   dP_iJ/dF_kL = μ δ_ik δ_JL + λ F⁻¹_Ji F⁻¹_Lk + (μ − λ ln J) F⁻¹_Jk F⁻¹_Li.
// The first Piola–Kirchhoff stress P, the stored energy W (the one internal variable MatLib keeps)
// and the tangent depend on the current F only. docs/lmgc90-facts/mailx-2d-large-strain.md §2.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

namespace lmgc::solver::fem {

struct NeoHookeanConstants {
  double mu = 0.0, lambda = 0.0;
};

inline NeoHookeanConstants neo_hookean_constants(double young, double poisson) {
  const double mu = young / (2.0 * (1.0 + poisson));
  const double bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  return {mu, bulk - 2.0 * mu / 3.0};
}

struct NeoHookeanPoint {
  Eigen::Matrix3d stress;   // P
  double energy = 0.0;      // W per unit reference volume
  bool admissible = false;  // J > 0
};

inline NeoHookeanPoint neo_hookean_stress(const NeoHookeanConstants& c, const Eigen::Matrix3d& f) {
  NeoHookeanPoint out;
  const double j = f.determinant();
  if (!(j > 0.0)) return out;
  const double log_j = std::log(j);
  const Eigen::Matrix3d inverse_transpose = f.inverse().transpose();
  out.stress = c.mu * f + (c.lambda * log_j - c.mu) * inverse_transpose;
  out.energy =
      0.5 * c.lambda * log_j * log_j - c.mu * log_j + 0.5 * c.mu * ((f.transpose() * f).trace() - 3.0);
  out.admissible = true;
  return out;
}

// dP_iJ/dF_kL for the components listed in `index` ((i, J) pairs), as a matrix over that list.
template <int N>
Eigen::Matrix<double, N, N> neo_hookean_tangent(const NeoHookeanConstants& c, const Eigen::Matrix3d& f,
                                                const int (&index)[N][2]) {
  const Eigen::Matrix3d g = f.inverse();
  const double log_j = std::log(f.determinant());
  const double shift = c.mu - c.lambda * log_j;
  Eigen::Matrix<double, N, N> t;
  for (int a = 0; a < N; ++a) {
    const int i = index[a][0], big_j = index[a][1];
    for (int b = 0; b < N; ++b) {
      const int k = index[b][0], big_l = index[b][1];
      t(a, b) = (i == k && big_j == big_l ? c.mu : 0.0) + c.lambda * g(big_j, i) * g(big_l, k) +
                shift * g(big_j, k) * g(big_l, i);
    }
  }
  return t;
}

}  // namespace lmgc::solver::fem
