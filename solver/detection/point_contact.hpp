#pragma once
// PTPT3: links between PT3Dx points of different RBDY3 bodies (wires, rods, glue). Which points
// are linked is decided once, in the reference configuration or by PTPT3_NETWORK.DAT; each step
// the link's geometry is the segment between the two points. docs/lmgc90-facts/contact-laws.md §3.4,
// numerics.md §5.3 (PTPT: gap = distance); LMGC90 contact_3D/mod_PTPT3.f90 compute_box (:340-693),
// compute_contact
// (:1018-1524).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "grammar/ptpt3_network/ast.hpp"
#include "solver/detection/pair_geometry_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

// Where a link's reference length (nonuc0) comes from: the reference configuration (BODIES.DAT
// centre + initial frame x offset, LMGC90's cooref), or with PTPT3_UseCurrentNonuc0(1) the file's
// value for the links of a network and, our choice for detected links, the positions at the start
// of the run (LMGC90 reads its current coordinates there before it has set them).
enum class LinkLength { reference_configuration, current };

// The PTPT3 links of a scene: for each PT3Dx (candidate, in contactor order) and each later PT3Dx
// of another body (antagonist) with a PTPT3 `$seety` row for their two colours (in either order, as
// get_isee), a link when their distance is within the row's alert. That distance is the link's
// reference length (the wires' gapREF). With periodic sides (scene.x_period, y_period), the
// antagonist's images one period away on either side are tried too, after the direct pair, counted
// in the periodic cell the points wrap into (so a point outside the cell may be shifted by more
// than one period); each image within the alert is a link of its own. LMGC90 stops on a point
// outside [0, period); here it links as it lies.
// LMGC90 tries only the +period images and then shifts the candidate instead of the antagonist
// ("n'a aucun sens", mod_PTPT3 compute_contact), which gives such a link another length than the
// one it was found with; here a link is measured every step as it was found.
std::vector<PointLink3D> link_points_3d(const Scene3D& scene,
                                        LinkLength length = LinkLength::reference_configuration);

// The links PTPT3_NETWORK.DAT lists (PTPT3_LoadNetwork), in file order. Points are numbered 1, 2,
// ... over the scene's PT3Dx contactors; a link's visibility row is the PTPT3 row for its two
// colours (either order, as get_isee). The period shift goes to the candidate when iloop = 1, else
// to the antagonist. Reference length: the distance of the two points, shifted, in the reference
// configuration (LMGC90 measures it without the shift, which no periodic link can mean), or the
// file's nonuc0 with LinkLength::current. False, with `error` set, for a point that does not exist,
// two points of one body, or a link without a row (lmgc-check reports these as L2021, L2022).
bool network_links_3d(const Scene3D& scene, const grammar::Ptpt3NetworkFile& network, LinkLength length,
                      std::vector<PointLink3D>& links, std::string& error);

// The offset of `periods` periodic images (x, y) in this scene.
Eigen::Vector3d period_shift(const Scene3D& scene, const std::array<std::int32_t, 2>& periods);

// PTPT3's frame and gap for points `candidate` and `antagonist`: n from the antagonist to the
// candidate, gap = distance, point = midpoint, t by mod_PTPT3's rule (a fixed axis when n is along
// an axis; else the unit vector orthogonal to n with two equal components), s = t × n. Coincident
// points (distance < 1e-20) give the global axes and gap 0, as LMGC90's glued nodes.
ContactGeometry3D point_point_geometry(const Eigen::Vector3d& candidate, const Eigen::Vector3d& antagonist);

}  // namespace lmgc::solver
