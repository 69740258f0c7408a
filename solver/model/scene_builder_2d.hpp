#pragma once
// Building a rigid 2D scene in code (tests, benchmarks, and later a Python module): bodies with
// one contactor each, laws, visibility rows, fixed dofs.
#include <string>

#include "solver/model/scene_2d.hpp"

namespace lmgc::solver {

class SceneBuilder2D {
 public:
  // A disk of radius r and areal density ρ at (x, y): m = ρ π r², I = m r²/2.
  int add_disk(double x, double y, double radius, double density, const std::string& color = "BLEUx");
  // A JONCx wall centred at (x, y), axis at `angle`, half-length ax1, half-thickness ax2; fixed.
  int add_fixed_joncx(double x, double y, double angle, double ax1, double ax2,
                      const std::string& color = "WALLx");
  // A convex polygon (vertices counter-clockwise, relative to (x, y)) re-centred on its centroid.
  int add_polygon(double x, double y, const std::vector<Eigen::Vector2d>& vertices, double density,
                  const std::string& color = "BLEUx");
  int add_law(const std::string& nickname, const ContactLaw& law);
  void see(const std::string& candidate_type, const std::string& candidate_color, const std::string& law,
           const std::string& antagonist_type, const std::string& antagonist_color, double alert);
  // Imposes zero velocity on every dof of `body`.
  void fix(int body);
  void set_velocity(int body, const Eigen::Vector3d& velocity);
  void set_gravity(const Eigen::Vector2d& g) { scene_.gravity = g; }
  // A linear elastic mesh (MAILx) at rest in its reference configuration; returns its index. Its
  // contactors: a CLxxx point on the edge (a, b) at apab from a, an ALpxx polyline (nodes 0-based,
  // described clockwise around the body so that its normals point out).
  int add_mesh(const fem::MeshBody& mesh);
  void add_candidate_point(int mesh, int a, int b, double apab, const std::string& color = "MESHx");
  void add_polyline(int mesh, const std::vector<int>& nodes, const std::string& color = "MESHx");
  // A PT2DL point on (a, b) at apab from a (P2P2L's side).
  void add_point(int mesh, int a, int b, double apab, const std::string& color = "MESHx");

  const Scene2D& scene() const { return scene_; }  // as built so far

  // Finishes the scene (inverse masses, visibility rows, plan, the meshes' matrices) and returns it;
  // throws std::invalid_argument for a mesh with an inverted element.
  Scene2D build();

 private:
  int add_body(double x, double y, double angle, double mass, double inertia);
  Scene2D scene_;
};

// Mass properties of a convex polygon of unit density: area, centroid, polar moment about the
// centroid (per unit density).
void polygon_mass_properties(const std::vector<Eigen::Vector2d>& vertices, double& area,
                             Eigen::Vector2d& centroid, double& polar_moment);

// Inverse masses, visibility families and the plan, from the rest of the scene.
void finalise_scene(Scene2D& scene);

}  // namespace lmgc::solver
