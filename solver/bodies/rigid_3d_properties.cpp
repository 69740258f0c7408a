#include "solver/bodies/rigid_3d_properties.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "solver/bodies/surface_integrals_t3.hpp"
#include "solver/bodies/symmetric_eigen_3x3.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double one_third = 1.0 / 3.0;  // `untiers` (mod_RBDY3.f90:474)

// Volume, geometric principal inertia, embedded frame and shift of one contactor as LMGC90's
// read_BDARY_* leave them.
struct ContactorGeometry {
  double volume = 0.0;
  Vector3d inertia = Vector3d::Zero();
  Matrix3d frame = Matrix3d::Identity();
  Vector3d shift = Vector3d::Zero();
  double centre_weight = 0.0;  // volume in the centre of inertia / total volume (0 for PT3Dx)
  bool modelled = true;
  std::vector<Vector3d> vertices;  // POLYR, about its centroid in `frame`
  std::vector<std::array<std::int32_t, 3>> faces;
};

double ball_volume(double r) {
  return 4.0 * lmgc_pi * r * r * r / 3.0;
}

ContactorGeometry contactor_geometry(const Rigid3DContactorShape& c, double avrd,
                                     const Vector3d& given_inertia) {
  ContactorGeometry g;
  if (c.type == "SPHER" || c.type == "SPHEb") {
    // mod_a_BDARY_SPHER.f90:68-71 (SPHER), :92-95 and :105-107 (SPHEb); SPHER's shift is the 0
    // set by read_bodies (mod_RBDY3.f90:810).
    const double r = c.radius;
    g.volume = ball_volume(r);
    g.inertia = Vector3d::Constant(0.4 * r * r * g.volume);
    if (c.type == "SPHEb") g.shift = c.shift;
    g.centre_weight = g.volume;
  } else if (c.type == "PLANx") {
    // mod_a_BDARY_PLANx.f90:82-86; localframe and its coo1..3 :96-128.
    const Vector3d& a = c.half_axes;
    g.volume = 8.0 * a.x() * a.y() * a.z();
    g.inertia = Vector3d(g.volume * (a.y() * a.y() + a.z() * a.z()) / 3.0,
                         g.volume * (a.x() * a.x() + a.z() * a.z()) / 3.0,
                         g.volume * (a.y() * a.y() + a.x() * a.x()) / 3.0);
    g.frame = c.frame;
    g.shift = c.shift;
    g.centre_weight = g.volume;
  } else if (c.type == "CYLND" || c.type == "DNLYC") {
    // mod_a_BDARY_CYLND.f90:84-89 (DNLYC the same, a solid cylinder): half-length H, radius r, axis
    // along its frame's third column; CYLND's localframe and shift as PLANx's.
    const double H = c.half_axes.z(), r = c.radius;
    g.volume = lmgc_pi * r * r * 2.0 * H;
    g.inertia = Vector3d(g.volume * (r * r / 4.0 + H * H / 3.0), g.volume * (r * r / 4.0 + H * H / 3.0),
                         g.volume * r * r / 2.0);
    g.frame = c.frame;
    g.shift = c.shift;
    g.centre_weight = g.volume;
  } else if (c.type == "POLYR") {
    // mod_a_BDARY_POLYR.f90:59-156 -> compute_mechanical_properties_surface_T3: LMGC90's
    // orientation and Gauss-point surface integrals, bit for bit (surface_integrals_t3.hpp).
    const bool given = given_inertia != Vector3d::Zero();
    const SurfaceT3Integrals m = lmgc90_polyr_integrals(c.vertices, c.faces, !given);
    g.volume = m.volume;
    g.shift = m.centre;
    g.centre_weight = g.volume;
    if (given) {
      g.inertia = given_inertia;
    } else {
      const PrincipalInertia principal = lmgc_diagonalise33(m.inertia);
      g.inertia = principal.moments;
      g.frame = principal.frame;
    }
    for (const Vector3d& v : c.vertices) g.vertices.push_back(g.frame.transpose() * (v - m.centre));
    g.faces = m.faces;
  } else if (c.type == "PT3Dx") {
    // A ball of radius avrd, 1 when avrd = 0 (mod_RBDY3.f90:902-909); given I-line values are kept
    // where non-zero (mod_RBDY3.f90:812-826, mod_a_BDARY_PT3Dx.f90:67-72); weight 0 in the centre
    // (mod_RBDY3.f90:1044).
    const double r = avrd == 0.0 ? 1.0 : avrd;
    g.volume = ball_volume(r);
    for (int k = 0; k < 3; ++k)
      g.inertia[k] = given_inertia[k] != 0.0 ? given_inertia[k] : 0.4 * r * r * g.volume;
    g.shift = c.shift;
    g.centre_weight = 0.0;
  } else {
    g.frame = c.frame;
    g.shift = c.shift;
    g.modelled = false;
  }
  return g;
}

}  // namespace

PrincipalInertia lmgc_diagonalise33(Matrix3d m) {
  // shared/mod_algebra.f90:338-453, LAPACK dsyevd('V', 'L') reproduced bit for bit.
  PrincipalInertia p;
  lmgc90_diagonalise33(m, p.moments, p.frame);
  return p;
}

RigidBody3DProperties rigid_3d_properties(double density, double avrd, const Vector3d& given_inertia,
                                          const std::vector<Rigid3DContactorShape>& contactors) {
  if (contactors.empty())
    throw std::invalid_argument("rigid_3d_properties: RBDY3 without contactor (LMGC90 cannot size it)");

  std::vector<ContactorGeometry> parts;
  parts.reserve(contactors.size());
  RigidBody3DProperties out;
  for (const auto& c : contactors) {
    parts.push_back(contactor_geometry(c, avrd, given_inertia));
    if (!parts.back().modelled) ++out.ignored_contactors;
  }

  if (parts.size() == 1) {
    // mod_RBDY3.f90:970-1028.
    const ContactorGeometry& g = parts.front();
    if (avrd == 0.0) {
      out.avrd = std::pow(0.75 * g.volume / lmgc_pi, one_third);  // :974-977
      out.volume = g.volume;
    } else {
      out.avrd = avrd;
      out.volume = 4.0 * lmgc_pi * std::pow(avrd, 3.0) * one_third;  // :979-980
    }
    out.centre_shift = g.shift;         // :996-998
    out.geometric_inertia = g.inertia;  // :1012-1014 (I-line overwritten by the reader)
    out.frame = g.frame;                // :1019-1022
    out.contactor_shifts.assign(1, Vector3d::Zero());
    out.contactor_frames.assign(1, Matrix3d::Identity());  // :1025
    out.contactor_vertices.assign(1, g.vertices);
    out.contactor_faces.assign(1, g.faces);
  } else {
    // mod_RBDY3.f90:1032-1052: centre of inertia and total volume.
    Vector3d og = Vector3d::Zero();
    double vt = 0.0;
    for (const auto& g : parts) {
      og += g.centre_weight * g.shift;
      vt += g.centre_weight;
    }
    if (vt == 0.0)
      throw std::invalid_argument("rigid_3d_properties: several contactors of total volume 0 (LMGC90 stops)");
    og /= vt;
    out.volume = vt;                                                           // :1054
    out.avrd = avrd == 0.0 ? std::pow(0.75 * vt / lmgc_pi, one_third) : avrd;  // :1059-1064
    out.centre_shift = og;                                                     // :1078
    for (const auto& g : parts) {
      out.contactor_shifts.push_back(g.shift - og);  // :1068-1071
      out.contactor_frames.push_back(g.frame);
      out.contactor_faces.push_back(g.faces);
    }

    if (given_inertia != Vector3d::Zero()) {
      // :1089-1113: the I-line is the principal inertia; identity frame as a placeholder (DOF.INI
      // expected), shifts left in the input axes.
      out.geometric_inertia = given_inertia;
      out.frame.setIdentity();
      out.frame_is_placeholder = true;
    } else {
      // :1117-1153: Huygens about the centre of inertia.
      Matrix3d it = Matrix3d::Zero();
      for (std::size_t i = 0; i < parts.size(); ++i) {
        const ContactorGeometry& g = parts[i];
        const Matrix3d& e = g.frame;
        it += e * (g.inertia.asDiagonal() * e.transpose());
        const Vector3d& s = out.contactor_shifts[i];
        for (int k = 0; k < 3; ++k) {
          Vector3d d = s;
          d[k] = 0.0;
          it(k, k) += g.volume * d.dot(d);
        }
        it(0, 1) -= g.volume * s.x() * s.y();
        it(1, 0) -= g.volume * s.x() * s.y();
        it(0, 2) -= g.volume * s.x() * s.z();
        it(2, 0) -= g.volume * s.x() * s.z();
        it(1, 2) -= g.volume * s.z() * s.y();
        it(2, 1) -= g.volume * s.z() * s.y();
      }
      const PrincipalInertia p = lmgc_diagonalise33(it);  // :1156
      out.geometric_inertia = p.moments;                  // :1165-1167
      out.frame = p.frame;                                // :1169-1172
      for (std::size_t i = 0; i < parts.size(); ++i) {
        out.contactor_shifts[i] = p.frame.transpose() * out.contactor_shifts[i];  // :1175-1181
        if (contactors[i].type == "PLANx" || contactors[i].type == "POLYR" || contactors[i].type == "CYLND")
          out.contactor_frames[i] = p.frame.transpose() * parts[i].frame;  // :1219-1224
      }
    }
    // POLYR vertices in the body frame (about their contactor's centroid); the embedded frame of a
    // POLYR is then the identity.
    for (std::size_t i = 0; i < parts.size(); ++i) {
      std::vector<Vector3d> vertices;
      for (const Vector3d& v : parts[i].vertices) vertices.push_back(out.contactor_frames[i] * v);
      out.contactor_vertices.push_back(std::move(vertices));
      if (contactors[i].type == "POLYR") out.contactor_frames[i].setIdentity();
    }
  }

  out.mass = density * out.volume;                // comp_mass_RBDY3 :3756
  out.inertia = density * out.geometric_inertia;  // :3761-3763
  return out;
}

}  // namespace lmgc::solver
