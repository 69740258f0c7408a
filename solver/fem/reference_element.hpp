#pragma once
// The isoparametric elements of LMGC90's MAILx bodies on their reference shapes: node positions,
// shape functions and their gradients, in 2D (T3xxx, Q4xxx, T6xxx, Q8xxx) and 3D (TE4xx, H8xxx).
// An element is a struct with kDimension, kNodes, reference_node(k), values(ξ) and gradients(ξ);
// the routines of element_matrices.hpp are templates over it, so a new element is one struct here
// and one row of the element catalogue (element_catalogue.cpp). Node order and reference shapes:
// docs/lmgc90-facts/mailx-2d.md §1.
#include <Eigen/Core>
#include <array>

namespace lmgc::solver::fem {

template <int D>
using Point = Eigen::Matrix<double, D, 1>;

// Linear triangle on (0,0), (1,0), (0,1): N = (1 − ξ − η, ξ, η).
struct T3 {
  static constexpr int kDimension = 2, kNodes = 3;
  static Point<2> reference_node(int k) {
    constexpr double n[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    return {n[k][0], n[k][1]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<2>& p) {
    return {1.0 - p.x() - p.y(), p.x(), p.y()};
  }
  static Eigen::Matrix<double, kNodes, 2> gradients(const Point<2>&) {
    Eigen::Matrix<double, kNodes, 2> g;
    g << -1, -1, 1, 0, 0, 1;
    return g;
  }
};

// Bilinear quadrilateral on [−1, 1]², nodes counter-clockwise from (−1, −1).
struct Q4 {
  static constexpr int kDimension = 2, kNodes = 4;
  static Point<2> reference_node(int k) {
    constexpr double n[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    return {n[k][0], n[k][1]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<2>& p) {
    Eigen::Matrix<double, kNodes, 1> v;
    for (int k = 0; k < kNodes; ++k) {
      const Point<2> a = reference_node(k);
      v(k) = 0.25 * (1 + a.x() * p.x()) * (1 + a.y() * p.y());
    }
    return v;
  }
  static Eigen::Matrix<double, kNodes, 2> gradients(const Point<2>& p) {
    Eigen::Matrix<double, kNodes, 2> g;
    for (int k = 0; k < kNodes; ++k) {
      const Point<2> a = reference_node(k);
      g(k, 0) = 0.25 * a.x() * (1 + a.y() * p.y());
      g(k, 1) = 0.25 * a.y() * (1 + a.x() * p.x());
    }
    return g;
  }
};

// Quadratic triangle: the T3 vertices, then the mid-sides (1-2, 2-3, 3-1).
struct T6 {
  static constexpr int kDimension = 2, kNodes = 6;
  static Point<2> reference_node(int k) {
    constexpr double n[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    return {n[k][0], n[k][1]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<2>& p) {
    const double l1 = 1.0 - p.x() - p.y(), l2 = p.x(), l3 = p.y();
    Eigen::Matrix<double, kNodes, 1> v;
    v << l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), l3 * (2 * l3 - 1), 4 * l1 * l2, 4 * l2 * l3, 4 * l3 * l1;
    return v;
  }
  static Eigen::Matrix<double, kNodes, 2> gradients(const Point<2>& p) {
    const double l1 = 1.0 - p.x() - p.y(), l2 = p.x(), l3 = p.y();
    // dl1 = (−1, −1), dl2 = (1, 0), dl3 = (0, 1).
    Eigen::Matrix<double, kNodes, 2> g;
    g << -(4 * l1 - 1), -(4 * l1 - 1),  //
        4 * l2 - 1, 0,                  //
        0, 4 * l3 - 1,                  //
        4 * (l1 - l2), -4 * l2,         //
        4 * l3, 4 * l2,                 //
        -4 * l3, 4 * (l1 - l3);
    return g;
  }
};

// Serendipity quadrilateral: the Q4 corners, then the mid-sides (1-2, 2-3, 3-4, 4-1).
struct Q8 {
  static constexpr int kDimension = 2, kNodes = 8;
  static Point<2> reference_node(int k) {
    constexpr double n[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    return {n[k][0], n[k][1]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<2>& p) {
    Eigen::Matrix<double, kNodes, 1> v;
    for (int k = 0; k < kNodes; ++k) {
      const Point<2> a = reference_node(k);
      if (k < 4)
        v(k) = 0.25 * (1 + a.x() * p.x()) * (1 + a.y() * p.y()) * (a.x() * p.x() + a.y() * p.y() - 1);
      else if (a.x() == 0)
        v(k) = 0.5 * (1 - p.x() * p.x()) * (1 + a.y() * p.y());
      else
        v(k) = 0.5 * (1 + a.x() * p.x()) * (1 - p.y() * p.y());
    }
    return v;
  }
  static Eigen::Matrix<double, kNodes, 2> gradients(const Point<2>& p) {
    Eigen::Matrix<double, kNodes, 2> g;
    for (int k = 0; k < kNodes; ++k) {
      const Point<2> a = reference_node(k);
      const double x = p.x(), y = p.y();
      if (k < 4) {
        g(k, 0) = 0.25 * a.x() * (1 + a.y() * y) * (2 * a.x() * x + a.y() * y);
        g(k, 1) = 0.25 * a.y() * (1 + a.x() * x) * (a.x() * x + 2 * a.y() * y);
      } else if (a.x() == 0) {
        g(k, 0) = -x * (1 + a.y() * y);
        g(k, 1) = 0.5 * a.y() * (1 - x * x);
      } else {
        g(k, 0) = 0.5 * a.x() * (1 - y * y);
        g(k, 1) = -y * (1 + a.x() * x);
      }
    }
    return g;
  }
};

// Linear tetrahedron on (0,0,0), (1,0,0), (0,1,0), (0,0,1).
struct TE4 {
  static constexpr int kDimension = 3, kNodes = 4;
  static Point<3> reference_node(int k) {
    constexpr double n[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    return {n[k][0], n[k][1], n[k][2]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<3>& p) {
    return {1.0 - p.x() - p.y() - p.z(), p.x(), p.y(), p.z()};
  }
  static Eigen::Matrix<double, kNodes, 3> gradients(const Point<3>&) {
    Eigen::Matrix<double, kNodes, 3> g;
    g << -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    return g;
  }
};

// Trilinear hexahedron on [−1, 1]³: the bottom face (ζ = −1) counter-clockwise, then the top.
struct H8 {
  static constexpr int kDimension = 3, kNodes = 8;
  static Point<3> reference_node(int k) {
    constexpr double n[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    return {n[k][0], n[k][1], n[k][2]};
  }
  static Eigen::Matrix<double, kNodes, 1> values(const Point<3>& p) {
    Eigen::Matrix<double, kNodes, 1> v;
    for (int k = 0; k < kNodes; ++k) {
      const Point<3> a = reference_node(k);
      v(k) = 0.125 * (1 + a.x() * p.x()) * (1 + a.y() * p.y()) * (1 + a.z() * p.z());
    }
    return v;
  }
  static Eigen::Matrix<double, kNodes, 3> gradients(const Point<3>& p) {
    Eigen::Matrix<double, kNodes, 3> g;
    for (int k = 0; k < kNodes; ++k) {
      const Point<3> a = reference_node(k);
      g(k, 0) = 0.125 * a.x() * (1 + a.y() * p.y()) * (1 + a.z() * p.z());
      g(k, 1) = 0.125 * a.y() * (1 + a.x() * p.x()) * (1 + a.z() * p.z());
      g(k, 2) = 0.125 * a.z() * (1 + a.x() * p.x()) * (1 + a.y() * p.y());
    }
    return g;
  }
};

}  // namespace lmgc::solver::fem
