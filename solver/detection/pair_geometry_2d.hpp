#pragma once
// Fine detection of each 2D pair family, as LMGC90 computes it: gap, normal (from antagonist to
// candidate), the point written to Vloc_Rloc, and the lever arms of both sides.
// docs/lmgc90-facts/rigid-2d.md §4 (numerics.md §5.3 for the summary).
#include <Eigen/Core>
#include <array>
#include <span>

namespace lmgc::solver {

struct PairContact2D {
  double gap = 0.0;
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // contact point as LMGC90 writes it
  // Lever arms measured from each contactor's centre (the caller adds the contactor's shift on
  // its body where LMGC90 does).
  Eigen::Vector2d candidate_lever = Eigen::Vector2d::Zero();
  Eigen::Vector2d antagonist_lever = Eigen::Vector2d::Zero();
  int candidate_vertex = 0;    // 1-based vertex of a candidate polygon, 0 when none
  int antagonist_segment = 0;  // 1-based edge of an antagonist polygon, 0 when none
  bool swapped = false;        // PLPLx: the rough antagonist became the candidate
  double length = 1.0;         // contact length used by cohesive laws
};

// A wall (JONCx): rectangle of half-length ax1 along `axis` and half-thickness ax2, rounded ends.
struct Joncx {
  Eigen::Vector2d centre;
  Eigen::Vector2d axis;  // unit
  double half_length, half_width;
};

// A polygon at the detection configuration: vertices (counter-clockwise), outward edge normals
// (normal i is the one of edge v_i → v_i+1) and its contactor centre.
struct PolygonView {
  std::span<const Eigen::Vector2d> vertices;
  std::span<const Eigen::Vector2d> normals;
  Eigen::Vector2d centre;
};

// DKDKx: two disks.
bool disk_disk(const Eigen::Vector2d& candidate, double candidate_radius, const Eigen::Vector2d& antagonist,
               double antagonist_radius, PairContact2D& out);
// DKKDx: a disk inside a hollow disk (xKSID) of radius `outer`.
bool disk_in_hollow_disk(const Eigen::Vector2d& disk, double radius, const Eigen::Vector2d& hollow,
                         double outer, PairContact2D& out);
// DKJCx: a disk against a JONCx.
bool disk_joncx(const Eigen::Vector2d& disk, double radius, const Joncx& wall, PairContact2D& out);
// DKPLx: a disk against a polygon; false when farther than `alert`.
bool disk_polygon(const Eigen::Vector2d& disk, double radius, const PolygonView& polygon, double alert,
                  PairContact2D& out);
// PLJCx: the vertices of a polygon against a JONCx; up to two contacts closer than `alert`.
int polygon_joncx(const PolygonView& polygon, const Joncx& wall, double alert,
                  std::array<PairContact2D, 2>& out);
// PLPLx: J.J. Moreau's shadow-overlap detection between two convex polygons; up to two contacts.
int polygon_polygon(const PolygonView& candidate, const PolygonView& antagonist, double alert,
                    std::array<PairContact2D, 2>& out);
// PTPT2: two points; the gap is their distance.
bool point_point(const Eigen::Vector2d& candidate, const Eigen::Vector2d& antagonist, PairContact2D& out);

double cross_2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace lmgc::solver
