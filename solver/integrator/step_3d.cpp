#include "solver/integrator/step_3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <span>
#include <tuple>

#include "solver/bodies/rigid_3d_properties.hpp"  // lmgc_pi
#include "solver/detection/cylinder_contact.hpp"
#include "solver/detection/pair_geometry_3d.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/detection/polyhedron_contact.hpp"
#include "solver/detection/sort_interactions.hpp"
#include "solver/nlgs/law_local_problem_3d.hpp"
#include "solver/nlgs/local_solver_3d.hpp"
#include "solver/nlgs/open_contact_visits.hpp"
#include "spatial/multilevel_grid.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// recup_rloc_PRPRx: a PRPRx point takes the previous step's reaction of the point of the same pair
// closer than 1e-3 (squared 1e-6, `tol_recup_rloc`), both seen from the candidate body.
constexpr double kRecupSquaredDistance = 1e-6;

// Fortran's modulo: x wrapped into [0, period).
double wrapped(double x, double period) {
  const double r = std::fmod(x, period);
  return r < 0.0 ? r + period : r;
}

// SPHEb is a sphere of a cluster: TACT_BEHAV.DAT rows name it SPHER.
std::string_view seen_as(const std::string& type) {
  return type == "SPHEb" ? std::string_view("SPHER") : std::string_view(type);
}

// How far ahead in sweep order the sweeps fetch the interaction of a contact they will solve.
constexpr std::size_t kPrefetchDistance = 32;

// Asks for the cache lines a sweep's local solve reads of an interaction: its first 376 bytes (up to
// r), seven lines at most as records of 504 bytes fall.
void prefetch_interaction(const Interaction3D& c) {
  const char* bytes = reinterpret_cast<const char*>(&c);
  for (std::size_t offset = 0; offset <= 384; offset += 64) __builtin_prefetch(bytes + offset);
}

// Relative local velocity (t, n, s) of the contact for body velocities V (numerics.md §2, 3D).
Vector3d local_velocity(const Interaction3D& c, const std::vector<Vector6d>& V) {
  const Vector6d& vc = V[static_cast<std::size_t>(c.candidate_body)];
  const Vector6d& va = V[static_cast<std::size_t>(c.antagonist_body)];
  return c.frame * (vc.head<3>() - va.head<3>()) + c.lever_candidate * vc.tail<3>() -
         c.lever_antagonist * va.tail<3>();
}

// H r of one contact's impulse r (t, n, s): the force and each body's moment in its own axes.
struct ContactImpulse {
  Vector3d force, torque_candidate, torque_antagonist;
};
ContactImpulse impulse_of(const Interaction3D& c, const Vector3d& r) {
  return {c.frame.transpose() * r, c.lever_candidate.transpose() * r, c.lever_antagonist.transpose() * r};
}

// V += M⁻¹ H r for an impulse r (t, n, s) of one contact.
void inject(const Interaction3D& c, const Vector3d& r, RigidBodies3D& b, std::vector<Vector6d>& V) {
  // Fixed-size halves throughout: this runs once per contact and sweep.
  const ContactImpulse f = impulse_of(c, r);
  const auto cd = static_cast<std::size_t>(c.candidate_body),
             an = static_cast<std::size_t>(c.antagonist_body);
  const Vector6d& m_cd = b.inverse_mass[cd];
  const Vector6d& m_an = b.inverse_mass[an];
  V[cd].head<3>() += m_cd.head<3>().cwiseProduct(f.force);
  V[cd].tail<3>() += m_cd.tail<3>().cwiseProduct(f.torque_candidate);
  V[an].head<3>() -= m_an.head<3>().cwiseProduct(f.force);
  V[an].tail<3>() -= m_an.tail<3>().cwiseProduct(f.torque_antagonist);
}

// Ireac += H r of one contact (the end of the solve sums it from the final reactions).
void add_impulse(const Interaction3D& c, const Vector3d& r, std::vector<Vector6d>& impulse) {
  const ContactImpulse f = impulse_of(c, r);
  const auto cd = static_cast<std::size_t>(c.candidate_body),
             an = static_cast<std::size_t>(c.antagonist_body);
  impulse[cd].head<3>() += f.force;
  impulse[cd].tail<3>() += f.torque_candidate;
  impulse[an].head<3>() -= f.force;
  impulse[an].tail<3>() -= f.torque_antagonist;
}

// Delassus block Hᵀ M⁻¹ H of one contact (rigid bodies: exact, numerics.md §3).
Matrix3d delassus_block(const Interaction3D& c, const RigidBodies3D& b) {
  Matrix3d W = Matrix3d::Zero();
  for (int side = 0; side < 2; ++side) {
    const auto body = static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body);
    const Matrix3d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
    const Vector6d& inverse = b.inverse_mass[body];
    W += c.frame * inverse.head<3>().asDiagonal() * c.frame.transpose() +
         lever * inverse.tail<3>().asDiagonal() * lever.transpose();
  }
  return W;
}

// The block the law's local problem is posed with: W, plus ELASTIC_REPELL_CLB's compliance on n.
Matrix3d law_block(const Interaction3D& c) {
  if (c.normal_compliance == 0.0 || c.form != LocalForm3D::coulomb) return c.W;
  Matrix3d WW = c.W;
  WW(1, 1) += c.normal_compliance;
  return WW;
}

// The reaction with the cohesion impulse (correction) of the WET / Mohr laws added, and back: Mohr
// adds it only to a contact that stays closed (mod_nlgs_3D solve_nlgs :4547-4552).
Vector3d with_cohesion(const Interaction3D& c, Vector3d rr) {
  if (c.correction != 0.0 && !(c.correction_needs_contact && rr(1) <= 0.0)) rr(1) += c.correction;
  return rr;
}
Vector3d cohesion_free(const Interaction3D& c, Vector3d r) {
  if (c.correction != 0.0 && !(c.correction_needs_contact && r.isZero(0.0))) r(1) -= c.correction;
  return r;
}

ContactStatus status_of(const Vector3d& r, double mu) {
  if (r(1) <= 0.0) return ContactStatus::noctc;
  const double tangential = std::hypot(r(0), r(2));
  return tangential < mu * r(1) * (1.0 - 1e-10) ? ContactStatus::stick : ContactStatus::slide;
}

}  // namespace

void increment_step(Scene3D& scene, RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  state.time += state.h;
  ++state.step;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.displacement[i] = b.displacement_begin[i];
    b.velocity[i] = b.velocity_begin[i];
    b.impulse[i].setZero();
  }
  // Driven velocities hold at t_begin too (LMGC90 imposes them over DOF.INI's values).
  const double t_begin = state.time - state.h;
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force) b.velocity_begin[static_cast<std::size_t>(d.body)](d.dof) = d.value(t_begin);
}

void compute_external_forces(Scene3D& scene, const RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vector6d f;
    f << b.mass[i] * scene.gravity, gyroscopic_torque(b.inertia[i], b.velocity_begin[i].tail<3>());
    b.external_force[i] = b.visible[i] ? f : Vector6d::Zero();  // invisible bodies wait (source point)
  }
  const double t_begin = state.time - state.h;
  for (const DrivenDof2D& d : scene.driven)
    if (d.is_force)
      b.external_force[static_cast<std::size_t>(d.body)](d.dof) +=
          (1.0 - state.theta) * d.value(t_begin) + state.theta * d.value(state.time);
}

void compute_free_velocity(Scene3D& scene, const RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.velocity_free[i] = b.velocity_begin[i] + state.h * b.inverse_mass[i].cwiseProduct(b.external_force[i]);
    for (int d = 0; d < 6; ++d)
      if (b.driven_mask[i] & (1u << d)) b.velocity_free[i](d) = 0.0;
  }
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force) b.velocity_free[static_cast<std::size_t>(d.body)](d.dof) = d.value(state.time);
  b.velocity = b.velocity_free;
}

namespace {

// LMGC90's sweep order of the 3D families (mod_nlgs_3D prep_nlgs): SPSPx, SPPLx, SPPRx, SPCDx, SPDCx,
// PRPLx, PRPRx, PTPT3, CDCDx, CDPLx.
constexpr std::array<std::uint8_t, kPairFamily3DCount> kSweepRank = [] {
  std::array<std::uint8_t, kPairFamily3DCount> rank{};
  const PairFamily3D order[] = {PairFamily3D::SPSPx, PairFamily3D::SPPLx, PairFamily3D::SPPRx,
                                PairFamily3D::SPCDx, PairFamily3D::SPDCx, PairFamily3D::PRPLx,
                                PairFamily3D::PRPRx, PairFamily3D::PTPT3, PairFamily3D::CDCDx,
                                PairFamily3D::CDPLx};
  for (std::size_t k = 0; k < std::size(order); ++k)
    rank[static_cast<std::size_t>(order[k])] = static_cast<std::uint8_t>(k);
  return rank;
}();

// The sort key of a detected point in LMGC90's enumeration (rigid-3d.md §3.1). The box families
// (SPSPx, SPPLx, PRPRx, CDCDx, CDPLx) cut space into boxes of side Lbox from the lowest contactor
// centres (x and y from 0 when periodic) and visit the boxes z, then y, then x outermost, a box's
// candidates by index, for each the 3 x 3 x 3 boxes around in the same nesting and their
// antagonists by index; PRPRx's big polyhedra and the periodic images come after. PRPLx pairs come
// by candidate then antagonist, SPCDx and SPDCx by antagonist then candidate, PTPT3 links as listed.
class LmgcOrder3D {
 public:
  LmgcOrder3D(const Scene3D& scene, const std::vector<Vector3d>& centre,
              const std::vector<std::uint8_t>& placed)
      : scene_(scene), centre_(centre) {
    const std::size_t n = scene.contactors.size();
    big_.assign(n, 0);
    // Radii as each LMGC90 module takes them.
    double sphere = 0.0, polyhedron = 0.0, polyhedron_min = std::numeric_limits<double>::infinity(),
           polyhedron_sum = 0.0, plane = 0.0, cylinder = 0.0;
    std::size_t polyhedra = 0;
    for (const Contactor3D& c : scene.contactors) switch (c.shape) {
        case ContactorShape3D::sphere:
          sphere = std::max(sphere, c.radius);
          break;
        case ContactorShape3D::polyhedron: {
          const double r = scene.polyhedra[static_cast<std::size_t>(c.polyhedron)].radius;
          polyhedron_sum += r;
          ++polyhedra;
          break;
        }
        case ContactorShape3D::plane:
          plane = std::max(plane, c.half_axes.norm());  // mod_PLANx: sqrt(ax1² + ax2² + ax3²)
          break;
        case ContactorShape3D::cylinder:
          cylinder = std::max(cylinder, c.half_axes.z() + c.radius);  // mod_CYLND: half-length + radius
          break;
        default:
          break;
      }
    // Big polyhedra (mod_PRPRx threshold_big_POLYR 4): out of the grid, and of its radii.
    for (std::size_t k = 0; k < n; ++k) {
      const Contactor3D& c = scene.contactors[k];
      if (c.shape != ContactorShape3D::polyhedron) continue;
      const double r = scene.polyhedra[static_cast<std::size_t>(c.polyhedron)].radius;
      if (polyhedra > 0 && r > 4.0 * polyhedron_sum / static_cast<double>(polyhedra))
        big_[k] = 1;
      else
        polyhedron = std::max(polyhedron, r), polyhedron_min = std::min(polyhedron_min, r);
    }
    std::array<double, kPairFamily3DCount> alert{};
    for (const Visibility3D& v : scene.visibility)
      alert[static_cast<std::size_t>(v.family)] =
          std::max(alert[static_cast<std::size_t>(v.family)], v.alert);
    const auto grid = [&](PairFamily3D f, double ray, double factor) {
      Grid& g = grids_[static_cast<std::size_t>(f)];
      g.on = true;
      double box = factor * (2.0 * ray + alert[static_cast<std::size_t>(f)]);
      if (f == PairFamily3D::PRPRx && std::abs(polyhedron - polyhedron_min) < 1e-4) box *= 2.0;
      g.inverse = box > 0.0 ? 1.0 / box : 0.0;
      g.low = Vector3d::Constant(std::numeric_limits<double>::infinity());
      for (std::size_t k = 0; k < n; ++k)
        if (placed[k] && !big_[k] && in_family(f, scene.contactors[k].shape))
          g.low = g.low.cwiseMin(centre[k]);
      if (scene.x_period > 0.0) g.low.x() = 0.0;
      if (scene.y_period > 0.0) g.low.y() = 0.0;
    };
    grid(PairFamily3D::SPSPx, sphere, 1.01);
    grid(PairFamily3D::SPPLx, std::max(sphere, plane), 1.01);
    grid(PairFamily3D::PRPRx, polyhedron, 1.05);
    const double cylinder_reach = 1.005 * cylinder + alert[static_cast<std::size_t>(PairFamily3D::CDCDx)];
    grid(PairFamily3D::CDCDx, cylinder_reach, 1.01);
    grid(PairFamily3D::CDPLx, std::max(cylinder, plane), 1.01);
    // Each candidate's place in its family's box enumeration: boxes z, y, x outermost, then index.
    for (int f = 0; f < kPairFamily3DCount; ++f) {
      const Grid& g = grids_[static_cast<std::size_t>(f)];
      if (!g.on) continue;
      std::vector<std::pair<std::array<std::int64_t, 4>, std::uint32_t>> keys;
      for (std::size_t k = 0; k < n; ++k) {
        if (!placed[k] || big_[k] || !in_family(static_cast<PairFamily3D>(f), scene.contactors[k].shape))
          continue;
        const auto b = box(g, k);
        keys.push_back({{b[2], b[1], b[0], static_cast<std::int64_t>(k)}, static_cast<std::uint32_t>(k)});
      }
      std::sort(keys.begin(), keys.end());
      std::vector<std::uint32_t>& rank = rank_[static_cast<std::size_t>(f)];
      rank.assign(n, std::numeric_limits<std::uint32_t>::max());
      for (std::size_t p = 0; p < keys.size(); ++p) rank[keys[p].second] = static_cast<std::uint32_t>(p);
    }
  }

  // (high, low): family, section (grid pairs, big polyhedra's, periodic), candidate's rank; then the
  // antagonist's box around the candidate's and the antagonist. Points of a pair keep their order.
  std::pair<std::uint64_t, std::uint64_t> key(const DetectedPoint3D& d) const {
    const auto f = static_cast<std::size_t>(d.family);
    const std::uint64_t family = kSweepRank[f];
    const auto cd = static_cast<std::size_t>(d.candidate), an = static_cast<std::size_t>(d.antagonist);
    const auto pack = [&](std::uint64_t section, std::uint64_t first, std::uint64_t around,
                          std::uint64_t second) {
      return std::pair{(family << 56) | (section << 48) | (first & 0xffffffffffffull),
                       (around << 40) | (second & 0xffffffffffull)};
    };
    switch (d.family) {
      case PairFamily3D::PRPLx:
      case PairFamily3D::SPPRx:
        return pack(0, cd, 0, an);
      case PairFamily3D::SPCDx:
      case PairFamily3D::SPDCx:
        return pack(0, an, 0, cd);
      case PairFamily3D::PTPT3:
        return pack(0, 0, 0, 0);  // the links' own order
      default:
        break;
    }
    const Grid& g = grids_[f];
    if (big_[cd] || big_[an]) return pack(1, big_[an] ? an : cd, 0, big_[an] ? cd : an);
    const std::uint64_t rank = rank_[f][cd];
    if (!d.image.isZero()) {
      // Periodic passes after the grid's: x, then y, then both (LMGC90's x, y, (+x, +y), (+x, -y)).
      const bool x = d.image.x() != 0.0, y = d.image.y() != 0.0;
      const std::uint64_t pass = x && y ? (d.image.x() * d.image.y() > 0.0 ? 4 : 5) : x ? 2 : 3;
      const auto b = box(g, an);
      return pack(pass, rank, static_cast<std::uint64_t>(b[2] * 4096 * 4096 + b[1] * 4096 + b[0]) & 0xffffff,
                  an);
    }
    const auto bc = box(g, cd), ba = box(g, an);
    const std::int64_t d3 = ba[2] - bc[2] + 1, d2 = ba[1] - bc[1] + 1, d1 = ba[0] - bc[0] + 1;
    const bool near = d1 >= 0 && d1 <= 2 && d2 >= 0 && d2 <= 2 && d3 >= 0 && d3 <= 2;
    return pack(0, rank, near ? static_cast<std::uint64_t>(d3 * 9 + d2 * 3 + d1) : 27, an);
  }

 private:
  struct Grid {
    bool on = false;
    double inverse = 0.0;
    Vector3d low = Vector3d::Zero();
  };
  static bool in_family(PairFamily3D f, ContactorShape3D shape) {
    switch (f) {
      case PairFamily3D::SPSPx:
        return shape == ContactorShape3D::sphere;
      case PairFamily3D::SPPLx:
        return shape == ContactorShape3D::sphere || shape == ContactorShape3D::plane;
      case PairFamily3D::PRPRx:
        return shape == ContactorShape3D::polyhedron;
      case PairFamily3D::CDCDx:
        return shape == ContactorShape3D::cylinder;
      case PairFamily3D::CDPLx:
        return shape == ContactorShape3D::cylinder || shape == ContactorShape3D::plane;
      default:
        return false;
    }
  }
  // Box indices as LMGC90 computes them: 1 + int((x - low) / Lbox), by the inverse.
  std::array<std::int64_t, 3> box(const Grid& g, std::size_t k) const {
    std::array<std::int64_t, 3> b{};
    for (int a = 0; a < 3; ++a)
      b[static_cast<std::size_t>(a)] = 1 + static_cast<std::int64_t>((centre_[k](a) - g.low(a)) * g.inverse);
    return b;
  }
  const Scene3D& scene_;
  const std::vector<Vector3d>& centre_;
  std::vector<std::uint8_t> big_;
  std::array<Grid, kPairFamily3DCount> grids_{};
  std::array<std::vector<std::uint32_t>, kPairFamily3DCount> rank_;
};

}  // namespace

void select_prox_tactors(Scene3D& scene, RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  const double h = state.h, theta = state.theta;
  // Detection configuration (numerics.md §1.2, compute_configurationTT).
  std::vector<Vector3d> body_centre(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    body_centre[i] = b.reference[i] + b.displacement_begin[i].head<3>() +
                     h * (1.0 - theta) * b.velocity_begin[i].head<3>();
    b.frame_detection[i] = update_frame(b.frame_initial[i], (1.0 - theta) * b.velocity_begin[i].tail<3>(), h,
                                        FrameUpdate::linearised);
    // Periodic: detection sees the centre wrapped into [0, period) (get_coorTT_RBDY3's modulo).
    if (scene.x_period > 0.0) body_centre[i].x() = wrapped(body_centre[i].x(), scene.x_period);
    if (scene.y_period > 0.0) body_centre[i].y() = wrapped(body_centre[i].y(), scene.y_period);
  }
  const std::size_t n = scene.contactors.size();
  std::vector<Vector3d> centre(n);
  std::vector<double> radii(n);
  std::vector<std::uint8_t> placed(n);
  // PTPT3 rows link fixed point pairs (below): their alerts do not size the grid, points stay out.
  double max_alert = 0.0;
  for (const Visibility3D& v : scene.visibility)
    if (v.family != PairFamily3D::PTPT3) max_alert = std::max(max_alert, v.alert);
  for (std::size_t k = 0; k < n; ++k) {
    const Contactor3D& c = scene.contactors[k];
    const auto body = static_cast<std::size_t>(c.body);
    centre[k] = body_centre[body] + b.frame_detection[body] * c.shift;
    radii[k] = c.bounding_radius;
    placed[k] = c.shape != ContactorShape3D::point && b.visible[body];
  }
  // The visibility row of an ordered (candidate, antagonist) pair, -1 if none: contactors are grouped
  // by (type as `$seety` names it, colour) once, and rows looked up in a class × class table (the
  // string comparisons per grid pair were a tenth of large steps).
  std::vector<std::int32_t> class_of(n);
  std::vector<std::pair<std::string_view, std::string_view>> classes;
  for (std::size_t k = 0; k < n; ++k) {
    const Contactor3D& c = scene.contactors[k];
    const std::pair<std::string_view, std::string_view> name(seen_as(c.type), c.color);
    const auto it = std::find(classes.begin(), classes.end(), name);
    class_of[k] = static_cast<std::int32_t>(it - classes.begin());
    if (it == classes.end()) classes.push_back(name);
  }
  const std::size_t class_count = classes.size();
  // Two contactors of one type (SPSPx, PRPRx, CDCDx) read a row either way round, the first that
  // names their colours (mod_tact_behav get_isee_specific), and the lower index stays the candidate.
  std::vector<std::int32_t> row_table(class_count * class_count, -1);
  for (std::size_t a = 0; a < class_count; ++a)
    for (std::size_t c = 0; c < class_count; ++c)
      for (std::size_t r = 0; r < scene.visibility.size(); ++r) {
        const Visibility3D& v = scene.visibility[r];
        const bool direct = classes[a].first == v.candidate_type && classes[a].second == v.candidate_color &&
                            classes[c].first == v.antagonist_type && classes[c].second == v.antagonist_color;
        const bool turned = v.candidate_type == v.antagonist_type && classes[a].first == v.candidate_type &&
                            classes[c].first == v.candidate_type && classes[a].second == v.antagonist_color &&
                            classes[c].second == v.candidate_color;
        if (direct || turned) {
          row_table[a * class_count + c] = static_cast<std::int32_t>(r);
          break;
        }
      }
  const auto row_of = [&](std::size_t cd, std::size_t an) {
    return row_table[static_cast<std::size_t>(class_of[cd]) * class_count +
                     static_cast<std::size_t>(class_of[an])];
  };
  // POLYR vertices and face normals at the detection configuration, one flat array each.
  std::vector<PlacedPolyhedron> placed_polyhedron(n);
  std::vector<Vector3d> polyhedron_vertices, polyhedron_normals;
  std::vector<std::size_t> vertex_offset(n + 1, 0), normal_offset(n + 1, 0);
  double smallest_polyhedron = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    const Contactor3D& c = scene.contactors[k];
    vertex_offset[k + 1] = vertex_offset[k];
    normal_offset[k + 1] = normal_offset[k];
    if (c.shape != ContactorShape3D::polyhedron) continue;
    const Polyhedron& shape = scene.polyhedra[static_cast<std::size_t>(c.polyhedron)];
    const Matrix3d& frame = b.frame_detection[static_cast<std::size_t>(c.body)];
    for (const Vector3d& v : shape.vertices) polyhedron_vertices.push_back(centre[k] + frame * v);
    for (const Vector3d& normal : shape.face_normals) polyhedron_normals.push_back(frame * normal);
    vertex_offset[k + 1] += shape.vertices.size();
    normal_offset[k + 1] += shape.face_normals.size();
    smallest_polyhedron = std::min(smallest_polyhedron, shape.radius);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Contactor3D& c = scene.contactors[k];
    if (c.shape != ContactorShape3D::polyhedron) continue;
    PlacedPolyhedron& p = placed_polyhedron[k];
    p.shape = &scene.polyhedra[static_cast<std::size_t>(c.polyhedron)];
    p.vertices = std::span<const Vector3d>(polyhedron_vertices)
                     .subspan(vertex_offset[k], vertex_offset[k + 1] - vertex_offset[k]);
    p.normals = std::span<const Vector3d>(polyhedron_normals)
                    .subspan(normal_offset[k], normal_offset[k + 1] - normal_offset[k]);
    p.centre = centre[k];
    p.radius = c.bounding_radius;
  }

  LargeArray<DetectedPoint3D>& found = state.detected;
  found.clear();
  // One point per contact point, in detection's order; the interactions are built from them once
  // they are sorted (below). `image`: the antagonist's periodic shift (zero but across a periodic
  // side). PTPT3's levers reach each body's own point (the contactors' centres), the others' the
  // contact point.
  const auto add_point = [&](std::size_t i, std::size_t j, const Vector3d& image, int row, const Vector3d& t,
                             const Vector3d& normal, const Vector3d& s, const Vector3d& point, double gap,
                             int vertex, double surface) {
    DetectedPoint3D& d = found.emplace_back();
    d.family = scene.visibility[static_cast<std::size_t>(row)].family;
    d.candidate = static_cast<std::int32_t>(i);
    d.antagonist = static_cast<std::int32_t>(j);
    d.visibility = row;
    d.vertex = vertex;
    d.frame.row(0) = t.transpose();
    d.frame.row(1) = normal.transpose();
    d.frame.row(2) = s.transpose();
    d.point = point;
    d.image = image;
    d.gap = gap;
    d.surface = surface;
  };
  std::vector<Vector3d> image_vertices;  // a periodic image's vertices (PRPRx)
  const auto fine = [&](std::size_t i, std::size_t j, const Vector3d& image) {
    const Contactor3D& cd = scene.contactors[i];
    const Contactor3D& an = scene.contactors[j];
    if (cd.body == an.body || cd.shape == ContactorShape3D::plane) return false;
    if (cd.shape == ContactorShape3D::point || an.shape == ContactorShape3D::point) return true;
    const int row = row_of(i, j);
    if (row < 0) return false;
    const Visibility3D& v = scene.visibility[static_cast<std::size_t>(row)];
    // LMGC90's PLANx frame is (T, S, N) = (e1, -e2, e3) of the body axes times the contactor's
    // frame (mod_SPPLx, mod_PRPLx).
    const auto plane_axes = [&] {
      Matrix3d axes = b.frame_detection[static_cast<std::size_t>(an.body)] * an.local_frame;
      axes.col(1) = -axes.col(1);
      return axes;
    };
    const bool across = !image.isZero();
    // LMGC90 has no periodic images for contacts with planes (mod_PRPLx, mod_SPPLx).
    if (across && (v.family == PairFamily3D::SPPLx || v.family == PairFamily3D::PRPLx ||
                   v.family == PairFamily3D::CDPLx))
      return true;
    const auto cylinder = [&](std::size_t k, const Vector3d& shift) {
      const Contactor3D& c = scene.contactors[k];
      PlacedCylinder placed;
      placed.centre = centre[k] + shift;
      placed.axis = (b.frame_detection[static_cast<std::size_t>(c.body)] * c.local_frame).col(2);
      placed.half_length = c.half_axes.z();
      placed.radius = c.radius;
      return placed;
    };
    if (v.family == PairFamily3D::SPDCx) {
      ContactGeometry3D g;
      if (detect_sphere_tube(centre[i], cd.radius, cylinder(j, image), v.alert, g))
        add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.point, g.gap, 0,
                  lmgc_pi * 0.01 * cd.radius * cd.radius);  // get_surf_SPDCx = π (0.1 r_s)²
      return true;
    }
    if (v.family == PairFamily3D::SPCDx) {
      ContactGeometry3D g;
      if (detect_sphere_cylinder(centre[i], cd.radius, cylinder(j, image), v.alert, g))
        add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.point, g.gap, 0,
                  lmgc_pi * cd.radius * cd.radius);
      return true;
    }
    if (v.family == PairFamily3D::CDCDx) {
      CylinderContact g;
      if (detect_cylinder_cylinder(cylinder(i, Vector3d::Zero()), cylinder(j, image), v.alert, g)) {
        const double reduced = cd.radius * an.radius / (cd.radius + an.radius);
        for (int k = 0; k < g.count; ++k) {
          const ContactGeometry3D& p = g.points[static_cast<std::size_t>(k)];
          add_point(i, j, image, row, p.tangent, p.normal, p.second_tangent, p.point, p.gap, k + 1,
                    reduced * std::min(cd.half_axes.z(), an.half_axes.z()));
        }
      }
      return true;
    }
    if (v.family == PairFamily3D::CDPLx) {
      // The two cap spheres (centre ± H a, first +H as mod_CDPLx) against the plane, as SPPLx.
      const PlacedCylinder c = cylinder(i, Vector3d::Zero());
      int rank = 0;
      for (const double side : {1.0, -1.0}) {
        ++rank;
        ContactGeometry3D g;
        if (detect_sphere_plane(c.centre + side * c.half_length * c.axis, c.radius, centre[j], plane_axes(),
                                an.half_axes, v.alert, g))
          add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.point, g.gap, rank,
                    c.half_length * c.radius);
      }
      return true;
    }
    if (v.family == PairFamily3D::SPSPx || v.family == PairFamily3D::SPPLx) {
      ContactGeometry3D g;
      const bool hit =
          v.family == PairFamily3D::SPSPx
              ? detect_sphere_sphere(centre[i], cd.radius, centre[j] + image, an.radius, v.alert, g)
              : detect_sphere_plane(centre[i], cd.radius, centre[j], plane_axes(), an.half_axes, v.alert, g);
      const double surface = v.family == PairFamily3D::SPSPx
                                 ? lmgc_pi * std::pow(cd.radius * an.radius / (cd.radius + an.radius), 2)
                                 : lmgc_pi * cd.radius * cd.radius;
      if (hit) add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.point, g.gap, 0, surface);
      return true;
    }
    if (v.family == PairFamily3D::SPPRx) {
      PlacedPolyhedron polyhedron = placed_polyhedron[j];
      if (across) {
        image_vertices.assign(polyhedron.vertices.begin(), polyhedron.vertices.end());
        for (Vector3d& x : image_vertices) x += image;
        polyhedron.vertices = image_vertices;
        polyhedron.centre += image;
      }
      ContactGeometry3D g;
      // Bounding spheres first (compute_contact_SPPRx), then the surface.
      if ((centre[i] - polyhedron.centre).norm() < cd.radius + polyhedron.radius + v.alert &&
          detect_sphere_polyhedron(centre[i], cd.radius, polyhedron, v.alert, g))
        add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.point, g.gap, 0,
                  lmgc_pi * cd.radius * cd.radius);  // as SPPLx (LMGC90's SPPRx area is left unset)
      return true;
    }
    PlacedPolyhedron antagonist = placed_polyhedron[j];
    if (across && an.shape == ContactorShape3D::polyhedron) {
      image_vertices.assign(antagonist.vertices.begin(), antagonist.vertices.end());
      for (Vector3d& x : image_vertices) x += image;
      antagonist.vertices = image_vertices;
      antagonist.centre += image;
    }
    PolyhedronContact g;
    const bool hit =
        v.family == PairFamily3D::PRPLx
            ? detect_polyhedron_plane(placed_polyhedron[i], centre[j], plane_axes(), an.half_axes, v.alert, g)
            : detect_polyhedron_polyhedron(placed_polyhedron[i], antagonist, v.alert, smallest_polyhedron,
                                           scene.cundall_iterations, g);
    if (hit)
      for (int k = 0; k < g.count; ++k) {
        const auto m = static_cast<std::size_t>(k);
        add_point(i, j, image, row, g.tangent, g.normal, g.second_tangent, g.points[m], g.gaps[m],
                  v.family == PairFamily3D::PRPLx ? g.vertices[m] + 1 : 0, g.area / g.count);
      }
    return true;
  };
  // Periodic images: every contactor (planes excepted) near a periodic side gets a ghost entry
  // shifted by ± the period, so that the grid also reports the pairs across the sides.
  std::vector<std::size_t> origin(n);
  std::vector<Vector3d> shift(n, Vector3d::Zero());
  std::iota(origin.begin(), origin.end(), std::size_t{0});
  if (scene.x_period > 0.0 || scene.y_period > 0.0) {
    double reach = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (scene.contactors[k].shape != ContactorShape3D::plane) reach = std::max(reach, radii[k]);
    const double margin = 2.0 * reach + max_alert;
    const auto sides = [&](double x, double period) {
      std::vector<int> out{0};
      if (period <= 0.0) return out;
      if (x < margin) out.push_back(1);
      if (x > period - margin) out.push_back(-1);
      return out;
    };
    for (std::size_t k = 0; k < n; ++k) {
      if (scene.contactors[k].shape == ContactorShape3D::plane || !placed[k]) continue;
      for (int sx : sides(centre[k].x(), scene.x_period))
        for (int sy : sides(centre[k].y(), scene.y_period)) {
          if (sx == 0 && sy == 0) continue;
          const Vector3d offset(sx * scene.x_period, sy * scene.y_period, 0.0);
          origin.push_back(k);
          shift.push_back(offset);
          centre.push_back(centre[k] + offset);
          radii.push_back(radii[k]);
          placed.push_back(1);
        }
    }
  }
  std::set<std::tuple<std::size_t, std::size_t, int, int>> images_seen;
  spatial::MultilevelGrid grid;
  grid.build(centre, radii, placed, max_alert);
  grid.for_each_candidate_pair(centre, radii, max_alert, [&](std::size_t i, std::size_t j) {
    std::size_t a = origin[i], c = origin[j];
    if (a == c || (i >= n && j >= n)) return;
    Vector3d image = shift[j] - shift[i];  // of c relative to a
    if (a > c) {
      std::swap(a, c);
      image = -image;
    }
    if (!image.isZero()) {
      const auto sign = [](double x) { return static_cast<int>(x > 0.0) - static_cast<int>(x < 0.0); };
      const auto key = std::tuple(a, c, sign(image.x()), sign(image.y()));
      if (!images_seen.insert(key).second) return;
    }
    // As in 2D: the lower index is the candidate when a visibility row reads the pair that way.
    if (!fine(a, c, image)) fine(c, a, Vector3d(-image));
  });
  // PTPT3: every link of two visible points, at their unwrapped detection positions.
  for (const PointLink3D& link : scene.point_links) {
    const auto i = static_cast<std::size_t>(link.candidate), j = static_cast<std::size_t>(link.antagonist);
    const auto cd_body = static_cast<std::size_t>(scene.contactors[i].body);
    const auto an_body = static_cast<std::size_t>(scene.contactors[j].body);
    if (!b.visible[cd_body] || !b.visible[an_body]) continue;
    const auto position = [&](std::size_t k, std::size_t body) {
      return Vector3d(b.reference[body] + b.displacement_begin[body].head<3>() +
                      h * (1.0 - theta) * b.velocity_begin[body].head<3>() +
                      b.frame_detection[body] * scene.contactors[k].shift);
    };
    // A link across a periodic side sees the antagonist shifted by its periods, or the candidate
    // the other way (PointLink3D).
    const Vector3d shift = period_shift(scene, link.periods);
    const Vector3d cd_point = position(i, cd_body) - (link.shift_candidate ? shift : Vector3d::Zero()),
                   an_point = position(j, an_body) + (link.shift_candidate ? Vector3d::Zero() : shift);
    const ContactGeometry3D g = point_point_geometry(cd_point, an_point);
    add_point(i, j, Vector3d::Zero(), link.visibility, g.tangent, g.normal, g.second_tangent, g.point, g.gap,
              link.pair_rank, 0.0);
    found.back().reference_gap = link.reference_length;
  }
  // The interaction of one point: local frame rows (t, n, s), lever rows, Delassus block.
  const auto interaction_of = [&](const DetectedPoint3D& d) {
    const Contactor3D& cd = scene.contactors[static_cast<std::size_t>(d.candidate)];
    const Contactor3D& an = scene.contactors[static_cast<std::size_t>(d.antagonist)];
    Interaction3D c;
    c.family = d.family;
    c.candidate = d.candidate;
    c.antagonist = d.antagonist;
    c.candidate_body = cd.body;
    c.antagonist_body = an.body;
    c.law = scene.visibility[static_cast<std::size_t>(d.visibility)].law;
    c.visibility = d.visibility;
    c.vertex = d.vertex;
    c.frame = d.frame;
    c.point = d.point;
    c.gap_begin = d.gap;
    for (int side = 0; side < 2; ++side) {
      const auto body = static_cast<std::size_t>(side == 0 ? cd.body : an.body);
      // PTPT3 (only the links above make its points): about the contactors' (wrapped) centres.
      const Vector3d& own = d.family == PairFamily3D::PTPT3
                                ? centre[static_cast<std::size_t>(side == 0 ? d.candidate : d.antagonist)]
                                : d.point;
      const Vector3d lever = own - body_centre[body] - (side == 0 ? Vector3d::Zero() : d.image);
      Matrix3d& G = side == 0 ? c.lever_candidate : c.lever_antagonist;
      for (int k = 0; k < 3; ++k)
        G.row(k) =
            (b.frame_detection[body].transpose() * lever.cross(c.frame.row(k).transpose())).transpose();
    }
    c.candidate_point = b.frame_detection[static_cast<std::size_t>(cd.body)].transpose() *
                        (d.point - body_centre[static_cast<std::size_t>(cd.body)]);
    c.velocity_begin = local_velocity(c, b.velocity_begin);
    c.W = delassus_block(c, b);
    return c;
  };
  // In LMGC90's order (docs/lmgc90-facts/rigid-3d.md §3.1): the families as mod_nlgs_3D sweeps
  // them, in a family the pairs as its rough detection enumerates them, the points of a pair as the
  // fine detection finds them. Each interaction is written once, in that order, from its point, so
  // that no gather copies the large records into order afterwards.
  const LmgcOrder3D lmgc_order(scene, centre, placed);
  const std::vector<std::uint32_t> order =
      interaction_order(found, [&](const DetectedPoint3D& d) { return lmgc_order.key(d); });
  state.contacts.clear();
  state.law_states.clear();
  // With room to grow: a packing that gains a few contacts would otherwise take a new buffer, which
  // the kernel zeroes page by page as it is first written (64k spheres: 100 MB).
  if (found.size() > state.contacts.capacity()) state.contacts.reserve(found.size() + found.size() / 8);
  const bool keeps_law_state = scene_keeps_law_state_3d(scene);
  const auto append = [&](const DetectedPoint3D& d) {
    state.contacts.push_back(interaction_of(d));
    if (!keeps_law_state) return;
    LawState3D& law_state = state.law_states.emplace_back();
    law_state.surface = d.surface;
    law_state.reference_gap = d.reference_gap;
  };
  if (order.empty())
    for (const DetectedPoint3D& d : found) append(d);
  else
    for (const std::uint32_t k : order) append(found[k]);
}

bool scene_keeps_law_state_3d(const Scene3D& scene) {
  for (const Visibility3D& v : scene.visibility)
    if (keeps_law_state_3d(scene.laws[static_cast<std::size_t>(v.law)].law)) return true;
  return false;
}

namespace {
// The stored list: the interactions' verlet entries, in their order (detection's).
struct StoredListBuilder {
  LargeArray<StoredInteraction3D>& stored;
  explicit StoredListBuilder(LargeArray<StoredInteraction3D>& list) : stored(list) {
    stored.clear();  // keeps its buffer
  }
  void append(const Interaction3D& c, const LawState3D* law_state) { stored.emplace_back(c, law_state); }
  void finish() {}
};
}  // namespace

void store_interactions(RunState3D& state, std::span<const Interaction3D> interactions,
                        std::span<const LawState3D> law_states) {
  StoredListBuilder builder(state.previous);
  for (std::size_t k = 0; k < interactions.size(); ++k)
    builder.append(interactions[k], law_states.empty() ? nullptr : &law_states[k]);
  builder.finish();
}

void recup_rloc(RunState3D& state) {
  // Key: the contactor pair and, for PRPLx, the candidate vertex; PRPRx points of a pair are then
  // told apart by position (numerics.md §4, recup_rloc_PRPRx / recup_rloc_PRPLx); the first stored
  // entry that matches is taken. The stored entries of each candidate contactor are listed together
  // (LMGC90's verlet lists are by candidate too), so a lookup reads its candidate's few entries.
  const LargeArray<StoredInteraction3D>& previous = state.previous;
  std::size_t contactors = 0;
  for (const StoredInteraction3D& p : previous)
    contactors = std::max<std::size_t>(contactors, static_cast<std::size_t>(p.candidate) + 1);
  thread_local std::vector<std::uint32_t> first, by_candidate, next;
  first.assign(contactors + 1, 0);
  for (const StoredInteraction3D& p : previous) ++first[static_cast<std::size_t>(p.candidate) + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  by_candidate.resize(previous.size());
  next.assign(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < previous.size(); ++k)
    by_candidate[next[static_cast<std::size_t>(previous[k].candidate)]++] = static_cast<std::uint32_t>(k);
  const bool keeps_law_state = !state.law_states.empty();
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    Interaction3D& c = state.contacts[k];
    const StoredInteraction3D* match = nullptr;
    const auto cd = static_cast<std::size_t>(c.candidate);
    if (cd + 1 < first.size())
      for (std::uint32_t m = first[cd]; m < first[cd + 1] && !match; ++m) {
        const StoredInteraction3D& p = previous[by_candidate[m]];
        if (p.family == c.family && p.antagonist == c.antagonist && p.vertex == c.vertex &&
            (c.family != PairFamily3D::PRPRx ||
             (p.candidate_point - c.candidate_point).squaredNorm() < kRecupSquaredDistance))
          match = &p;
      }
    if (!match) {
      c.r.setZero();
      c.status_begin = ContactStatus::nknow;
      continue;
    }
    c.r = match->r;
    c.status_begin = match->status;
    if (keeps_law_state) state.law_states[k].internal = match->internal;
  }
}

NlgsResult solve_contacts(Scene3D& scene, RunState3D& state, const NlgsOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RigidBodies3D& b = scene.bodies;
  NlgsResult result;
  LargeArray<Interaction3D>& contacts = state.contacts;
  std::vector<Vector6d>& V = b.velocity;
  V = b.velocity_free;
  for (auto& impulse : b.impulse) impulse.setZero();
  double q_squared = 0.0;
  const bool first = !state.laws_initialized && !contacts.empty();
  if (!contacts.empty()) state.laws_initialized = true;
  const LawStep law_step{state.h, state.time, state.step == 1, first};
  std::vector<std::uint8_t> law_updates_at_check(scene.laws.size());
  for (std::size_t l = 0; l < scene.laws.size(); ++l)
    law_updates_at_check[l] = updates_at_check(scene.laws[l].law);
  // Contact k's law state; in a scene whose laws keep none, one that no law reads.
  LawState3D unused_law_state;
  const auto law_state = [&](std::size_t k) -> LawState3D& {
    return state.law_states.empty() ? unused_law_state : state.law_states[k];
  };
  // Whether each contact is without reaction, beside its visits: a sweep passes most open contacts
  // by on these 12 bytes without reading their 504-byte interaction (open_contact_visits.hpp): in a
  // packing most contacts are open, and a pass-by would read two cache lines of it.
  struct OpenContact {
    OpenContactSchedule visits;
    bool no_reaction = true;
    bool solved_at(std::int32_t sweep) const { return !no_reaction || !visits.passes_by(sweep); }
  };
  std::vector<OpenContact> open(contacts.size());
  // One pass over the interactions (on large scenes each pass streams them from memory): the law's
  // problem, |q|, the warm start's impulse and whether the contact starts without reaction.
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    Interaction3D& c = contacts[k];
    // Each law's derived problem (its own file, solver/laws/*.hpp).
    if (!prepare_law(scene.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k), law_step))
      c.inactive = true;
    if (c.inactive) c.r.setZero();
    const Vector3d q = local_velocity(c, b.velocity_free) + c.covfree;
    if (!c.inactive) q_squared += q.squaredNorm();
    if (!c.inactive && !c.r.isZero(0.0)) inject(c, c.r, b, V);
    open[k].no_reaction = c.r.isZero(0.0);
  }
  result.free_velocity_norm = std::sqrt(q_squared);

  const double local_tolerance = 1e-10 * std::max(result.free_velocity_norm, 1e-300);
  // Inexact local solves in the sweeps: a Newton solve also stops at 1/100 of the residual of its
  // start (mostly the previous reaction), so sweeps far from convergence do not pay for 1e-10; near
  // convergence the start is already close and the tolerance rules. The check pass solves exactly.
  constexpr double sweep_forcing = 1e-2;
  // A sticking contact keeps its previous reaction when that solves its problem within 1/20 of the
  // local tolerance (local_solver_3d.hpp): converged sweeps then repeat their reactions bit for bit
  // and the rest of the block is skipped (below), where exact solves traded round-off for hundreds of
  // sweeps (100_PR_PerioBox checks every 400). 1/20 keeps the achieved residual at or below the exact
  // solves'.
  const double keep_tolerance = local_tolerance / 20.0;
  // Each block's inverse in the local solver's order, once per step, when its contact first meets a
  // compressive free velocity: a contact that stays open, as most of a packing's do, never needs it.
  std::vector<Matrix3d> W_inverse(contacts.size());
  std::vector<std::uint8_t> inverted(contacts.size(), 0);
  const auto inverse_of = [&](std::size_t k) -> const Matrix3d& {
    if (!inverted[k]) {
      const Matrix3d W_normal_first = swap_normal_first(law_block(contacts[k]));
      bool invertible = false;
      const double scale = W_normal_first.cwiseAbs().maxCoeff();
      W_normal_first.computeInverseWithCheck(W_inverse[k], invertible, 1e-14 * scale * scale * scale);
      if (!invertible) W_inverse[k].setConstant(std::nan(""));
      inverted[k] = 1;
    }
    return W_inverse[k];
  };
  // One local solve of contact k with the others frozen; returns the new reaction. The local problem
  // is posed on rr = r − correction e_n (cohesive laws, contact-laws.md §3.2), r = rr + correction.
  const auto local_solve = [&](std::size_t k, Vector3d& q_local, double forcing) {
    const Interaction3D& c = contacts[k];
    // Rods, wires, cohesive zones: the law's own local problem (law_local_problem_3d.hpp), whatever
    // the resolution (LMGC90's diagonal variants of these are not reproduced).
    if (c.form != LocalForm3D::coulomb) {
      q_local = local_velocity(c, V) - c.W * c.r + c.covfree;
      return solve_law_form_3d(c, law_state(k), q_local, c.r, local_tolerance);
    }
    // The others' contribution and the free velocity, plus the cohesion term −c h W e_n.
    const Vector3d correction(0.0, c.correction, 0.0);
    const Vector3d rr_previous = cohesion_free(c, c.r);
    if (options.diagonal_resolution) {
      // solve_nlgs with diagonal_resolution (mod_nlgs_3D): only the diagonal self-terms removed.
      const Vector3d diagonal = c.W.diagonal();
      q_local = local_velocity(c, V) - diagonal.cwiseProduct(c.r - correction) + c.covfree;
      if (q_local(1) >= 0.0) return with_cohesion(c, Vector3d::Zero());
      Vector3d r = -q_local.cwiseQuotient(law_block(c).diagonal());  // invWnn = 1/WWnn
      const double bound = c.mu * r(1), tangential_squared = r(0) * r(0) + r(2) * r(2);
      // Inside the cone by a margin far above the sum of squares' round-off, |r_T| > bound cannot hold,
      // and std::hypot (costly, and called at every update) is only taken near or outside it: the
      // same decisions and reactions bit for bit.
      if (bound >= 0.0 && tangential_squared < bound * bound * (1.0 - 1e-12)) return with_cohesion(c, r);
      const double tangential = std::hypot(r(0), r(2));
      if (tangential > bound && tangential > 1e-18) {
        r(0) *= bound / tangential;
        r(2) *= bound / tangential;
      }
      return with_cohesion(c, r);
    }
    q_local = local_velocity(c, V) - c.W * (c.r - correction) + c.covfree;
    // A separating free velocity needs no inverse: the solver returns r = 0 before it would invert.
    const Matrix3d* inverse = q_local(1) < 0.0 ? &inverse_of(k) : nullptr;
    const LocalSolution3D s =
        solve_signorini_coulomb_3d(swap_normal_first(law_block(c)), inverse, swap_normal_first(q_local), c.mu,
                                   swap_normal_first(rr_previous), local_tolerance, forcing, keep_tolerance);
    ++result.local_solves;
    return with_cohesion(c, swap_normal_first(s.r));
  };
  const double tol = options.tolerance;
  const int max_checks = options.gs_it2;
  // Sweep order: detection order, or LMGC90's quick scramble before each block of gs_it1 sweeps
  // (nlgs_3D_SetWithQuickScramble; quick_scramble.hpp).
  std::vector<std::size_t> order(contacts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (options.quick_scramble) state.scramble.prepare(contacts.size());
  // The reaction a sweep gives contact k, relaxed.
  const auto sweep_reaction = [&](std::size_t k) {
    Vector3d q_local;
    Vector3d r_new = local_solve(k, q_local, sweep_forcing);
    if (options.relax != 1.0) r_new = options.relax * r_new + (1.0 - options.relax) * contacts[k].r;
    return r_new;
  };
  // After a sweep that changed no reaction: whether the open contacts it may have passed by would
  // keep theirs too. Then every local solve returns its contact's reaction, no velocity moves, and
  // the rest of the block would repeat this state bit for bit, so it is skipped (counted as done).
  const auto stands_still = [&] {
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (open[k].no_reaction && !contacts[k].inactive && sweep_reaction(k) != contacts[k].r) return false;
    return true;
  };
  for (int check = 0; check < max_checks; ++check) {
    const auto sweeps_start = std::chrono::steady_clock::now();
    if (options.quick_scramble) state.scramble.scramble(order);
    for (OpenContact& o : open) o.visits.restart();
    for (int sweep = 0; sweep < options.gs_it1; ++sweep) {
      bool changed = false;
      for (std::size_t position = 0; position < order.size(); ++position) {
        // The contact this sweep will solve a few dozen positions on is fetched now: when most
        // contacts are passed by, the solved ones lie far apart in a list larger than the caches,
        // and each waited for its interaction's lines to come from memory.
        if (position + kPrefetchDistance < order.size()) {
          const std::size_t ahead = order[position + kPrefetchDistance];
          if (open[ahead].solved_at(sweep)) prefetch_interaction(contacts[ahead]);
        }
        const std::size_t k = order[position];
        OpenContact& o = open[k];
        if (o.no_reaction && o.visits.skip(sweep)) continue;
        Interaction3D& c = contacts[k];
        if (c.inactive) continue;
        const Vector3d r_new = sweep_reaction(k);
        o.no_reaction = r_new.isZero(0.0);
        if (!o.no_reaction) o.visits.restart();
        if (r_new != c.r) {
          inject(c, r_new - c.r, b, V);
          changed = true;
        }
        c.r = r_new;
      }
      ++result.iterations;
      if (!changed && sweep + 1 < options.gs_it1 && stands_still()) {
        const int rest = options.gs_it1 - sweep - 1;
        result.iterations += rest;
        result.sweeps_skipped += rest;
        break;
      }
    }
    result.sweep_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - sweeps_start).count();
    // Check pass (numerics.md §4.1): one more local solve per contact, r left unchanged.
    NlgsCheckSums sums;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      Interaction3D& c = contacts[k];
      if (c.inactive) continue;
      Vector3d q_local;
      const Vector3d r_check = local_solve(k, q_local, 0.0);
      // Laws that re-evaluate their state at a check do it with the velocity of this solution.
      if (law_updates_at_check[static_cast<std::size_t>(c.law)])
        update_law_at_check(scene.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k),
                            local_velocity(c, V) + c.W * (r_check - c.r), law_step);
      const Vector3d mean_r = 0.5 * (c.r + r_check);
      const Vector3d dv = c.W * (c.r - r_check);
      const double dvdv = dv.squaredNorm();
      const double rr = mean_r.squaredNorm();
      if (rr == 0.0) continue;
      sums.active += 1.0;
      sums.dvdv += dvdv;
      sums.max_dvdv = std::max(sums.max_dvdv, dvdv);
      sums.dvdvrr += dvdv * rr;
      sums.max_dvdvrr = std::max(sums.max_dvdvrr, dvdv * rr);
      sums.dvor += mean_r.dot(dv);
      const Vector3d wr = c.W * c.r, wr_check = c.W * r_check;
      sums.wrr += 0.5 * (wr.dot(c.r) + wr_check.dot(r_check));
      sums.wrwr += 0.5 * (wr.squaredNorm() + wr_check.squaredNorm());
    }
    result.norms = nlgs_norms(sums, tol);
    if (!std::isfinite(result.norms.mean_dvor) || !std::isfinite(result.norms.quad_dv)) {
      result.diverged = true;
      break;
    }
    result.converged = nlgs_check_passes(options.norm, result.norms);
    if (result.converged) break;
  }
  if (contacts.empty()) result.converged = true;

  // Post (mod_nlgs_3D solve_nlgs i_post after RnodHRloc): the velocities rebuilt from scratch
  // (Vfree + M^-1 H r), then one more relaxed sweep that solves every contact. With
  // Stored_Delassus_Loops LMGC90 does not inject that sweep's changes: the bodies end the step with
  // the velocities and impulses of the reactions before it, the contacts keep the new reactions.
  const bool stored_delassus = options.storage == NlgsStorage::stored_delassus_loops;
  std::vector<Vector6d> velocity_before_post;
  if (!contacts.empty()) {
    V = b.velocity_free;
    for (Interaction3D& c : contacts)
      if (!c.inactive && !c.r.isZero(0.0)) inject(c, c.r, b, V);
    if (stored_delassus) {
      velocity_before_post = V;
      for (const Interaction3D& c : contacts)
        if (!c.inactive && !c.r.isZero(0.0)) add_impulse(c, c.r, b.impulse);
    }
    for (const std::size_t k : order) {
      Interaction3D& c = contacts[k];
      if (c.inactive) continue;
      Vector3d q_local;
      const Vector3d r_solved = local_solve(k, q_local, sweep_forcing);
      // Laws that re-evaluate their state at a check do it here too, from this solution's velocity.
      if (law_updates_at_check[static_cast<std::size_t>(c.law)])
        update_law_at_check(scene.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k),
                            local_velocity(c, V) + c.W * (r_solved - c.r), law_step);
      const Vector3d r_new =
          options.relax != 1.0 ? Vector3d(options.relax * r_solved + (1.0 - options.relax) * c.r) : r_solved;
      if (r_new != c.r) inject(c, r_new - c.r, b, V);
      c.r = r_new;
    }
  }

  // End of the solve, in one pass: Ireac of every body from the final reactions, relative velocities,
  // statuses, and the natural-map residual of the local problems (fc3d/FORMAT.md §3) in the auxiliary
  // variables u + covfree.
  double residual_squared = 0.0;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    Interaction3D& c = contacts[k];
    if (!stored_delassus && !c.inactive && !c.r.isZero(0.0)) add_impulse(c, c.r, b.impulse);
    c.u = local_velocity(c, V);
    if (c.inactive) {
      c.status = ContactStatus::noctc;
      continue;
    }
    if (c.r.squaredNorm() > 0.0) ++result.active;
    if (c.form != LocalForm3D::coulomb) {
      const Vector3d uu = c.u + c.covfree;
      c.status = law_form_status_3d(c, law_state(k), c.r, uu);
      residual_squared += law_form_residual_3d(c, law_state(k), c.r, uu).squaredNorm();
    } else {
      const Vector3d rr = cohesion_free(c, c.r);
      c.status = status_of(rr, c.mu);
      Vector3d uu = c.u + c.covfree;
      uu(1) += c.normal_compliance * rr(1);  // ELASTIC_REPELL_CLB's WW (0 for the other laws)
      residual_squared += natural_map_3d(swap_normal_first(rr), swap_normal_first(uu), c.mu).squaredNorm();
    }
    finish_law(scene.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k), law_step);
  }
  if (stored_delassus && !contacts.empty()) V = std::move(velocity_before_post);
  result.residual_absolute = std::sqrt(residual_squared);
  result.residual_relative = result.free_velocity_norm > 0.0
                                 ? result.residual_absolute / result.free_velocity_norm
                                 : result.residual_absolute;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void compute_dof(Scene3D& scene, const RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  const double h = state.h, theta = state.theta;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.visible[i]) continue;  // comp_dof_RBDY3 skips invisible bodies
    b.displacement[i].head<3>() =
        b.displacement_begin[i].head<3>() +
        h * ((1.0 - theta) * b.velocity_begin[i].head<3>() + theta * b.velocity[i].head<3>());
    b.displacement[i].tail<3>().setZero();
    const Vector3d spin = b.velocity[i].tail<3>();
    b.frame[i] = scene.rotation == FrameUpdate::cayley
                     ? update_frame(b.frame_initial[i], spin, h, FrameUpdate::cayley)
                     : update_frame(b.frame_detection[i], theta * spin, h, FrameUpdate::linearised);
  }
}

void update_step(Scene3D& scene, RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.displacement_begin[i] = b.displacement[i];
    b.velocity_begin[i] = b.velocity[i];
    b.frame_initial[i] = b.frame[i];
  }
  StoredListBuilder builder(state.previous);
  const bool keeps_law_state = !state.law_states.empty();
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    Interaction3D& c = state.contacts[k];
    c.status_begin = c.status;
    builder.append(c, keeps_law_state ? &state.law_states[k] : nullptr);
  }
  builder.finish();
}

namespace {
// Contactor 1 of body i is a SPHER or POLYR (the bodies a source point handles) of colour `color`.
const Contactor3D* first_contactor(const Scene3D& scene, std::size_t i) {
  for (const Contactor3D& c : scene.contactors)
    if (static_cast<std::size_t>(c.body) == i && c.rank == 1) return &c;
  return nullptr;
}
bool enters_by_source(const Contactor3D* c) {
  return c && (c->type == "SPHER" || c->type == "POLYR");
}
}  // namespace

void init_source_point(Scene3D& scene, std::size_t first, double radius, const Vector3d& point,
                       bool absolute) {
  RigidBodies3D& b = scene.bodies;
  if (first >= b.size()) return;
  scene.source = SourcePoint3D{true, false, first, radius, point};
  for (std::size_t i = 0; i <= first; ++i) b.visible[i] = 1;
  if (absolute) b.reference[first].setZero();
  b.displacement_begin[first].head<3>() = point;
  b.displacement[first] = b.displacement_begin[first];
  for (std::size_t i = first + 1; i < b.size(); ++i) {
    const Contactor3D* c = first_contactor(scene, i);
    if (!enters_by_source(c) || c->color == "BASEx") continue;
    b.visible[i] = 0;
    if (absolute) b.reference[i].setZero();
    b.displacement_begin[i].setZero();
    b.displacement[i].setZero();
    b.velocity_begin[i].head<3>().setZero();
    b.velocity[i].head<3>().setZero();
  }
}

void check_source_point(Scene3D& scene) {
  RigidBodies3D& b = scene.bodies;
  SourcePoint3D& s = scene.source;
  const std::size_t next = s.last + 1;
  if (s.stopped || next >= b.size()) return;
  if (!enters_by_source(first_contactor(scene, next))) {
    s.stopped = true;
    return;
  }
  // The last body's X is its position: its reference was set to 0.
  if ((b.displacement[s.last].head<3>() - s.point).squaredNorm() <= s.radius * s.radius) return;
  s.last = next;
  b.visible[next] = 1;
  b.displacement[next].head<3>() = s.point;
}

NlgsResult step_3d(Scene3D& scene, RunState3D& state, const NlgsOptions& options) {
  increment_step(scene, state);
  compute_external_forces(scene, state);
  compute_free_velocity(scene, state);
  select_prox_tactors(scene, state);
  recup_rloc(state);
  const NlgsResult result = solve_contacts(scene, state, options);
  compute_dof(scene, state);
  if (scene.source.active) check_source_point(scene);
  update_step(scene, state);
  return result;
}

}  // namespace lmgc::solver
