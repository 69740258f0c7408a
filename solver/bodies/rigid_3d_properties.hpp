#pragma once
// What LMGC90 computes for an RBDY3 body of BODIES.DAT before anything runs: its volume, mass,
// equivalent radius avrd, principal inertia and principal frame, the centre of inertia (as a shift
// of the BODIES.DAT node), and the contactor shifts/frames re-expressed about that centre and in
// that frame. docs/lmgc90-facts/datbox-inputs.md §1.2 (RBDY3 `PLAIN`), §1.4 (contactors, "Read vs written"),
// numerics.md §1.2. LMGC90 (src/Core): rigid_3D/mod_RBDY3.f90 read_bodies (:941-1237), read_PLAIN
// (:3073-3099), comp_mass_RBDY3 (:3731-3807); rigid_3D/mod_a_BDARY_SPHER.f90, mod_a_BDARY_PLANx.f90,
// mod_a_BDARY_PT3Dx.f90; shared/mod_algebra.f90 diagonalise33 (:338-453).
//
// Summary of LMGC90's rules (line numbers of mod_RBDY3.f90 unless stated):
//  - Contactor geometry, "geometric" = per unit density (volume-weighted):
//      SPHER/SPHEb: V = 4/3 π r³, I1 = I2 = I3 = 2/5 r² V (mod_a_BDARY_SPHER.f90:68-71, :92-95);
//        SPHEb shift = its coo1..3 (:105-107), SPHER shift = 0 (mod_RBDY3.f90:810).
//      PLANx: V = 8 a1 a2 a3, I1 = V(a2²+a3²)/3, I2 = V(a1²+a3²)/3, I3 = V(a1²+a2²)/3 in its embedded
//        frame (`localframe` α β γ columns, identity by default), shift = the localframe coo1..3
//        (mod_a_BDARY_PLANx.f90:82-86, :96-128).
//      CYLND/DNLYC: a solid cylinder of half-length H = High and radius r: V = 2π r² H,
//        I1 = I2 = V (r²/4 + H²/3), I3 = V r²/2 (mod_a_BDARY_CYLND.f90:84-89); CYLND's localframe as PLANx.
//      POLYR: the exact volume integrals of its closed surface (faces reoriented first), about its
//        centroid, diagonalised by diagonalise33 unless the I-line gives the moments; shift = the
//        centroid, frame = the principal frame, vertices re-expressed in it about the centroid
//        (mod_a_BDARY_POLYR.f90:59-156, mod_DiscreteGeometry compute_mechanical_properties_surface_T3).
//      PT3Dx: a ball of radius avrd (1 when avrd = 0): V = 4/3 π ρ³, I = 2/5 ρ² V (given I-line values
//        kept where non-zero); it weighs 0 in the centre of inertia and the total volume of a cluster
//        but its V and I enter the cluster's inertia tensor (:902-917, :1044, :1144;
//        mod_a_BDARY_PT3Dx.f90:67-79).
//  - One contactor (:970-1028): V = 4/3 π avrd³ when avrd > 0, else V = contactor volume and
//    avrd = (3V/4π)^(1/3); principal inertia = the contactor's own (the I-line is overwritten by the
//    SPHER/SPHEb/PLANx readers, so it is ignored); frame = the contactor's embedded frame (PLANx
//    localframe, else identity), then the contactor frame becomes identity; centre = node + shift,
//    the shift becomes 0.
//  - Several contactors (:1030-1235): V = Σ V_i (whatever avrd is; avrd only filled when 0);
//    centre OG = Σ V_i s_i / Σ V_i, shifts become s_i - OG, node += OG. If the I-line is given
//    (any of I1..I3 ≠ 0), it is the principal inertia and the frame is identity (a placeholder:
//    LMGC90 expects the principal frame from DOF.INI), shifts stay in the body's input axes. Else
//    the inertia tensor Σ [E_i diag(I_i) E_iᵀ + V_i (|d|² 1 - d dᵀ)] (d = s_i - OG) is diagonalised
//    by diagonalise33 and shifts (and PLANx frames) are expressed in the principal frame.
//  - mass = Umas · V, principal inertia = Umas · geometric inertia (comp_mass_RBDY3 :3756-3763);
//    LMGC90 stops if any of them is ≤ 0 (:3774-3780). The I-line holds geometric values (the
//    BODIES.OUT echo writes them, :3101-3119).
//  - DOF.INI, when it lists the body, replaces the frame (LocalFrameIni) with its α β γ
//    (read_in_dof :1543-1563); the frame here is the one for bodies absent from DOF.INI.
//  - π is LMGC90's PI_g, a default-real (single precision) literal: 3.1415927410125732
//    (shared/mod_overall.f90:358).
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "solver/bodies/lmgc_pi.hpp"

namespace lmgc::solver {

// One contactor of an RBDY3 body, in the body's input axes, as read from BODIES.DAT.
// type: "SPHER", "SPHEb", "PLANx", "PT3Dx"; any other type counts as a contactor (one vs several)
// but has volume 0, inertia 0, and its `shift`/`frame` are used as given (see ignored_contactors).
struct Rigid3DContactorShape {
  std::string type;
  double radius = 0.0;                                  // SPHER/SPHEb/CYLND/DNLYC byrd
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();      // SPHEb coo1..3, PLANx localframe coo1..3,
                                                        // PT3Dx coo1..3: offset from the BODIES.DAT node
  Eigen::Vector3d half_axes = Eigen::Vector3d::Zero();  // PLANx axe1..3; CYLND/DNLYC (0, 0, High)
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // PLANx localframe (columns α, β, γ)
  std::vector<Eigen::Vector3d> vertices;                // POLYR: from the BODIES.DAT node, input axes
  std::vector<std::array<std::int32_t, 3>> faces;       // POLYR: 0-based vertex ids
};

struct RigidBody3DProperties {
  double mass = 0.0;                                            // Umas · volume [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();            // principal moments I1, I2, I3 [kg·m²]
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();          // principal frame, columns in input axes
  Eigen::Vector3d centre_shift = Eigen::Vector3d::Zero();       // centre of inertia - BODIES.DAT node
  double volume = 0.0;                                          // [m³]
  double avrd = 0.0;                                            // equivalent radius as held (BODIES.OUT)
  Eigen::Vector3d geometric_inertia = Eigen::Vector3d::Zero();  // inertia / Umas (BODIES.OUT I-line)
  std::vector<Eigen::Vector3d> contactor_shifts;  // per contactor: offset from the centre, body frame
  std::vector<Eigen::Matrix3d> contactor_frames;  // per contactor: embedded frame in the body frame
  // POLYR: vertices about the contactor's own centroid in the body frame, and its faces after
  // LMGC90's reorientation (empty for the other types).
  std::vector<std::vector<Eigen::Vector3d>> contactor_vertices;
  std::vector<std::vector<std::array<std::int32_t, 3>>> contactor_faces;
  bool frame_is_placeholder = false;   // I-line given with several contactors: identity, DOF.INI expected
  std::size_t ignored_contactors = 0;  // contactors of a type not modelled here
};

// density: Umas of the body's bulk behaviour (BULK_BEHAV.DAT); avrd: the `PLAIN` avrd (0 = compute);
// given_inertia: the optional I-line I1 I2 I3 (zeros when absent), geometric (per unit density).
// Throws std::invalid_argument for a body without contactors or several contactors of total
// volume 0 (LMGC90 stops or produces NaN there, :1052, :1062-1063).
RigidBody3DProperties rigid_3d_properties(double density, double avrd, const Eigen::Vector3d& given_inertia,
                                          const std::vector<Rigid3DContactorShape>& contactors);

// LMGC90's diagonalise33 (shared/mod_algebra.f90:338-453): off-diagonal terms below 1e-14·|diagonal|
// of their row (or below 1e-17 when that diagonal is ≤ 1e-10) are zeroed; if all six are zero the
// moments are the diagonal in place (unsorted) and the frame is identity; otherwise the eigenvalues
// of the lower triangle, ascending (LAPACK dsyevd), with e3 = e1 × e2. Eigenvalues and vectors,
// signs included, are reference LAPACK 3.11's bit for bit (symmetric_eigen_3x3.hpp).
struct PrincipalInertia {
  Eigen::Vector3d moments;
  Eigen::Matrix3d frame;  // columns
};
PrincipalInertia lmgc_diagonalise33(Eigen::Matrix3d tensor);

}  // namespace lmgc::solver
