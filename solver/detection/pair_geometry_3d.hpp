#pragma once
// Fine detection of the 3D rigid pair families, with LMGC90's local frames (t, n, s): n points from
// the antagonist to the candidate, s = t × n. docs/lmgc90-facts/numerics.md §2 (frames), §5.3 (SPSPx, SPPLx).
#include <Eigen/Core>

namespace lmgc::solver {

struct ContactGeometry3D {
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();         // t
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();          // n, from antagonist to candidate
  Eigen::Vector3d second_tangent = Eigen::Vector3d::Zero();  // s = t × n
  Eigen::Vector3d point = Eigen::Vector3d::Zero();           // contact point, global frame
  double gap = 0.0;                                          // signed distance [m]
};

// LMGC90's `comp_rep` (mod_DiscreteGeometry): the tangents (t, s) of a unit normal.
void tangents_of_normal(const Eigen::Vector3d& normal, Eigen::Vector3d& tangent,
                        Eigen::Vector3d& second_tangent);

// SPSPx's own tangent construction (mod_SPSPx), differing from comp_rep.
void sphere_sphere_tangents(const Eigen::Vector3d& normal, Eigen::Vector3d& tangent,
                            Eigen::Vector3d& second_tangent);

// SPSPx: candidate sphere (centre, radius) against antagonist sphere. False when the gap exceeds
// `alert` or the centres coincide.
bool detect_sphere_sphere(const Eigen::Vector3d& candidate_centre, double candidate_radius,
                          const Eigen::Vector3d& antagonist_centre, double antagonist_radius, double alert,
                          ContactGeometry3D& geometry);

// SPPLx: sphere against a PLANx box of half-axes (axe1, axe2, axe3) along the columns (T, S, N) of
// `plane_frame`, centred at `plane_centre`. False when the gap exceeds `alert`.
bool detect_sphere_plane(const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& plane_centre,
                         const Eigen::Matrix3d& plane_frame, const Eigen::Vector3d& half_axes, double alert,
                         ContactGeometry3D& geometry);

}  // namespace lmgc::solver
