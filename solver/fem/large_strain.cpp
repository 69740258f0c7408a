#include "solver/fem/large_strain.hpp"

#include <array>

#include "solver/fem/element_catalogue.hpp"
#include "solver/fem/element_matrices.hpp"
#include "solver/fem/neo_hookean.hpp"

namespace lmgc::solver::fem {

namespace {

using GradientTangent = Eigen::Matrix<double, 5, 5>;

// The (i, J) of each component of the gradient vector.
constexpr int kComponents[5][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}};

Eigen::Matrix3d as_tensor(const GradientVector& v) {
  Eigen::Matrix3d f = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 5; ++a) f(kComponents[a][0], kComponents[a][1]) = v(a);
  return f;
}

// The material's response at F. False when F is not admissible (det F ≤ 0).
bool material_point(const Material& material, const GradientVector& gradient, LargeStrainPoint& point,
                    GradientTangent* tangent) {
  point.gradient = gradient;
  const Eigen::Matrix3d f = as_tensor(gradient);
  switch (material.law) {
    case MaterialLaw::linear_elastic:  // a small-strain law: mesh_bodies.cpp never pairs it with F
    case MaterialLaw::j2_plasticity:   // evaluated per element (j2_element)
      return false;
    case MaterialLaw::neo_hookean: {
      const NeoHookeanConstants c = neo_hookean_constants(material.young, material.poisson);
      const NeoHookeanPoint p = neo_hookean_stress(c, f);
      if (!p.admissible) return false;
      for (int a = 0; a < 5; ++a) point.stress(a) = p.stress(kComponents[a][0], kComponents[a][1]);
      point.internal.assign(1, p.energy);
      if (tangent) *tangent = neo_hookean_tangent<5>(c, f, kComponents);
      return true;
    }
  }
  return false;
}

template <class E>
struct ElementFrame {
  static constexpr int N = E::kNodes;
  NodeCoordinates<E> x;
  Eigen::Matrix<double, 2 * N, 1> u;
};

template <class E>
ElementFrame<E> element_frame(const MeshBody& body, const MeshElement& element,
                              const Eigen::VectorXd& displacement) {
  ElementFrame<E> frame;
  for (int k = 0; k < E::kNodes; ++k) {
    const auto node = static_cast<Eigen::Index>(element.nodes[static_cast<std::size_t>(k)]);
    for (int c = 0; c < 2; ++c) {
      frame.x(k, c) = body.coordinates[static_cast<std::size_t>(node * 2 + c)];
      frame.u(k * 2 + c) = displacement(node * 2 + c);
    }
  }
  return frame;
}

// B_F: F = I + B_F u (the rows (11, 12, 21, 22, 33)).
template <class E>
Eigen::Matrix<double, 5, 2 * E::kNodes> gradient_matrix(const PointGeometry<E>& g, Hypothesis h) {
  Eigen::Matrix<double, 5, 2 * E::kNodes> b = Eigen::Matrix<double, 5, 2 * E::kNodes>::Zero();
  for (int k = 0; k < E::kNodes; ++k) {
    b(0, 2 * k) = g.gradients(k, 0);
    b(1, 2 * k) = g.gradients(k, 1);
    b(2, 2 * k + 1) = g.gradients(k, 0);
    b(3, 2 * k + 1) = g.gradients(k, 1);
    if (h == Hypothesis::axisymmetric) b(4, 2 * k) = g.values(k) / g.position.x();
  }
  return b;
}

const GradientVector kIdentity = (GradientVector() << 1.0, 0.0, 0.0, 1.0, 1.0).finished();

// Visits the Gauss points of element e: f(point index, geometry, B_F, F). False when a reference
// Jacobian is not positive (refused when the body was assembled).
template <class E, class F>
bool for_each_point(const MeshBody& body, const MeshElement& element, const ElementFrame<E>& frame, F&& f) {
  const QuadratureRule<2> rule = quadrature<2>(element_entry(element.kind).stiffness_rule);
  for (int p = 0; p < rule.size(); ++p) {
    const auto g = point_geometry<E>(frame.x, rule.points[static_cast<std::size_t>(p)],
                                     rule.weights[static_cast<std::size_t>(p)], body.hypothesis);
    if (!g) return false;
    const auto b = gradient_matrix<E>(*g, body.hypothesis);
    const GradientVector gradient = kIdentity + b * frame.u;
    if (!f(p, *g, b, gradient)) return false;
  }
  return true;
}

// Adds an element's force (and stiffness, when triplets are wanted) to the body's at its nodes' dofs.
template <int N>
void scatter(const MeshElement& element, const Eigen::Matrix<double, 2 * N, 1>& fe,
             const Eigen::Matrix<double, 2 * N, 2 * N>& ke, Eigen::VectorXd& internal,
             std::vector<Eigen::Triplet<double>>* triplets) {
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < 2; ++i) {
      const int row = element.nodes[static_cast<std::size_t>(a)] * 2 + i;
      internal(row) += fe(2 * a + i);
      if (triplets)
        for (int c = 0; c < N; ++c)
          for (int j = 0; j < 2; ++j)
            triplets->emplace_back(row, element.nodes[static_cast<std::size_t>(c)] * 2 + j,
                                   ke(2 * a + i, 2 * c + j));
    }
}

// A Q4P0x element of LMGC90's own J2 plasticity: its force, tangent triplets and history.
bool j2_forces(const MeshBody& body, std::size_t e, const Eigen::VectorXd& displacement,
               Eigen::VectorXd& internal, std::vector<Eigen::Triplet<double>>* triplets,
               InvertedElement& inverted, const PointHistory& history) {
  const MeshElement& element = body.elements[e];
  const Material& material = body.materials[static_cast<std::size_t>(element.material)];
  Eigen::Matrix<double, 4, 2> x0;
  Eigen::Matrix<double, 8, 1> u;
  std::array<J2State, 4> begin;
  for (int a = 0; a < 4; ++a) {
    const auto node = static_cast<std::size_t>(element.nodes[static_cast<std::size_t>(a)]);
    for (int c = 0; c < 2; ++c) {
      x0(a, c) = body.coordinates[2 * node + static_cast<std::size_t>(c)];
      u(2 * a + c) = displacement(static_cast<Eigen::Index>(2 * node) + c);
    }
    for (int k = 0; k < kJ2Internal; ++k)
      begin[static_cast<std::size_t>(a)][static_cast<std::size_t>(k)] =
          (*history.begin)[(e * 4 + static_cast<std::size_t>(a)) * kJ2Internal + static_cast<std::size_t>(k)];
  }
  J2ElementResult result;
  int point = 0;
  const J2Failure failure =
      j2_element(x0, u, begin, material.young, material.poisson, material.plasticity,
                 body.hypothesis == Hypothesis::axisymmetric, triplets != nullptr, result, point);
  if (failure != J2Failure::none) {
    inverted = {e, point, failure == J2Failure::return_mapping};
    return false;
  }
  scatter<4>(element, result.force, result.stiffness, internal, triplets);
  for (int a = 0; a < 4; ++a) {
    const std::size_t at = e * 4 + static_cast<std::size_t>(a);
    if (history.end)
      for (int k = 0; k < kJ2Internal; ++k)
        (*history.end)[at * kJ2Internal + static_cast<std::size_t>(k)] =
            result.internal[static_cast<std::size_t>(a)][static_cast<std::size_t>(k)];
    if (history.stress)
      for (int k = 0; k < 4; ++k)
        (*history.stress)[at * 4 + static_cast<std::size_t>(k)] =
            result.stress[static_cast<std::size_t>(a)](k);
  }
  return true;
}

}  // namespace

Eigen::VectorXd reported_internal_force(const MeshBody& body, const std::vector<double>& stress) {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body.dofs()));
  const QuadratureRule<2> rule = quadrature<2>(Rule::quad_2x2);
  for (std::size_t e = 0; e < body.elements.size(); ++e) {
    const MeshElement& element = body.elements[e];
    NodeCoordinates<Q4> x;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 2; ++c)
        x(a, c) =
            body.coordinates[static_cast<std::size_t>(element.nodes[static_cast<std::size_t>(a)] * 2 + c)];
    for (int g = 0; g < 4; ++g) {
      const auto geometry = point_geometry<Q4>(x, rule.points[static_cast<std::size_t>(g)],
                                               rule.weights[static_cast<std::size_t>(g)], body.hypothesis);
      if (!geometry) continue;  // refused when the body was assembled
      // Bᵀσ of the small-strain B (xx, yy, xy[, θθ]), node by node.
      const std::size_t at = (e * 4 + static_cast<std::size_t>(g)) * 4;
      const double sxx = stress[at], syy = stress[at + 1], sxy = stress[at + 2], szz = stress[at + 3];
      const bool hoop = body.hypothesis == Hypothesis::axisymmetric;
      for (int a = 0; a < 4; ++a) {
        const double dx = geometry->gradients(a, 0), dy = geometry->gradients(a, 1);
        const double hoop_term = hoop ? geometry->values(a) / geometry->position.x() * szz : 0.0;
        const int node = element.nodes[static_cast<std::size_t>(a)];
        force(node * 2) += (dx * sxx + dy * sxy + hoop_term) * geometry->weight;
        force(node * 2 + 1) += (dy * syy + dx * sxy) * geometry->weight;
      }
    }
  }
  return force;
}

bool keeps_point_history(const MeshBody& body) {
  for (const Material& m : body.materials)
    if (m.law == MaterialLaw::j2_plasticity) return true;
  return false;
}

std::vector<double> initial_point_history(const MeshBody& body) {
  std::vector<double> history;
  if (!keeps_point_history(body)) return history;
  for (std::size_t e = 0; e < body.elements.size() * 4; ++e)
    history.insert(history.end(), kJ2Initial.begin(), kJ2Initial.end());
  return history;
}

bool large_strain_forces(const MeshBody& body, const Eigen::VectorXd& displacement, Eigen::VectorXd& internal,
                         Eigen::SparseMatrix<double>* tangent, InvertedElement& inverted,
                         const PointHistory& history) {
  internal = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(body.dofs()));
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t e = 0; e < body.elements.size(); ++e) {
    const MeshElement& element = body.elements[e];
    const Material& material = body.materials[static_cast<std::size_t>(element.material)];
    if (material.law == MaterialLaw::j2_plasticity) {
      if (!j2_forces(body, e, displacement, internal, tangent ? &triplets : nullptr, inverted, history))
        return false;
      continue;
    }
    const bool ok = with_element(element.kind, [&](auto shape) {
      using E = decltype(shape);
      if constexpr (E::kDimension != 2) {
        return false;
      } else {
        constexpr int N = E::kNodes;
        const ElementFrame<E> frame = element_frame<E>(body, element, displacement);
        Eigen::Matrix<double, 2 * N, 1> fe = Eigen::Matrix<double, 2 * N, 1>::Zero();
        Eigen::Matrix<double, 2 * N, 2 * N> ke = Eigen::Matrix<double, 2 * N, 2 * N>::Zero();
        LargeStrainPoint point;
        GradientTangent d;
        const bool points_ok = for_each_point<E>(
            body, element, frame, [&](int p, const auto& g, const auto& b, const GradientVector& gradient) {
              if (!material_point(material, gradient, point, tangent ? &d : nullptr)) {
                inverted = {e, p};
                return false;
              }
              fe.noalias() += b.transpose() * point.stress * g.weight;
              if (tangent) ke.noalias() += b.transpose() * d * b * g.weight;
              return true;
            });
        if (!points_ok) return false;
        scatter<N>(element, fe, ke, internal, tangent ? &triplets : nullptr);
        return true;
      }
    });
    if (!ok) {
      if (inverted.element != e) inverted = {e, 0};
      return false;
    }
  }
  if (tangent) {
    const auto n = static_cast<Eigen::Index>(body.dofs());
    tangent->resize(n, n);
    tangent->setFromTriplets(triplets.begin(), triplets.end());
  }
  return true;
}

std::vector<LargeStrainPoint> large_strain_points(const MeshBody& body, const Eigen::VectorXd& displacement,
                                                  std::size_t e) {
  std::vector<LargeStrainPoint> points;
  const MeshElement& element = body.elements[e];
  const Material& material = body.materials[static_cast<std::size_t>(element.material)];
  with_element(element.kind, [&](auto shape) {
    using E = decltype(shape);
    if constexpr (E::kDimension == 2) {
      const ElementFrame<E> frame = element_frame<E>(body, element, displacement);
      const bool ok = for_each_point<E>(body, element, frame,
                                        [&](int, const auto&, const auto&, const GradientVector& gradient) {
                                          LargeStrainPoint point;
                                          if (!material_point(material, gradient, point, nullptr))
                                            return false;
                                          points.push_back(std::move(point));
                                          return true;
                                        });
      if (!ok) points.clear();
    }
  });
  return points;
}

}  // namespace lmgc::solver::fem
