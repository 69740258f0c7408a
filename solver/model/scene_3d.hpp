#pragma once
// Everything a rigid 3D run needs, as flat arrays: RBDY3 bodies, sphere and plane contactors,
// laws, visibility rows, and the ScenePlan3D saying which pair families the scene uses.
// docs/lmgc90-facts/numerics.md §1.2, §2, §5.3. Local vectors are in LMGC90's order (t, n, s).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "solver/bodies/polyhedron.hpp"
#include "solver/bodies/rigid_bodies_3d.hpp"
#include "solver/model/contact_status.hpp"
#include "solver/model/interaction_3d.hpp"
#include "solver/model/scene_2d.hpp"  // NamedLaw, DrivenDof2D (dimension-free parts)

namespace lmgc::solver {

enum class ContactorShape3D : std::uint8_t { sphere, plane, polyhedron, cylinder, tube, point };

struct Contactor3D {
  ContactorShape3D shape = ContactorShape3D::sphere;
  std::int32_t body = 0;
  std::int32_t rank = 1;  // rank within its body (1-based)
  std::string type;       // "SPHER", "SPHEb", "PLANx", "POLYR", "CYLND", "DNLYC", "PT3Dx"
  std::string color;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();            // offset from the centre of inertia, body axes
  Eigen::Matrix3d local_frame = Eigen::Matrix3d::Identity();  // PLANx axes (T, S, N), CYLND axes, body axes
  double radius = 0.0;                                        // SPHER, SPHEb, CYLND
  Eigen::Vector3d half_axes = Eigen::Vector3d::Zero();        // PLANx axe1, axe2, axe3; CYLND (0, 0, High)
  std::int32_t polyhedron = -1;                               // POLYR: index into Scene3D::polyhedra
  double bounding_radius = 0.0;
};

struct Visibility3D {
  std::string candidate_type, candidate_color, antagonist_type, antagonist_color;
  std::int32_t law = 0;
  double alert = 0.0;
  PairFamily3D family = PairFamily3D::SPSPx;
};

// A PTPT3 link: two PT3Dx contactors of different bodies, their `$seety` row and their distance in
// the reference configuration (solver/detection/point_contact.hpp).
struct PointLink3D {
  std::int32_t candidate = 0, antagonist = 0;  // contactor ids
  std::int32_t visibility = 0;
  double reference_length = 0.0;  // nonuc0 [m]
  // The antagonist is seen shifted by periods[0] x periods and periods[1] y periods (a link across
  // a periodic side); 0 for a direct link.
  std::array<std::int32_t, 2> periods{};
  // The shift is applied to the candidate instead (by -periods): a network link with iloop = 1, so
  // that its contact point is where LMGC90 puts it. The geometry is the same.
  bool shift_candidate = false;
  // Rank among the links of the same pair (0, or 1... for its periodic duplicates): the key that
  // matches each to its reaction of the previous step.
  std::int32_t pair_rank = 0;
};

struct ScenePlan3D {
  std::array<bool, kPairFamily3DCount> families{};
};

// RBDY3_SetSourcePointWithIni: bodies after the last injected one wait, invisible, until it is
// farther than `radius` from `point`; then the next one enters there (one per step).
struct SourcePoint3D {
  bool active = false;
  bool stopped = false;  // the next body's first contactor is not SPHER/POLYR: no more injection
  std::size_t last = 0;  // index of the last injected body
  double radius = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

struct Scene3D {
  RigidBodies3D bodies;
  std::vector<Contactor3D> contactors;
  std::vector<Polyhedron> polyhedra;  // POLYR shapes, body axes about their contactor's shift point
  std::vector<NamedLaw> laws;
  std::vector<Visibility3D> visibility;
  std::vector<DrivenDof2D> driven;  // dof 0..5
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  FrameUpdate rotation = FrameUpdate::linearised;  // cayley = RBDY3_NewRotationScheme
  // SetPeriodicCondition: detection sees centres wrapped into [0, period) and the images of the
  // bodies near the sides; positions themselves are never wrapped (0 = not periodic).
  double x_period = 0.0, y_period = 0.0;
  // Cap of Cundall's common-plane search between polyhedra (PRPRx_UseCpCundallDetection(nb_iter),
  // COMMAND.DAT's CUNDALL ITERATION; 100 is mod_PRPRx's default `cundall_iter`). The search usually
  // ends earlier, when its tilt angle falls below 0.0017 rad.
  int cundall_iterations = 100;
  SourcePoint3D source;
  std::vector<PointLink3D> point_links;  // PTPT3, fixed for the run
  ScenePlan3D plan;
};

}  // namespace lmgc::solver
