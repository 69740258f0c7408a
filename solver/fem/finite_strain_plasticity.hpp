#pragma once
// LMGC90's own large-strain material on Q4P0x (MODELS.DAT 'kine_ large', 'form_ UpdtL', 'isext no___';
// BULK_BEHAV.DAT ELAS_PLAS with a von Mises criterion): finite-strain J2 plasticity with a
// multiplicative split, stored Cp⁻¹ and isotropic hardening (Simo 1988; Simo & Hughes, Boxes 9.1-9.2),
// the pressure constant over the element from its mean dilatation Θ = v/V. The element routine
// BULK_NL_ISO of mod_a_mecaEF_iso.f90, formula for formula: docs/lmgc90-facts/mailx-2d-large-strain.md §6.
#include <Eigen/Core>
#include <array>
#include <cstdint>

namespace lmgc::solver::fem {

// BULK_BEHAV.DAT 'isoh:' (LMGC90's SEUDUB): σ_y(p) and H = dσ_y/dp.
enum class Hardening : std::uint8_t {
  linear,   // SIG0 + K___ p
  swift,    // C0__ (EPS0 + p)^n___
  hollomon  // K___ p^n___ (0 below p = 1e-10)
};

struct J2Parameters {
  Hardening hardening = Hardening::linear;
  std::array<double, 3>
      coefficients{};  // linear (SIG0, K___), Swift (C0__, EPS0, n___), Hollomon (K___, n___)
};

// Per Gauss point: Cp⁻¹ (xx, yy, xy, zz), the cumulated plastic strain p, the von Mises value q of the
// Kirchhoff deviator (the trial one at an elastic point) — LMGC90's 6 internal variables.
inline constexpr int kJ2Internal = 6;
using J2State = std::array<double, kJ2Internal>;
inline constexpr J2State kJ2Initial{1.0, 1.0, 0.0, 1.0, 0.0, 0.0};

struct J2ElementResult {
  Eigen::Matrix<double, 8, 1> force;      // ∫ Bᵀσ dv
  Eigen::Matrix<double, 8, 8> stiffness;  // material + volumetric + geometric
  std::array<Eigen::Vector4d, 4> stress;  // Cauchy (xx, yy, xy, zz) per Gauss point
  std::array<J2State, 4> internal;        // the state at the displacement
};

enum class J2Failure : std::uint8_t { none, inverted, return_mapping };

// One Q4P0x element: reference nodes x0 (4 × 2, counter-clockwise), nodal displacement u
// (u_x, u_y per node), the states at the beginning of the step per Gauss point (2 × 2 rule, LMGC90's
// order), E, ν; axisymmetric when `axisymmetric`; the stiffness only when `tangent`. On failure
// `failed_point` is the Gauss point.
J2Failure j2_element(const Eigen::Matrix<double, 4, 2>& x0, const Eigen::Matrix<double, 8, 1>& u,
                     const std::array<J2State, 4>& begin, double young, double poisson,
                     const J2Parameters& plasticity, bool axisymmetric, bool tangent, J2ElementResult& out,
                     int& failed_point);

}  // namespace lmgc::solver::fem
