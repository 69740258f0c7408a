#pragma once
// What LMGC90 computes from an RBDY2 body of BODIES.DAT before anything runs: equivalent radius
// avrd and gyration radius gyrd when given as 0, the centre of inertia when the node is at the
// origin, contactor shifts relative to it, polygon vertices relative to their centroid.
// spec: datbox-inputs.md §1.4 "Read vs written"; LMGC90 mod_RBDY2 read_bodies, mod_a_BDARY_*.
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

// Rewrites `body` (RBDY2) as LMGC90 holds it after reading: fills avrd/gyrd when either is 0,
// moves the node to the centre of inertia when all its coordinates are 0, recentres shifts and
// polygon vertices. Its BODIES.OUT echo is then LMGC90's.
void normalise_rigid_body_2d(grammar::Body& body);

}  // namespace lmgc::solver
