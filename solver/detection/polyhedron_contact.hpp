#pragma once
// Fine detection of convex polyhedra (POLYR): against a PLANx (PRPLx) and against another POLYR
// (PRPRx, Cundall's common plane). Up to four contact points per pair, all sharing one local frame
// (t, n, s) with n from the antagonist to the candidate. docs/lmgc90-facts/numerics.md §5.3 (PRPRx CpCundall,
// PRPLx); the facts and where we differ from LMGC90: docs/lmgc90-facts/polyhedra.md.
#include <Eigen/Core>
#include <array>
#include <span>

#include "solver/bodies/polyhedron.hpp"
#include "solver/detection/pair_geometry_3d.hpp"

namespace lmgc::solver {

// A polyhedron placed in the global frame for one detection: vertices and face normals.
struct PlacedPolyhedron {
  const Polyhedron* shape = nullptr;
  std::span<const Eigen::Vector3d> vertices;  // global
  std::span<const Eigen::Vector3d> normals;   // global, outward, one per face
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

inline constexpr int kMaxPolyhedronPoints = 4;

struct PolyhedronContact {
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();         // t
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();          // n, antagonist -> candidate
  Eigen::Vector3d second_tangent = Eigen::Vector3d::Zero();  // s
  int count = 0;
  std::array<Eigen::Vector3d, kMaxPolyhedronPoints> points{};
  std::array<double, kMaxPolyhedronPoints> gaps{};
  std::array<int, kMaxPolyhedronPoints> vertices{};  // PRPLx: candidate vertex (0-based); PRPRx: -1
  double area = 0.0;  // PRPRx: area of the overlap of the two projected bands (0 for a point or a line)
};

// PRPLx (mod_PRPLx compute_contact_PRPLx): the plane is a box of half-axes (a1, a2, a3) along the
// columns (T, S, N) of `plane_frame`. n = ±N towards the polyhedron's centre; a vertex inside the
// face rectangle grown by `alert` with gap n·(x − centre) − a3 < alert is a contact point; the four
// smallest gaps are kept. (t, s) = (T, S), or (−T, −S) when n = −N, as LMGC90 writes them.
bool detect_polyhedron_plane(const PlacedPolyhedron& polyhedron, const Eigen::Vector3d& plane_centre,
                             const Eigen::Matrix3d& plane_frame, const Eigen::Vector3d& half_axes,
                             double alert, PolyhedronContact& contact);

// PRPRx by Cundall's common plane (mod_PRPRx DETECTION_COMMON_PLANE): a face-normal separating test
// gives the starting normal, Cundall's tilt search maximises the separation gap(n) = min_cd n·x −
// max_an n·x, the vertices of each body within a band of the plane are projected on it and the
// corners of the overlap of their two hulls (at most four, the sharpest) are the contact points.
// Each point's gap is the distance along n between the two surfaces there. `reference_size` is the
// smallest POLYR radius of the scene (the scale of Cundall's convergence test).
bool detect_polyhedron_polyhedron(const PlacedPolyhedron& candidate, const PlacedPolyhedron& antagonist,
                                  double alert, double reference_size, int max_iterations,
                                  PolyhedronContact& contact);

// SPPRx (mod_SPPRx DETECTION_SPPRx): a sphere (centre, radius) against a convex polyhedron. The
// contact point is the point of the polyhedron's surface nearest to the centre; n goes from it to
// the centre, gap = distance − radius. A centre inside the polyhedron takes the least deep face:
// n = its normal, gap = (signed distance to its plane) − radius. (t, s) by comp_rep. False when the
// gap exceeds `alert`.
bool detect_sphere_polyhedron(const Eigen::Vector3d& centre, double radius,
                              const PlacedPolyhedron& polyhedron, double alert, ContactGeometry3D& geometry);

}  // namespace lmgc::solver
