#pragma once
// PTPT3: links between PT3Dx points of different RBDY3 bodies (wires, rods, glue). Which points
// are linked is decided once, in the reference configuration; each step the link's geometry is
// the segment between the two points. spec: contact-laws.md §3.4, numerics.md §5.3 (PTPT: gap =
// distance); LMGC90 contact_3D/mod_PTPT3.f90 compute_box (:340-693), compute_contact (:1018-1524).
#include <Eigen/Core>
#include <vector>

#include "solver/detection/pair_geometry_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

// The PTPT3 links of a scene: for each PT3Dx (candidate, in contactor order) and each later PT3Dx
// of another body (antagonist) with a `$seety` row read that way, a link when their distance in
// the reference configuration (BODIES.DAT centre + initial frame × offset, cooref) is within the
// row's alert. That distance is the link's reference length (nonuc0, the wires' gapREF). The
// PTPT3_NETWORK.DAT file and periodic links are not read.
std::vector<PointLink3D> link_points_3d(const Scene3D& scene);

// PTPT3's frame and gap for points `candidate` and `antagonist`: n from the antagonist to the
// candidate, gap = distance, point = midpoint, t by mod_PTPT3's rule (a fixed axis when n is along
// an axis; else the unit vector orthogonal to n with two equal components), s = t × n. Coincident
// points (distance < 1e-20) give the global axes and gap 0, as LMGC90's glued nodes.
ContactGeometry3D point_point_geometry(const Eigen::Vector3d& candidate, const Eigen::Vector3d& antagonist);

}  // namespace lmgc::solver
