#pragma once
// Gauss rules on the reference shapes of reference_element.hpp: points and weights, in the order
// LMGC90 numbers its Gauss points (GPV files list them in that order). Which rule an element takes
// for stiffness and for mass is a column of the element catalogue (element_catalogue.cpp);
// docs/lmgc90-facts/mailx-2d.md §1.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "solver/fem/reference_element.hpp"

namespace lmgc::solver::fem {

template <int D>
struct QuadratureRule {
  std::vector<Point<D>> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(points.size()); }
};

enum class Rule : std::uint8_t {
  triangle_1,  // centroid
  triangle_3,  // interior points (1/6, 1/6), (2/3, 1/6), (1/6, 2/3)
  triangle_6,
  quad_2x2,
  quad_3x3,
  tetrahedron_1,
  tetrahedron_4,
  hexahedron_2x2x2,
};

// Gauss points of a tensor rule on [−1, 1]ⁿ: LMGC90 writes the abscissae and weights as 15-digit
// decimals (mailx-2d.md §1.3); the same decimals here keep its element matrices to the last bit.
inline std::vector<double> gauss_line(int n, std::vector<double>& weights) {
  if (n == 2) {
    const double a = 0.577350269189626;
    weights = {1.0, 1.0};
    return {-a, a};
  }
  const double a = 0.774596669241483;
  weights = {0.555555555555556, 0.888888888888889, 0.555555555555556};
  return {-a, 0.0, a};
}

template <int D>
QuadratureRule<D> quadrature(Rule rule) {
  QuadratureRule<D> q;
  const auto add = [&](const Point<D>& p, double w) {
    q.points.push_back(p);
    q.weights.push_back(w);
  };
  if constexpr (D == 2) {
    switch (rule) {
      case Rule::triangle_1:
        add(Point<2>(1.0 / 3.0, 1.0 / 3.0), 0.5);
        break;
      case Rule::triangle_3:
        add(Point<2>(1.0 / 6.0, 1.0 / 6.0), 1.0 / 6.0);
        add(Point<2>(2.0 / 3.0, 1.0 / 6.0), 1.0 / 6.0);
        add(Point<2>(1.0 / 6.0, 2.0 / 3.0), 1.0 / 6.0);
        break;
      case Rule::triangle_6: {
        const double a = 0.445948490915965, b = 0.091576213509771;
        const double wa = 0.111690794839005, wb = 0.054975871827661;
        add(Point<2>(a, a), wa);
        add(Point<2>(1 - 2 * a, a), wa);
        add(Point<2>(a, 1 - 2 * a), wa);
        add(Point<2>(b, b), wb);
        add(Point<2>(1 - 2 * b, b), wb);
        add(Point<2>(b, 1 - 2 * b), wb);
        break;
      }
      case Rule::quad_2x2:
      case Rule::quad_3x3: {
        std::vector<double> w;
        const std::vector<double> x = gauss_line(rule == Rule::quad_2x2 ? 2 : 3, w);
        for (std::size_t j = 0; j < x.size(); ++j)
          for (std::size_t i = 0; i < x.size(); ++i) add(Point<2>(x[i], x[j]), w[i] * w[j]);
        break;
      }
      default:
        break;
    }
  } else {
    switch (rule) {
      case Rule::tetrahedron_1:
        add(Point<3>(0.25, 0.25, 0.25), 1.0 / 6.0);
        break;
      case Rule::tetrahedron_4: {
        const double a = (5.0 - std::sqrt(5.0)) / 20.0, b = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
        add(Point<3>(a, a, a), 1.0 / 24.0);
        add(Point<3>(a, a, b), 1.0 / 24.0);
        add(Point<3>(a, b, a), 1.0 / 24.0);
        add(Point<3>(b, a, a), 1.0 / 24.0);
        break;
      }
      case Rule::hexahedron_2x2x2: {
        std::vector<double> w;
        const std::vector<double> x = gauss_line(2, w);
        for (std::size_t k = 0; k < 2; ++k)
          for (std::size_t j = 0; j < 2; ++j)
            for (std::size_t i = 0; i < 2; ++i) add(Point<3>(x[i], x[j], x[k]), w[i] * w[j] * w[k]);
        break;
      }
      default:
        break;
    }
  }
  return q;
}

}  // namespace lmgc::solver::fem
