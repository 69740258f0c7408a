#pragma once
// LMGC90's volume, centre of inertia and inertia tensor of a closed triangulated surface (a POLYR
// contactor), bit for bit: compute_volume_inertia_global_frame_surface_T3 of
// src/Core/shared/mod_DiscreteGeometry.f90 (:6272-6384) and what it calls (normals:
// compute_info_triangle :6917-6997; volume, centre, inertia: compute_volume_surface_T3 :6033-6086,
// compute_mass_center_surface_T3 :6094-6168, compute_inertia_surface_T3 :6176-6269, integrands
// f_vol .. f_I21 :7624-7774; Gauss points and weights: mod_a_EF.f90 pos_gauss :313-332,
// get_gp_coor :1508-1573, integrate_field :1660-2067 (T_P1 in 3D :1874-1915)).
//
// What LMGC90 computes (per unit density), by the divergence theorem on each triangle T with unit
// normal n (cross product of its edges 3→2 and 1→2, normalised):
//   V    = Σ_T ∫_T x n_x dS,                    Gauss rule TR01: the centroid, weight 1/2;
//   G_k  = (Σ_T ∫_T ½ x_k² n_k dS) / V,          TR03: (1/6,1/6) (2/3,1/6) (1/6,2/3), weights 1/6;
//   I_11 = Σ_T ∫_T ⅓ (dy³ n_y + dz³ n_z) dS,     TR04: the centroid with weight -27/96, then
//          I_22, I_33 alike,                           (0.2,0.2) (0.6,0.2) (0.2,0.6) with 25/96;
//   I_32 = -Σ_T ∫_T ½ dy² dz n_y dS, I_31 = -Σ_T ∫_T ½ dx² dz n_x dS, I_21 = -Σ_T ∫_T ½ dx² dy n_x dS,
// with d = x - G, the integral over T being Σ_gp |(x2-x1)×(x3-x1)| w_gp f(x_gp) (w sums to 1/2).
// So `inertia` is the inertia tensor (diagonal: ∫ of the sum of the two other squared coordinates;
// off-diagonal: minus the product integrals) about the centre of inertia G, in the global axes of
// the vertex coordinates, before any diagonalisation. The faces are those left by
// set_orientation_surface_T3; if V comes out negative it is replaced by |V|, every normal is negated
// and every face gets its 2nd and 3rd vertices swapped before G and I are computed.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

struct SurfaceT3Integrals {
  double volume = 0.0;                                // |V|
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // G, in the coordinates of the vertices
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about G, global axes; zero unless computed
  std::vector<std::array<std::int32_t, 3>> faces;     // the faces after the sign flip (LMGC90's final ones)
  bool flipped = false;                               // V was negative: faces turned over
  // Faces whose three vertices are merged or aligned (Heron area below 1e-24): LMGC90 gives them a
  // zero normal and then stops with an error (err 2/3 of :6326-6344, fatal in read_BDARY_POLYR).
  std::size_t degenerate_faces = 0;
};

// vertices: POLYR vertex coordinates as read (from the BODIES.DAT node, input axes).
// faces: 0-based, oriented as set_orientation_surface_T3 leaves them, i.e. BEFORE the global flip
// on the sign of the volume (which this function does itself, on LMGC90's volume): the roundings
// depend on the vertex order of each face, so the faces turned over by orient_faces' final flip do
// not give LMGC90's bits; use lmgc90_polyr_integrals for faces as read.
// compute_inertia: false when LMGC90 does not recompute it (I-line given: I1, I2 or I3 non-zero,
// compute_mechanical_properties_surface_T3 :6415); `inertia` is then zero.
// Throws std::invalid_argument for a face naming a missing vertex.
SurfaceT3Integrals lmgc90_surface_t3_integrals(const std::vector<Eigen::Vector3d>& vertices,
                                               const std::vector<std::array<std::int32_t, 3>>& faces,
                                               bool compute_inertia = true);

// The same from the faces as read in BODIES.DAT (0-based): orient_faces (polyhedron.hpp), with its
// final turn-over undone (set_orientation_surface_T3 never changes face 1, so the turn-over shows
// on face 0), then lmgc90_surface_t3_integrals, which redoes the turn-over on LMGC90's volume.
SurfaceT3Integrals lmgc90_polyr_integrals(const std::vector<Eigen::Vector3d>& vertices,
                                          const std::vector<std::array<std::int32_t, 3>>& faces_as_read,
                                          bool compute_inertia = true);

}  // namespace lmgc::solver
