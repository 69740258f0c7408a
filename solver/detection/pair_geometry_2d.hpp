#pragma once
// Fine detection of each 2D pair family: gap, normal (from antagonist to candidate), contact point.
// spec: numerics.md §5.3. Shapes are given in world coordinates at the detection configuration.
#include <Eigen/Core>
#include <array>
#include <span>

namespace lmgc::solver {

struct PairContact2D {
  double gap = 0.0;
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  int candidate_vertex = 0;    // 1-based vertex of a candidate polygon, 0 when not a vertex contact
  int antagonist_segment = 0;  // 1-based edge of an antagonist polygon
  double length = 1.0;         // contact length for cohesive laws (2D: 1 unless an edge contact)
};

// A wall (JONCx): rectangle of half-length ax1 along `axis` and half-thickness ax2, rounded ends.
struct Joncx {
  Eigen::Vector2d centre;
  Eigen::Vector2d axis;  // unit
  double half_length, half_width;
};

// DKDKx: two disks.
bool disk_disk(const Eigen::Vector2d& candidate, double candidate_radius, const Eigen::Vector2d& antagonist,
               double antagonist_radius, PairContact2D& out);
// DKKDx: a disk inside a hollow disk (xKSID) of radius `outer`.
bool disk_in_hollow_disk(const Eigen::Vector2d& disk, double radius, const Eigen::Vector2d& hollow, double outer,
                         PairContact2D& out);
// DKJCx: a disk against a JONCx.
bool disk_joncx(const Eigen::Vector2d& disk, double radius, const Joncx& wall, PairContact2D& out);
// DKPLx: a disk against a convex polygon (vertices counter-clockwise).
bool disk_polygon(const Eigen::Vector2d& disk, double radius, std::span<const Eigen::Vector2d> polygon,
                  PairContact2D& out);
// PLJCx: the vertices of a polygon against a JONCx; up to two contacts within `alert`.
int polygon_joncx(std::span<const Eigen::Vector2d> polygon, const Joncx& wall, double alert,
                  std::array<PairContact2D, 2>& out);
// PLPLx: two convex polygons; up to two contacts within `alert` (vertex of one against an edge
// of the other).
int polygon_polygon(std::span<const Eigen::Vector2d> candidate, std::span<const Eigen::Vector2d> antagonist,
                    double alert, std::array<PairContact2D, 2>& out);
// PTPT2: two points.
bool point_point(const Eigen::Vector2d& candidate, const Eigen::Vector2d& antagonist, PairContact2D& out);

}  // namespace lmgc::solver
