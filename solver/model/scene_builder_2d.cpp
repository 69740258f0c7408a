#include "solver/model/scene_builder_2d.hpp"

#include <cmath>
#include <stdexcept>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "solver/bodies/lmgc_pi.hpp"
#include "solver/bodies/rigid_2d_properties.hpp"
#include "solver/detection/detection_2d.hpp"

namespace lmgc::solver {

bool contactor_pair_family_2d(std::string_view cd, std::string_view an, PairFamily2D& family) {
  const grammar::ContactorPair* pair =
      grammar::find_contactor_pair(grammar::see_name(cd), grammar::see_name(an));
  if (!pair) return false;
  for (int f = 0; f < kPairFamily2DCount; ++f)
    if (pair_family_name(static_cast<PairFamily2D>(f)) == pair->interaction) {
      family = static_cast<PairFamily2D>(f);
      return true;
    }
  return false;
}

using Eigen::Vector2d;
using Eigen::Vector3d;

int SceneBuilder2D::add_body(double x, double y, double angle, double mass, double inertia) {
  RigidBodies2D& b = scene_.bodies;
  const std::size_t n = b.size();
  b.reference.push_back(Vector3d(x, y, angle));
  for (auto* v : {&b.displacement_begin, &b.displacement, &b.velocity_begin, &b.velocity, &b.velocity_free,
                  &b.inverse_mass, &b.external_force, &b.impulse})
    v->push_back(Vector3d::Zero());
  b.mass.push_back(mass);
  b.inertia.push_back(inertia);
  b.avrd.push_back(0.0);
  b.gyrd.push_back(mass > 0.0 ? std::sqrt(inertia / mass) : 0.0);
  b.bulk_behav.push_back(0);
  b.driven_mask.push_back(0);
  b.visible.push_back(1);
  return static_cast<int>(n);
}

int SceneBuilder2D::add_disk(double x, double y, double radius, double density, const std::string& color) {
  const double mass = density * lmgc_pi * radius * radius;
  const int body = add_body(x, y, 0.0, mass, 0.5 * mass * radius * radius);
  scene_.bodies.avrd.back() = radius;
  Contactor2D c;
  c.shape = ContactorShape2D::disk;
  c.type = "DISKx";
  c.body = body;
  c.color = color;
  c.radius = radius;
  c.bounding_radius = radius;
  scene_.contactors.push_back(c);
  return body;
}

int SceneBuilder2D::add_fixed_joncx(double x, double y, double angle, double ax1, double ax2,
                                    const std::string& color) {
  const int body = add_body(x, y, angle, 1.0, 1.0);
  Contactor2D c;
  c.shape = ContactorShape2D::joncx;
  c.type = "JONCx";
  c.body = body;
  c.color = color;
  c.half_length = ax1;
  c.half_width = ax2;
  c.bounding_radius = ax1 + ax2;
  scene_.contactors.push_back(c);
  fix(body);
  return body;
}

void polygon_mass_properties(const std::vector<Vector2d>& v, double& area, Vector2d& centroid,
                             double& polar) {
  area = 0.0;
  centroid.setZero();
  double second = 0.0;  // ∫ |x|² about the origin
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vector2d& a = v[i];
    const Vector2d& b = v[(i + 1) % v.size()];
    const double cross = a.x() * b.y() - a.y() * b.x();
    area += 0.5 * cross;
    centroid += cross * (a + b) / 6.0;
    second += cross * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 12.0;
  }
  if (area != 0.0) centroid /= area;
  polar = second - area * centroid.squaredNorm();
}

int SceneBuilder2D::add_polygon(double x, double y, const std::vector<Vector2d>& vertices, double density,
                                const std::string& color) {
  double area, polar;
  Vector2d centroid;
  polygon_mass_properties(vertices, area, centroid, polar);
  if (area <= 0.0) throw std::invalid_argument("polygon vertices must be counter-clockwise");
  const int body = add_body(x + centroid.x(), y + centroid.y(), 0.0, density * area, density * polar);
  Contactor2D c;
  c.shape = ContactorShape2D::polygon;
  c.type = "POLYG";
  c.body = body;
  c.color = color;
  c.first_vertex = static_cast<std::int32_t>(scene_.vertices.size());
  c.vertex_count = static_cast<std::int32_t>(vertices.size());
  std::vector<Vector2d> centred;
  for (const Vector2d& p : vertices) centred.push_back(p - centroid);
  scene_.vertices.insert(scene_.vertices.end(), centred.begin(), centred.end());
  c.bounding_radius = polygon_outer_radius(centred);
  scene_.contactors.push_back(c);
  return body;
}

int SceneBuilder2D::add_law(const std::string& nickname, const ContactLaw& law) {
  scene_.laws.push_back({nickname, law});
  return static_cast<int>(scene_.laws.size()) - 1;
}

void SceneBuilder2D::see(const std::string& cd_type, const std::string& cd_color, const std::string& law,
                         const std::string& an_type, const std::string& an_color, double alert) {
  Visibility2D v;
  v.candidate_type = cd_type;
  v.candidate_color = cd_color;
  v.antagonist_type = an_type;
  v.antagonist_color = an_color;
  v.law_nickname = law;
  v.alert = alert;
  scene_.visibility.push_back(v);
}

void SceneBuilder2D::fix(int body) {
  for (int d = 0; d < 3; ++d) {
    DrivenDof2D dof;
    dof.body = body;
    dof.dof = d;
    dof.coefficients = {0.0, 0.0, 0.0, 0.0, 1.0, 0.0};
    scene_.driven.push_back(dof);
  }
}

void SceneBuilder2D::set_velocity(int body, const Vector3d& velocity) {
  scene_.bodies.velocity_begin[static_cast<std::size_t>(body)] = velocity;
  scene_.bodies.velocity[static_cast<std::size_t>(body)] = velocity;
}

int SceneBuilder2D::add_mesh(const fem::MeshBody& mesh) {
  scene_.deformable.meshes.bodies.push_back(mesh);
  scene_.deformable.meshes.matlib.push_back(false);
  return static_cast<int>(scene_.deformable.meshes.bodies.size()) - 1;
}

namespace {
void add_mesh_contactor(Scene2D& scene, MeshContactor c) {
  std::vector<MeshContactor>& all = scene.deformable.meshes.contactors;
  c.rank = 1;
  c.serial = 1;
  for (const MeshContactor& other : all) {
    c.rank += other.mesh == c.mesh;
    c.serial += other.type == c.type;
  }
  all.push_back(std::move(c));
}

// A contactor at apab from a on the edge (a, b) of a mesh: CLxxx or PT2DL.
MeshContactor edge_point(MeshContactorShape shape, const char* type, int mesh, int a, int b, double apab,
                         const std::string& color) {
  MeshContactor c;
  c.shape = shape;
  c.type = type;
  c.color = color;
  c.mesh = mesh;
  c.nodes = {a, b};
  c.apab = apab;
  return c;
}
}  // namespace

void SceneBuilder2D::add_candidate_point(int mesh, int a, int b, double apab, const std::string& color) {
  add_mesh_contactor(scene_,
                     edge_point(MeshContactorShape::candidate_point, "CLxxx", mesh, a, b, apab, color));
}

void SceneBuilder2D::add_point(int mesh, int a, int b, double apab, const std::string& color) {
  add_mesh_contactor(scene_, edge_point(MeshContactorShape::point, "PT2DL", mesh, a, b, apab, color));
}

void SceneBuilder2D::add_polyline(int mesh, const std::vector<int>& nodes, const std::string& color) {
  MeshContactor c;
  c.shape = MeshContactorShape::polyline;
  c.type = "ALpxx";
  c.color = color;
  c.mesh = mesh;
  c.nodes.assign(nodes.begin(), nodes.end());
  add_mesh_contactor(scene_, std::move(c));
}

Scene2D SceneBuilder2D::build() {
  finalise_scene(scene_);
  std::string error;
  std::size_t body = 0, element = 0;
  if (!initialise_mesh_states(scene_.deformable, error, body, element))
    throw std::invalid_argument("mesh " + std::to_string(body) + ": " + error);
  return scene_;
}

void finalise_scene(Scene2D& scene) {
  RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.driven_mask[i] = 0;
    const double im = b.mass[i] > 0.0 ? 1.0 / b.mass[i] : 0.0;
    const double ii = b.inertia[i] > 0.0 ? 1.0 / b.inertia[i] : 0.0;
    b.inverse_mass[i] = Vector3d(im, im, ii);
  }
  // Dofs with an imposed velocity do not move under contact impulses (numerics.md §1.1).
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force) {
      b.inverse_mass[static_cast<std::size_t>(d.body)](d.dof) = 0.0;
      b.driven_mask[static_cast<std::size_t>(d.body)] |= static_cast<std::uint8_t>(1u << d.dof);
    } else {
      scene.plan.any_driven_force = true;
    }
  // Law indices and pair families of the visibility rows.
  for (Visibility2D& v : scene.visibility) {
    for (std::size_t l = 0; l < scene.laws.size(); ++l)
      if (scene.laws[l].nickname == v.law_nickname) {
        v.law = static_cast<std::int32_t>(l);
        break;
      }
    PairFamily2D family;
    if (contactor_pair_family_2d(v.candidate_type, v.antagonist_type, family) ||
        contactor_pair_family_2d(v.antagonist_type, v.candidate_type, family)) {
      v.family = family;
      scene.plan.families[static_cast<std::size_t>(family)] = true;
      scene.plan.any_mesh_family |= is_mesh_family(family);
    }
  }
  for (const Contactor2D& c : scene.contactors)
    scene.plan.any_polygon |= c.shape == ContactorShape2D::polygon;
}

}  // namespace lmgc::solver
