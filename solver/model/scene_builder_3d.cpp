#include "solver/model/scene_builder_3d.hpp"

#include <Eigen/Eigenvalues>
#include <numbers>

#include "solver/detection/point_contact.hpp"

namespace lmgc::solver {

int SceneBuilder3D::add_body(const Eigen::Vector3d& centre, double mass, const Eigen::Vector3d& inertia) {
  RigidBodies3D& b = scene_.bodies;
  const std::size_t n = b.size();
  b.resize(n + 1);
  b.reference[n] = centre;
  b.mass[n] = mass;
  b.inertia[n] = inertia;
  b.bulk_behav[n] = 0;
  return static_cast<int>(n);
}

int SceneBuilder3D::add_sphere(const Eigen::Vector3d& centre, double radius, double density,
                               const std::string& color) {
  const double mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const int body = add_body(centre, mass, Eigen::Vector3d::Constant(0.4 * mass * radius * radius));
  Contactor3D c;
  c.shape = ContactorShape3D::sphere;
  c.body = body;
  c.type = "SPHER";
  c.color = color;
  c.radius = radius;
  c.bounding_radius = radius;
  scene_.contactors.push_back(c);
  return body;
}

int SceneBuilder3D::add_sphere_cluster(const Eigen::Vector3d& centre,
                                       const std::vector<Eigen::Vector3d>& offsets, double radius,
                                       double density, const std::string& color) {
  const double ball_mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double mass = ball_mass * static_cast<double>(offsets.size());
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& o : offsets) centroid += o;
  centroid /= static_cast<double>(offsets.size());
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (const auto& o : offsets) {
    const Eigen::Vector3d d = o - centroid;
    tensor += ball_mass * (0.4 * radius * radius + d.squaredNorm()) * Eigen::Matrix3d::Identity() -
              ball_mass * d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(tensor);
  Eigen::Matrix3d axes = principal.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  const int body = add_body(centre + centroid, mass, principal.eigenvalues());
  scene_.bodies.frame_initial[static_cast<std::size_t>(body)] = axes;
  scene_.bodies.frame[static_cast<std::size_t>(body)] = axes;
  scene_.bodies.frame_detection[static_cast<std::size_t>(body)] = axes;
  int rank = 1;
  for (const auto& o : offsets) {
    Contactor3D c;
    c.shape = ContactorShape3D::sphere;
    c.body = body;
    c.rank = rank++;
    c.type = "SPHEb";
    c.color = color;
    c.radius = radius;
    c.shift = axes.transpose() * (o - centroid);  // body (principal) axes
    c.bounding_radius = radius;
    scene_.contactors.push_back(c);
  }
  return body;
}

Contactor3D& SceneBuilder3D::add_contactor(int body, ContactorShape3D shape, const char* type,
                                           const std::string& color) {
  Contactor3D& c = scene_.contactors.emplace_back();
  c.shape = shape;
  c.body = body;
  c.type = type;
  c.color = color;
  return c;
}

void SceneBuilder3D::add_axial_contactor(int body, ContactorShape3D shape, const char* type,
                                         const std::string& color, double half_length, double radius) {
  Contactor3D& c = add_contactor(body, shape, type, color);
  c.radius = radius;
  c.half_axes = Eigen::Vector3d(0.0, 0.0, half_length);
  c.bounding_radius = half_length + radius;
}

void SceneBuilder3D::fix(int body) {
  scene_.bodies.driven_mask[static_cast<std::size_t>(body)] = 0x3f;
}

int SceneBuilder3D::add_cylinder(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame,
                                 double half_length, double radius, double density,
                                 const std::string& color) {
  const double mass = density * std::numbers::pi * radius * radius * 2.0 * half_length;
  const double across = mass * (radius * radius / 4.0 + half_length * half_length / 3.0);
  const int body = add_body(centre, mass, Eigen::Vector3d(across, across, mass * radius * radius / 2.0));
  set_frame(body, frame);
  add_axial_contactor(body, ContactorShape3D::cylinder, "CYLND", color, half_length, radius);
  return body;
}

int SceneBuilder3D::add_fixed_tube(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame,
                                   double half_length, double radius, const std::string& color) {
  const int body = add_body(centre, 1.0, Eigen::Vector3d::Ones());
  set_frame(body, frame);
  fix(body);
  add_axial_contactor(body, ContactorShape3D::tube, "DNLYC", color, half_length, radius);
  return body;
}

int SceneBuilder3D::add_fixed_plane(const Eigen::Vector3d& centre, const Eigen::Matrix3d& frame,
                                    const Eigen::Vector3d& half_axes, const std::string& color) {
  const int body = add_body(centre, 1.0, Eigen::Vector3d::Ones());
  fix(body);
  Contactor3D& c = add_contactor(body, ContactorShape3D::plane, "PLANx", color);
  c.local_frame = frame;
  c.half_axes = half_axes;
  c.bounding_radius = half_axes.norm();
  return body;
}

int SceneBuilder3D::add_law(const std::string& nickname, const ContactLaw& law) {
  scene_.laws.push_back({nickname, law});
  return static_cast<int>(scene_.laws.size()) - 1;
}

void SceneBuilder3D::see(const std::string& candidate_type, const std::string& candidate_color,
                         const std::string& law, const std::string& antagonist_type,
                         const std::string& antagonist_color, double alert) {
  Visibility3D v;
  v.candidate_type = candidate_type;
  v.candidate_color = candidate_color;
  v.antagonist_type = antagonist_type;
  v.antagonist_color = antagonist_color;
  v.alert = alert;
  for (std::size_t k = 0; k < scene_.laws.size(); ++k)
    if (scene_.laws[k].nickname == law) v.law = static_cast<std::int32_t>(k);
  pair_family_3d(candidate_type, antagonist_type, v.family);
  scene_.visibility.push_back(v);
}

void SceneBuilder3D::set_velocity(int body, const Vector6d& velocity) {
  scene_.bodies.velocity_begin[static_cast<std::size_t>(body)] = velocity;
  scene_.bodies.velocity[static_cast<std::size_t>(body)] = velocity;
}

void SceneBuilder3D::set_frame(int body, const Eigen::Matrix3d& frame) {
  const auto b = static_cast<std::size_t>(body);
  scene_.bodies.frame_initial[b] = scene_.bodies.frame[b] = scene_.bodies.frame_detection[b] = frame;
}

void SceneBuilder3D::add_point(int body, const Eigen::Vector3d& offset, const std::string& color) {
  std::int32_t rank = 1;
  for (const Contactor3D& c : scene_.contactors) rank += c.body == body ? 1 : 0;
  Contactor3D& c = add_contactor(body, ContactorShape3D::point, "PT3Dx", color);
  c.shift = offset;
  c.rank = rank;
}

Scene3D SceneBuilder3D::build() {
  RigidBodies3D& b = scene_.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vector6d inverse;
    inverse << Eigen::Vector3d::Constant(1.0 / b.mass[i]), b.inertia[i].cwiseInverse();
    for (int d = 0; d < 6; ++d)
      if (b.driven_mask[i] & (1u << d)) inverse(d) = 0.0;
    b.inverse_mass[i] = inverse;
  }
  scene_.point_links = link_points_3d(scene_);
  scene_.plan = {};
  for (const Visibility3D& v : scene_.visibility) scene_.plan.families[static_cast<int>(v.family)] = true;
  return scene_;
}

}  // namespace lmgc::solver
