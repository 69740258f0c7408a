#pragma once
// Element matrices of linear isotropic elasticity on any element of reference_element.hpp:
// the strain–displacement matrix B at a point, the elasticity matrix D of each 2D hypothesis (plane
// strain, plane stress, axisymmetric) and of 3D, the stiffness ∫ Bᵀ D B and the consistent and
// lumped masses ∫ ρ Nᵀ N. The dofs of an element are its nodes' in order, each node's components
// together (u_x, u_y[, u_z]). Strains are Voigt vectors with engineering shears: 2D (xx, yy, xy),
// axisymmetric (rr, zz, rz, θθ), 3D (xx, yy, zz, xy, yz, zx). docs/lmgc90-facts/mailx-2d.md §2-§4.
#include <Eigen/Core>
#include <Eigen/LU>
#include <numbers>
#include <optional>

#include "solver/fem/quadrature.hpp"
#include "solver/fem/reference_element.hpp"

namespace lmgc::solver::fem {

enum class Hypothesis : std::uint8_t { plane_strain, plane_stress, axisymmetric, three_d };

inline int strain_size(Hypothesis h) {
  switch (h) {
    case Hypothesis::plane_strain:
    case Hypothesis::plane_stress:
      return 3;
    case Hypothesis::axisymmetric:
      return 4;
    case Hypothesis::three_d:
      return 6;
  }
  return 0;
}

// D of linear isotropic elasticity (Young's modulus E, Poisson's ratio ν) in the strain order above,
// written as LMGC90 writes it (D_SOLID_ISO, mailx-2d.md §2.2): c(1 − ν), cν and c(1 − 2ν)/2 with
// c = E/((1 − 2ν)(1 + ν)); plane stress c = E/(1 − ν²).
inline Eigen::MatrixXd elasticity_matrix(Hypothesis h, double young, double poisson) {
  const double e = young, nu = poisson;
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(strain_size(h), strain_size(h));
  const double c = e / ((1.0 - 2.0 * nu) * (1.0 + nu));
  const double normal = c * (1.0 - nu), coupling = c * nu, shear = c * (1.0 - 2.0 * nu) / 2.0;
  switch (h) {
    case Hypothesis::plane_stress: {
      const double s = e / (1.0 - nu * nu);
      d << s, s * nu, 0, s * nu, s, 0, 0, 0, s * (1.0 - nu) / 2.0;
      break;
    }
    case Hypothesis::plane_strain:
      d << normal, coupling, 0, coupling, normal, 0, 0, 0, shear;
      break;
    case Hypothesis::axisymmetric:
      // (rr, zz, rz, θθ): the normal components couple by cν.
      d << normal, coupling, 0, coupling,  //
          coupling, normal, 0, coupling,   //
          0, 0, shear, 0,                  //
          coupling, coupling, 0, normal;
      break;
    case Hypothesis::three_d:
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) d(i, j) = coupling;
        d(i, i) = normal;
        d(i + 3, i + 3) = shear;
      }
      break;
  }
  return d;
}

// LMGC90's 2π in axisymmetric integrals: the decimal 6.2831853 (mailx-2d.md §2.4).
inline constexpr double kAxisymmetricTwoPi = 6.2831853;

// What an element sees at one Gauss point: shape values, physical gradients, the volume weight
// (|J| w, times 2π r in axisymmetry: the integral over the full revolution), the point's position.
// A Jacobian that is not positive is refused (LMGC90 takes det J as it comes and integrates a
// clockwise element with negative stiffness and mass, mailx-2d.md §1.4; lmgc-check reports it).
template <class E>
struct PointGeometry {
  Eigen::Matrix<double, E::kNodes, 1> values;
  Eigen::Matrix<double, E::kNodes, E::kDimension> gradients;
  double weight = 0.0;
  double jacobian = 0.0;
  Point<E::kDimension> position;
};

template <class E>
using NodeCoordinates = Eigen::Matrix<double, E::kNodes, E::kDimension>;

// Geometry at reference point ξ; nullopt when the Jacobian is not positive (an inverted or
// degenerate element).
template <class E>
std::optional<PointGeometry<E>> point_geometry(const NodeCoordinates<E>& x, const Point<E::kDimension>& xi,
                                               double weight, Hypothesis h) {
  constexpr int D = E::kDimension;
  PointGeometry<E> g;
  g.values = E::values(xi);
  const Eigen::Matrix<double, E::kNodes, D> reference = E::gradients(xi);
  const Eigen::Matrix<double, D, D> j = x.transpose() * reference;  // ∂x_i/∂ξ_j
  g.jacobian = j.determinant();
  if (!(g.jacobian > 0.0)) return std::nullopt;
  g.gradients = reference * j.inverse();
  g.position = x.transpose() * g.values;
  g.weight = g.jacobian * weight;
  if (h == Hypothesis::axisymmetric) g.weight *= kAxisymmetricTwoPi * g.position.x();
  return g;
}

// B: strain = B u_e.
template <class E>
Eigen::MatrixXd strain_matrix(const PointGeometry<E>& g, Hypothesis h) {
  constexpr int D = E::kDimension, N = E::kNodes;
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(strain_size(h), N * D);
  for (int k = 0; k < N; ++k) {
    const double dx = g.gradients(k, 0), dy = g.gradients(k, 1);
    if constexpr (D == 2) {
      b(0, 2 * k) = dx;
      b(1, 2 * k + 1) = dy;
      b(2, 2 * k) = dy;
      b(2, 2 * k + 1) = dx;
      if (h == Hypothesis::axisymmetric) b(3, 2 * k) = g.values(k) / g.position.x();  // u_r / r
    } else {
      const double dz = g.gradients(k, 2);
      b(0, 3 * k) = dx;
      b(1, 3 * k + 1) = dy;
      b(2, 3 * k + 2) = dz;
      b(3, 3 * k) = dy;
      b(3, 3 * k + 1) = dx;
      b(4, 3 * k + 1) = dz;
      b(4, 3 * k + 2) = dy;
      b(5, 3 * k) = dz;
      b(5, 3 * k + 2) = dx;
    }
  }
  return b;
}

template <class E>
using ElementMatrix = Eigen::Matrix<double, E::kNodes * E::kDimension, E::kNodes * E::kDimension>;

// K_e = Σ_g Bᵀ D B w_g. False when a Gauss point's Jacobian is not positive.
template <class E>
bool stiffness(const NodeCoordinates<E>& x, const Eigen::MatrixXd& d, Hypothesis h,
               const QuadratureRule<E::kDimension>& rule, ElementMatrix<E>& k) {
  k.setZero();
  for (int p = 0; p < rule.size(); ++p) {
    const auto g = point_geometry<E>(x, rule.points[static_cast<std::size_t>(p)],
                                     rule.weights[static_cast<std::size_t>(p)], h);
    if (!g) return false;
    const Eigen::MatrixXd b = strain_matrix<E>(*g, h);
    k.noalias() += b.transpose() * d * b * g->weight;
  }
  return true;
}

// Consistent mass M_e = Σ_g ρ Nᵀ N w_g, on each component.
template <class E>
bool consistent_mass(const NodeCoordinates<E>& x, double density, Hypothesis h,
                     const QuadratureRule<E::kDimension>& rule, ElementMatrix<E>& m) {
  constexpr int D = E::kDimension;
  m.setZero();
  for (int p = 0; p < rule.size(); ++p) {
    const auto g = point_geometry<E>(x, rule.points[static_cast<std::size_t>(p)],
                                     rule.weights[static_cast<std::size_t>(p)], h);
    if (!g) return false;
    const auto nn = (g->values * g->values.transpose() * (density * g->weight)).eval();
    for (int a = 0; a < E::kNodes; ++a)
      for (int b = 0; b < E::kNodes; ++b)
        for (int c = 0; c < D; ++c) m(D * a + c, D * b + c) += nn(a, b);
  }
  return true;
}

// The element's volume (area in plane 2D; the volume of revolution in axisymmetry).
template <class E>
std::optional<double> volume(const NodeCoordinates<E>& x, Hypothesis h,
                             const QuadratureRule<E::kDimension>& rule) {
  double v = 0.0;
  for (int p = 0; p < rule.size(); ++p) {
    const auto g = point_geometry<E>(x, rule.points[static_cast<std::size_t>(p)],
                                     rule.weights[static_cast<std::size_t>(p)], h);
    if (!g) return std::nullopt;
    v += g->weight;
  }
  return v;
}

}  // namespace lmgc::solver::fem
