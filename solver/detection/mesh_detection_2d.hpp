#pragma once
// Contact detection with a side on a mesh, as LMGC90's modules do it
// (docs/lmgc90-facts/mailx-2d-contact.md §5-§7):
// - CLALp: each CLxxx point against the ALpxx polylines it sees, at most one contact per point, on
//   the segment next to the polyline's closest node (a vertex of the polyline gets its own normal);
// - CLJCx: each CLxxx point against the first JONCx whose box holds it;
// - PLALp: the vertices of a rigid POLYG against each segment of an ALpxx, one contact per vertex and
//   segment;
// - P2P2L: the pairs of PT2DL points made at the run's first detection (PointPairs2D), each step;
// - DKALp: a rigid DISKx against each segment of an ALpxx (its end node beyond its ends), one contact
//   per disk and segment;
// - DKDKL: a rigid DISKx against each DISKL within the alert.
// Positions are the detection configuration (coorTT): x_ref + X_begin + (1 − θ)h V_begin for mesh
// nodes, the rigid bodies' coordinates as detect_contacts_2d takes them.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "solver/model/large_array.hpp"
#include "solver/model/mesh_contact_2d.hpp"
#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

// Appends the interactions of the mesh families (CLALp, CLJCx, P2P2L, PLALp, DKALp, then DKDKL:
// LMGC90's sweep order) to `out`, each with its local frame, gap, point, nodes' weights
// (mesh_contact_2d.hpp) and relative velocity at the beginning of the step. `node_coordinates[m]`:
// mesh m's nodes (x, y each). `point_pairs`: the run's P2P2L pairs, made here the first time.
void detect_mesh_contacts_2d(const Scene2D& scene, std::span<const Eigen::Vector3d> body_coordinates,
                             std::span<const Eigen::VectorXd> node_coordinates, PointPairs2D& point_pairs,
                             LargeArray<Interaction2D>& out);

// The nodes of mesh m at the detection configuration: x_ref + X_begin + (1 − θ)h V_begin.
Eigen::VectorXd mesh_detection_coordinates(const Scene2D& scene, std::size_t mesh, double theta, double h);

}  // namespace lmgc::solver
