#include "solver/detection/detection_3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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
#include "solver/model/contact_kinematics_3d.hpp"
#include "spatial/multilevel_grid.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Fortran's modulo: x wrapped into [0, period).
double wrapped(double x, double period) {
  const double r = std::fmod(x, period);
  return r < 0.0 ? r + period : r;
}

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
      : centre_(centre) {
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
  const std::vector<Vector3d>& centre_;
  std::vector<std::uint8_t> big_;
  std::array<Grid, kPairFamily3DCount> grids_{};
  std::array<std::vector<std::uint32_t>, kPairFamily3DCount> rank_;
};

}  // namespace

void update_visibility_index_3d(const Scene3D& scene, VisibilityIndex3D& index) {
  const std::size_t n = scene.contactors.size();
  if (index.built && index.contactors == n && index.rows == scene.visibility.size()) return;
  index.class_of.assign(n, 0);
  std::vector<std::pair<std::string_view, std::string_view>> classes;
  for (std::size_t k = 0; k < n; ++k) {
    const Contactor3D& c = scene.contactors[k];
    const std::pair<std::string_view, std::string_view> name(grammar::see_name(c.type), c.color);
    const auto it = std::find(classes.begin(), classes.end(), name);
    index.class_of[k] = static_cast<std::int32_t>(it - classes.begin());
    if (it == classes.end()) classes.push_back(name);
  }
  const std::size_t class_count = classes.size();
  // Two contactors of one type (SPSPx, PRPRx, CDCDx) read a row either way round, the first that
  // names their colours (mod_tact_behav get_isee_specific), and the lower index stays the candidate.
  index.row.assign(class_count * class_count, -1);
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
          index.row[a * class_count + c] = static_cast<std::int32_t>(r);
          break;
        }
      }
  index.class_count = class_count;
  index.contactors = n;
  index.rows = scene.visibility.size();
  index.built = true;
}

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
  // The visibility row of an ordered (candidate, antagonist) pair, -1 if none.
  update_visibility_index_3d(scene, state.visibility);
  const VisibilityIndex3D& visibility = state.visibility;
  const auto row_of = [&](std::size_t cd, std::size_t an) { return visibility.row_of(cd, an); };
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

}  // namespace lmgc::solver
