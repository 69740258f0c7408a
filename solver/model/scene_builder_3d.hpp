#pragma once
// Building a rigid 3D scene in code (tests, benchmarks, reference cases): spheres, sphere
// clusters, fixed planes, laws, visibility rows, fixed dofs.
#include <string>
#include <vector>

#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

class SceneBuilder3D {
 public:
  // A sphere of radius r and density ρ at `centre`: m = ρ 4/3 π r³, I = 2/5 m r².
  int add_sphere(const Eigen::Vector3d& centre, double radius, double density,
                 const std::string& color = "BLEUx");
  // Equal spheres rigidly joined (SPHEb), offsets from `centre`; mass and inertia of the union of
  // the balls taken as disjoint (parallel-axis theorem), principal axes from the inertia tensor.
  int add_sphere_cluster(const Eigen::Vector3d& centre, const std::vector<Eigen::Vector3d>& offsets,
                         double radius, double density, const std::string& color = "BLEUx");
  // A fixed PLANx box centred at `centre`, axes (T, S, N) the columns of `frame`, half-axes
  // (axe1, axe2, axe3).
  // A CYLND of half-length H and radius r whose axis is the third column of `frame` (a solid
  // cylinder: m = ρ 2π r² H, I1 = I2 = m (r²/4 + H²/3), I3 = m r²/2).
  int add_cylinder(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame, double half_length,
                   double radius, double density, const std::string& color = "BLEUx");
  // A fixed DNLYC (open tube: spheres inside) of half-length H and radius r, axis along the third
  // column of `frame`.
  int add_fixed_tube(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame, double half_length,
                     double radius, const std::string& color = "VERTx");
  int add_fixed_plane(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame,
                      const Eigen::Vector3d& half_axes, const std::string& color = "VERTx");
  // A PT3Dx point of `body` at `offset` from its centre (body axes); adds no mass.
  void add_point(int body, const Eigen::Vector3d& offset, const std::string& color = "BLEUx");
  int add_law(const std::string& nickname, const ContactLaw& law);
  void see(const std::string& candidate_type, const std::string& candidate_color, const std::string& law,
           const std::string& antagonist_type, const std::string& antagonist_color, double alert);
  void set_velocity(int body, const Vector6d& velocity);
  void set_frame(int body, const Eigen::Matrix3d& frame);
  void set_gravity(const Eigen::Vector3d& g) { scene_.gravity = g; }
  void set_rotation_scheme(FrameUpdate method) { scene_.rotation = method; }
  Scene3D build();

 private:
  int add_body(const Eigen::Vector3d& centre, double mass, const Eigen::Vector3d& inertia);
  // A contactor of `body`, appended to the scene (its geometry left to the caller).
  Contactor3D& add_contactor(int body, ContactorShape3D shape, const char* type, const std::string& color);
  // CYLND / DNLYC: radius, half-length along the third axis, bounding radius H + r.
  void add_axial_contactor(int body, ContactorShape3D shape, const char* type, const std::string& color,
                           double half_length, double radius);
  void fix(int body);  // all six velocities imposed to 0
  Scene3D scene_;
};

}  // namespace lmgc::solver
