#pragma once
// Fine detection of the rigid 3D cylinder (CYLND) families: a sphere against a cylinder (SPCDx), a
// cylinder against a cylinder (CDCDx: capsules, i.e. segments swept by their radius) and a cylinder
// against a PLANx (CDPLx: the two cap spheres). n points from the antagonist to the candidate.
// docs/lmgc90-facts/numerics.md §5.3; the facts and where we differ from LMGC90:
// docs/lmgc90-facts/cylinders.md.
#include <Eigen/Core>
#include <array>

#include "solver/detection/pair_geometry_3d.hpp"

namespace lmgc::solver {

// A cylinder placed for one detection: centre, unit axis, half-length H (High) and radius.
struct PlacedCylinder {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double half_length = 0.0;
  double radius = 0.0;
};

// SPCDx (mod_SPCDx compute_contact_SPCDx): beside the cylinder (|h| < H) the radial direction, gap
// ρ − r_s − R; beyond an end over the disc (ρ ≤ R) the axis, gap |h| − H − r_s; beyond an end
// outside the disc, the closest point of the rim. Contact point on the sphere (x − r_s n);
// (t, s) by the SPSPx construction with s = n × t, as LMGC90 writes them. False when the gap
// exceeds alert.
bool detect_sphere_cylinder(const Eigen::Vector3d& sphere_centre, double sphere_radius,
                            const PlacedCylinder& cylinder, double alert, ContactGeometry3D& geometry);

// SPDCx (mod_SPDCx compute_contact_SPDCx): a sphere inside a DNLYC, an open tube of radius R and
// half-length H: within the tube's length, the inner wall, gap R − ρ − r_s, n towards the axis
// (LMGC90's end branches have gap errors and are not reproduced: beyond the ends, no contact).
bool detect_sphere_tube(const Eigen::Vector3d& sphere_centre, double sphere_radius,
                        const PlacedCylinder& tube, double alert, ContactGeometry3D& geometry);

// CDCDx (mod_CDCDx compute_contact_CDCDx): capsules. Axes within 1.8° of parallel: up to two points
// (the caps of each over the other's axis); otherwise one point, the closest points of the two
// axis segments. Each point: n along the axis points' difference, gap = their distance − r_cd − r_an,
// the point midway between the two surfaces, (t, s) by comp_rep.
struct CylinderContact {
  int count = 0;
  std::array<ContactGeometry3D, 2> points{};
};
bool detect_cylinder_cylinder(const PlacedCylinder& candidate, const PlacedCylinder& antagonist, double alert,
                              CylinderContact& contact);

}  // namespace lmgc::solver
