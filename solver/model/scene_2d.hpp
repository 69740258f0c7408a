#pragma once
// Everything a rigid 2D run needs, as flat arrays: bodies, contactors, laws, visibility, driven
// dofs, and the ScenePlan that says which pair families and laws this scene uses.
#include <Eigen/Core>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "solver/bodies/rigid_bodies_2d.hpp"
#include "solver/laws/contact_law.hpp"
#include "solver/model/deformable_bodies.hpp"
#include "solver/model/driven_dof.hpp"
#include "solver/model/interaction_2d.hpp"

namespace lmgc::solver {

enum class ContactorShape2D : std::uint8_t { disk, hollow_disk, joncx, polygon, point };

struct Contactor2D {
  ContactorShape2D shape = ContactorShape2D::disk;
  std::int32_t body = 0;
  std::int32_t rank = 1;  // rank of the contactor within its body (1-based), written in Vloc_Rloc
  std::string type;       // LMGC90 keyword: "DISKx", "DISKb", "JONCx", "POLYG", "xKSID", "PT2Dx"
  std::string color;
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // offset from the centre of inertia, body frame
  double radius = 0.0;                              // DISKx, DISKb, xKSID
  double half_length = 0.0;                         // JONCx ax1
  double half_width = 0.0;                          // JONCx ax2
  std::int32_t first_vertex = 0;  // POLYG: vertices[first_vertex, first_vertex + vertex_count)
  std::int32_t vertex_count = 0;
  double bounding_radius = 0.0;  // radius of the circle centred at the shift containing the shape
};

// A '$seety' row: which contactor pairs may interact, with which law and alert distance.
struct Visibility2D {
  std::string candidate_type, candidate_color, antagonist_type, antagonist_color;
  std::string law_nickname;
  std::int32_t law = 0;
  double alert = 0.0;
  PairFamily2D family = PairFamily2D::DKDKx;
};

struct NamedLaw {
  std::string nickname;  // 5 characters, TACT_BEHAV.DAT columns 2-6
  ContactLaw law;
};

// What this scene needs: only these families are detected and only these laws dispatched.
struct ScenePlan2D {
  std::array<bool, kPairFamily2DCount> families{};  // indexed by PairFamily2D
  bool any_polygon = false;
  bool any_mesh_family = false;  // a visibility row of CLALp, CLJCx or PLALp
  bool any_driven_force = false;
};

// The family of LMGC90's interaction module for a (candidate, antagonist) pair of '$seety' contactor
// names, every 2D family (rigid and mesh); false when lmgc has none.
bool contactor_pair_family_2d(std::string_view candidate_type, std::string_view antagonist_type,
                              PairFamily2D& family);

struct Scene2D {
  RigidBodies2D bodies;
  std::vector<Contactor2D> contactors;
  std::vector<Eigen::Vector2d> vertices;  // polygon vertices, body frame, counter-clockwise
  std::vector<NamedLaw> laws;
  std::vector<Visibility2D> visibility;
  std::vector<DrivenDof2D> driven;
  DeformableBodies deformable;  // MAILx bodies: meshes, matrices, nodal state
  Eigen::Vector2d gravity = Eigen::Vector2d(0.0, -9.81);
  std::vector<double> density;  // per bulk behaviour [kg/m²]
  std::vector<std::string> behaviour_names;
  // Periodic in x with this period, when > 0 (numerics.md §5.2).
  double x_period = 0.0;
  // Bodies whose centre leaves these bounds become invisible: frozen at the bound with zero
  // velocity and no longer detected (LMGC90 RBDY2 "out of bounds", e.g. SetYminBoundary).
  double y_min = -std::numeric_limits<double>::infinity();
  double y_max = std::numeric_limits<double>::infinity();
  double x_min = -std::numeric_limits<double>::infinity();
  double x_max = std::numeric_limits<double>::infinity();
  ScenePlan2D plan;
};

}  // namespace lmgc::solver
