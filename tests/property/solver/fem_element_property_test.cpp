// Properties of every element of solver/fem/ on random shapes (an affine map of the reference
// element with its nodes moved a little, never inverted): the stiffness of linear elasticity is
// symmetric positive semi-definite with exactly the rigid modes in its kernel (3 in 2D, 6 in 3D),
// an affine displacement gives its uniform strain at every Gauss point (the element passes the
// patch test at element level), and the consistent mass sums to ρ times the volume on each
// component.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Eigenvalues>

#include "solver/fem/element_matrices.hpp"
#include "solver/fem/linear_body.hpp"

namespace lmgc::solver::fem {
namespace {

double unit() {
  return *rc::gen::inRange(-1000, 1001) / 1000.0;
}

// A random non-degenerate element: x = A ξ + c, with A well conditioned, nodes moved by at most 5 %
// of the element's size (keeps every Jacobian positive).
template <class E>
NodeCoordinates<E> random_element() {
  constexpr int D = E::kDimension;
  Eigen::Matrix<double, D, D> a = Eigen::Matrix<double, D, D>::Identity();
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) a(i, j) += 0.3 * unit();
  const double scale = std::pow(10.0, 2.0 * unit());
  NodeCoordinates<E> x;
  for (int k = 0; k < E::kNodes; ++k) {
    Point<D> p = a * E::reference_node(k);
    for (int i = 0; i < D; ++i) p(i) += 0.05 * unit();
    x.row(k) = (scale * p).transpose();
  }
  return x;
}

template <class E>
Hypothesis hypothesis_2d_or_3d() {
  if constexpr (E::kDimension == 3) return Hypothesis::three_d;
  return *rc::gen::element(Hypothesis::plane_strain, Hypothesis::plane_stress);
}

template <class E>
void stiffness_has_rigid_kernel(Rule rule) {
  constexpr int D = E::kDimension;
  const NodeCoordinates<E> x = random_element<E>();
  const Hypothesis h = hypothesis_2d_or_3d<E>();
  const double young = std::pow(10.0, 3.0 * unit() + 6.0), poisson = 0.45 * (unit() + 1.0) / 2.0;
  ElementMatrix<E> k;
  RC_ASSERT(stiffness<E>(x, elasticity_matrix(h, young, poisson), h, quadrature<D>(rule), k));
  RC_ASSERT((k - k.transpose()).norm() <= 1e-12 * k.norm());
  const Eigen::SelfAdjointEigenSolver<ElementMatrix<E>> eigen(k);
  const auto& lambda = eigen.eigenvalues();
  const double largest = lambda.maxCoeff();
  const int rigid = D == 2 ? 3 : 6;
  for (int i = 0; i < rigid; ++i) RC_ASSERT(std::abs(lambda(i)) <= 1e-10 * largest);
  RC_ASSERT(lambda(rigid) > 1e-8 * largest);  // no other zero-energy mode
}

template <class E>
void affine_displacement_gives_uniform_strain(Rule rule) {
  constexpr int D = E::kDimension;
  const NodeCoordinates<E> x = random_element<E>();
  const Hypothesis h = hypothesis_2d_or_3d<E>();
  Eigen::Matrix<double, D, D> grad;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) grad(i, j) = unit();
  Eigen::Matrix<double, E::kNodes * D, 1> u;
  for (int k = 0; k < E::kNodes; ++k) u.template segment<D>(D * k) = grad * x.row(k).transpose();
  const QuadratureRule<D> q = quadrature<D>(rule);
  for (int p = 0; p < q.size(); ++p) {
    const auto g = point_geometry<E>(x, q.points[static_cast<std::size_t>(p)],
                                     q.weights[static_cast<std::size_t>(p)], h);
    RC_ASSERT(g.has_value());
    const Eigen::VectorXd strain = strain_matrix<E>(*g, h) * u;
    RC_ASSERT(std::abs(strain(0) - grad(0, 0)) <= 1e-9);
    RC_ASSERT(std::abs(strain(1) - grad(1, 1)) <= 1e-9);
    if constexpr (D == 2) {
      RC_ASSERT(std::abs(strain(2) - (grad(0, 1) + grad(1, 0))) <= 1e-9);
    } else {
      RC_ASSERT(std::abs(strain(2) - grad(2, 2)) <= 1e-9);
      RC_ASSERT(std::abs(strain(3) - (grad(0, 1) + grad(1, 0))) <= 1e-9);
      RC_ASSERT(std::abs(strain(4) - (grad(1, 2) + grad(2, 1))) <= 1e-9);
      RC_ASSERT(std::abs(strain(5) - (grad(2, 0) + grad(0, 2))) <= 1e-9);
    }
  }
}

template <class E>
void consistent_mass_sums_to_the_element_mass(Rule rule) {
  constexpr int D = E::kDimension;
  const NodeCoordinates<E> x = random_element<E>();
  const Hypothesis h = hypothesis_2d_or_3d<E>();
  const double density = 1000.0 * (unit() + 2.0);
  ElementMatrix<E> m;
  RC_ASSERT(consistent_mass<E>(x, density, h, quadrature<D>(rule), m));
  const double v = *volume<E>(x, h, quadrature<D>(rule));
  for (int c = 0; c < D; ++c) {
    double sum = 0.0;
    for (int a = 0; a < E::kNodes; ++a)
      for (int b = 0; b < E::kNodes; ++b) sum += m(D * a + c, D * b + c);
    RC_ASSERT(std::abs(sum - density * v) <= 1e-9 * density * v);
  }
}

RC_GTEST_PROP(FemElement, StiffnessIsSymmetricPsdWithExactlyTheRigidModesInItsKernel, ()) {
  stiffness_has_rigid_kernel<T3>(Rule::triangle_3);
  stiffness_has_rigid_kernel<Q4>(Rule::quad_2x2);
  stiffness_has_rigid_kernel<T6>(Rule::triangle_3);
  stiffness_has_rigid_kernel<Q8>(Rule::quad_3x3);
  stiffness_has_rigid_kernel<TE4>(Rule::tetrahedron_4);
  stiffness_has_rigid_kernel<H8>(Rule::hexahedron_2x2x2);
}

RC_GTEST_PROP(FemElement, AnAffineDisplacementGivesItsUniformStrainAtEveryGaussPoint, ()) {
  affine_displacement_gives_uniform_strain<T3>(Rule::triangle_1);
  affine_displacement_gives_uniform_strain<Q4>(Rule::quad_2x2);
  affine_displacement_gives_uniform_strain<T6>(Rule::triangle_3);
  affine_displacement_gives_uniform_strain<Q8>(Rule::quad_3x3);
  affine_displacement_gives_uniform_strain<TE4>(Rule::tetrahedron_4);
  affine_displacement_gives_uniform_strain<T6>(Rule::triangle_6);
  affine_displacement_gives_uniform_strain<H8>(Rule::hexahedron_2x2x2);
}

RC_GTEST_PROP(FemElement, ConsistentMassSumsToDensityTimesVolume, ()) {
  consistent_mass_sums_to_the_element_mass<T3>(Rule::triangle_3);
  consistent_mass_sums_to_the_element_mass<Q4>(Rule::quad_2x2);
  consistent_mass_sums_to_the_element_mass<T6>(Rule::triangle_6);
  consistent_mass_sums_to_the_element_mass<Q8>(Rule::quad_3x3);
  consistent_mass_sums_to_the_element_mass<TE4>(Rule::tetrahedron_4);
  consistent_mass_sums_to_the_element_mass<H8>(Rule::hexahedron_2x2x2);
}

// 2D Q8 under the 2 × 2 rule has a zero-energy mode beyond the rigid ones (12 strain samples for 13
// deformation modes): the rule an element takes is a catalogue fact, not a free choice.
TEST(FemElement, Q8UnderTwoByTwoHasASpuriousMode) {
  NodeCoordinates<Q8> x;
  for (int k = 0; k < 8; ++k) x.row(k) = Q8::reference_node(k).transpose();
  ElementMatrix<Q8> k;
  ASSERT_TRUE(stiffness<Q8>(x, elasticity_matrix(Hypothesis::plane_strain, 1.0, 0.3),
                            Hypothesis::plane_strain, quadrature<2>(Rule::quad_2x2), k));
  const Eigen::SelfAdjointEigenSolver<ElementMatrix<Q8>> eigen(k);
  int zero = 0;
  for (int i = 0; i < 16; ++i)
    zero += std::abs(eigen.eigenvalues()(i)) < 1e-12 * eigen.eigenvalues().maxCoeff();
  EXPECT_EQ(zero, 4);
}

// 3D elements: a uniaxial strain ε along x of a unit cube stores ½ (λ + 2μ) ε² V (ν = 0.25, E = 1).
TEST(FemElement, TetrahedraAndHexahedronStoreTheUniaxialStrainEnergy) {
  const double young = 1.0, nu = 0.25, eps = 1e-3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  const double expected = 0.5 * (lambda + 2 * mu) * eps * eps;
  NodeCoordinates<H8> x;
  for (int k = 0; k < 8; ++k) x.row(k) = (0.5 * (H8::reference_node(k) + Point<3>::Ones())).transpose();
  ElementMatrix<H8> k;
  ASSERT_TRUE(stiffness<H8>(x, elasticity_matrix(Hypothesis::three_d, young, nu), Hypothesis::three_d,
                            quadrature<3>(Rule::hexahedron_2x2x2), k));
  Eigen::Matrix<double, 24, 1> u = Eigen::Matrix<double, 24, 1>::Zero();
  for (int n = 0; n < 8; ++n) u(3 * n) = eps * x(n, 0);
  EXPECT_NEAR(0.5 * u.dot(k * u), expected, 1e-15);
  NodeCoordinates<TE4> t;
  for (int n = 0; n < 4; ++n) t.row(n) = TE4::reference_node(n).transpose();
  ElementMatrix<TE4> kt;
  ASSERT_TRUE(stiffness<TE4>(t, elasticity_matrix(Hypothesis::three_d, young, nu), Hypothesis::three_d,
                             quadrature<3>(Rule::tetrahedron_4), kt));
  Eigen::Matrix<double, 12, 1> ut = Eigen::Matrix<double, 12, 1>::Zero();
  for (int n = 0; n < 4; ++n) ut(3 * n) = eps * t(n, 0);
  EXPECT_NEAR(0.5 * ut.dot(kt * ut), expected / 6.0, 1e-15);  // the tetrahedron's volume is 1/6
}

// An inverted element is refused: its Jacobian is negative.
TEST(FemElement, AnInvertedElementIsRefused) {
  NodeCoordinates<Q4> x;
  for (int k = 0; k < 4; ++k) x.row(k) = Q4::reference_node(k).transpose();
  x.row(1).swap(x.row(3));  // clockwise
  ElementMatrix<Q4> k;
  EXPECT_FALSE(stiffness<Q4>(x, elasticity_matrix(Hypothesis::plane_strain, 1.0, 0.3),
                             Hypothesis::plane_strain, quadrature<2>(Rule::quad_2x2), k));
}

}  // namespace
}  // namespace lmgc::solver::fem

namespace lmgc::solver::fem {
namespace {

// A T6 whose corners turn counter-clockwise but whose mid-side node is pushed across the element:
// the corner test of lmgc-check cannot see it, the Gauss points can (assemble names the element).
TEST(FemElement, AQuadraticElementInvertedInsideIsNamed) {
  MeshBody body;
  body.dimension = 2;
  body.materials = {Material{1e9, 0.3, 1000.0}};
  body.coordinates = {0,   0,   1,   0,   0, 1,
                      0.5, 0.9, 0.5, 0.5, 0, 0.5};  // node 4 (side 1-2) pushed up to y = 0.9
  MeshElement e;
  e.kind = ElementKind::T6;
  e.nodes = {0, 1, 2, 3, 4, 5};
  body.elements = {e};
  LinearBodyMatrices m;
  std::string error;
  std::size_t failed = 99;
  EXPECT_FALSE(assemble(body, m, error, &failed));
  EXPECT_EQ(failed, 0u);
  EXPECT_NE(error.find("element 1 (T6xxx)"), std::string::npos) << error;
}

}  // namespace
}  // namespace lmgc::solver::fem
