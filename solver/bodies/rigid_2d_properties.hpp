#pragma once
// What LMGC90 computes from an RBDY2 body of BODIES.DAT before anything runs: equivalent radius
// avrd and gyration radius gyrd when given as 0, the centre of inertia when the node is at the
// origin, contactor shifts relative to it, polygon vertices relative to their centroid.
// docs/lmgc90-facts/datbox-inputs.md §1.4 "Read vs written"; LMGC90 mod_RBDY2 read_bodies, mod_a_BDARY_*.
#include <Eigen/Core>
#include <vector>

#include "grammar/bodies/ast.hpp"

namespace lmgc::solver {

// Per-contactor values: area (negative for xKSID), equivalent radius, gyration radius, shift.
struct ContactorInertia2D {
  double area = 0.0;
  double radius = 0.0;           // "rdg": sqrt(area / π)
  double gyration_radius = 0.0;  // "grdg"
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
};

ContactorInertia2D contactor_inertia_2d(const grammar::Contactor& contactor);

// A polygon's outer radius as LMGC90 computes it (mod_POLYG): the largest distance from the mean
// of its vertices (not its centroid) to a vertex. Its rough detection and PLPLx's pre-test use it.
double polygon_outer_radius(const std::vector<Eigen::Vector2d>& vertices);

// The contactors of a body as LMGC90 holds them after reading it: each one's offset from the
// body's centre, and a polygon's vertices about its own centroid (mod_POLYG vertex_ref). Taken
// before the card is written back: a cluster's polygon card holds vertex + offset, and reading the
// two apart again would not give the same doubles.
struct RigidContactorFrames2D {
  std::vector<Eigen::Vector2d> shift;                          // per contactor
  std::vector<std::vector<Eigen::Vector2d>> polygon_vertices;  // per contactor (POLYG only)
};

// Rewrites `body` (RBDY2) as LMGC90 holds it after reading: fills avrd/gyrd when either is 0,
// moves the node to the centre of inertia when all its coordinates are 0, recentres shifts and
// polygon vertices. Its BODIES.OUT echo is then LMGC90's. `frames`, when given, receives the
// contactors' offsets and polygon vertices.
void normalise_rigid_body_2d(grammar::Body& body, RigidContactorFrames2D* frames = nullptr);

}  // namespace lmgc::solver
