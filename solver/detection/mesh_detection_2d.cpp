#include "solver/detection/mesh_detection_2d.hpp"

#include <cmath>
#include <map>
#include <string>

#include "solver/bodies/lmgc_pi.hpp"
#include "solver/detection/pair_geometry_2d.hpp"
#include "solver/model/mesh_contact_2d.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;

// mailx-2d-contact.md §5.2: a point within this fraction of a segment's ends is at its vertex.
constexpr double kVertexTolerance = 1e-5;

Vector2d node_at(const VectorXd& x, std::int32_t n) {
  return Vector2d(x(2 * n), x(2 * n + 1));
}

// The left normal of a → b: outward for a polyline described clockwise (mailx-2d-contact.md §4).
Vector2d left_normal(const Vector2d& a, const Vector2d& b) {
  const Vector2d t = (b - a) / (b - a).norm();
  return Vector2d(-t.y(), t.x());
}

// The '$seety' rows of the scene by colour: each contactor's colour as a small id, and for a pair of
// contactor types the first row (in LMGC90's order) of each (candidate colour, antagonist colour), so
// that the pair loops look a row up by two indices instead of comparing strings per pair.
class SeeRows {
 public:
  explicit SeeRows(const Scene2D& scene) : scene_(scene) {
    for (const Contactor2D& c : scene.contactors) rigid_.push_back(id_of(c.color));
    for (const MeshContactor& c : scene.deformable.meshes.contactors) mesh_.push_back(id_of(c.color));
  }
  int rigid_colour(std::size_t k) const { return rigid_[k]; }
  int mesh_colour(std::size_t k) const { return mesh_[k]; }
  // The rows of the (candidate type, antagonist type) pairs: rows[cd colour × colours + an colour], -1
  // where no row sees them.
  std::vector<std::int32_t> table(std::string_view cd_type, std::string_view an_type) const {
    const std::size_t n = ids_.size();
    std::vector<std::int32_t> rows(n * n, -1);
    for (std::size_t v = 0; v < scene_.visibility.size(); ++v) {
      const Visibility2D& row = scene_.visibility[v];
      const auto cd = ids_.find(row.candidate_color), an = ids_.find(row.antagonist_color);
      if (row.candidate_type != cd_type || row.antagonist_type != an_type || cd == ids_.end() ||
          an == ids_.end())
        continue;
      std::int32_t& slot =
          rows[static_cast<std::size_t>(cd->second) * n + static_cast<std::size_t>(an->second)];
      if (slot < 0) slot = static_cast<std::int32_t>(v);  // the first match wins
    }
    return rows;
  }
  std::size_t colours() const { return ids_.size(); }

 private:
  int id_of(const std::string& colour) {
    return ids_.emplace(colour, static_cast<int>(ids_.size())).first->second;
  }
  const Scene2D& scene_;
  std::map<std::string, int> ids_;
  std::vector<int> rigid_, mesh_;
};

// Nodes whose two velocity dofs are driven: a contact between such nodes only is not detected
// (mailx-2d-contact.md §5.2).
std::vector<std::vector<std::uint8_t>> fully_driven_nodes(const Scene2D& scene) {
  const DeformableBodies& d = scene.deformable;
  std::vector<std::vector<std::uint8_t>> driven(d.states.size());
  for (std::size_t m = 0; m < d.states.size(); ++m) {
    std::vector<std::uint8_t> dofs(d.meshes.bodies[m].dofs(), 0);
    for (std::int32_t dof : d.states[m].velocity_driven) dofs[static_cast<std::size_t>(dof)] = 1;
    driven[m].assign(d.meshes.bodies[m].nodes(), 0);
    for (std::size_t n = 0; n < driven[m].size(); ++n) driven[m][n] = dofs[2 * n] && dofs[2 * n + 1];
  }
  return driven;
}

struct Frame {
  double gap = 0.0;
  Vector2d normal = Vector2d::Zero(), point = Vector2d::Zero();
  double beta = 0.0;  // position on the antagonist segment, 0 at its first node
};

// CLxxx length (mailx-2d-contact.md §2): the deformed edge over its two points; axisymmetric bodies
// weigh it by 2πr at the point.
double candidate_point_length(const Scene2D& scene, const MeshContactor& cl, const VectorXd& x) {
  const Vector2d a = node_at(x, cl.nodes[0]), b = node_at(x, cl.nodes[1]);
  double length = (b - a).norm() / 2.0;
  if (scene.deformable.meshes.bodies[static_cast<std::size_t>(cl.mesh)].hypothesis ==
      fem::Hypothesis::axisymmetric)
    length *= fem::kAxisymmetricTwoPi * ((1.0 - cl.apab) * a.x() + cl.apab * b.x());
  return length;
}

// A rigid disk's centre: its body's position q plus its offset turned by the body's angle.
Vector2d disk_centre(const Contactor2D& dk, const Vector3d& q) {
  const double cs = std::cos(q.z()), sn = std::sin(q.z());
  return q.head<2>() + Vector2d(cs * dk.shift.x() - sn * dk.shift.y(), sn * dk.shift.x() + cs * dk.shift.y());
}

}  // namespace

VectorXd mesh_detection_coordinates(const Scene2D& scene, std::size_t mesh, double theta, double h) {
  const fem::MeshBody& body = scene.deformable.meshes.bodies[mesh];
  const MeshBodyState& s = scene.deformable.states[mesh];
  VectorXd x(static_cast<Eigen::Index>(body.dofs()));
  for (std::size_t i = 0; i < body.dofs(); ++i) x(static_cast<Eigen::Index>(i)) = body.coordinates[i];
  return x + s.x_begin + (1.0 - theta) * h * s.v_begin;
}

void detect_mesh_contacts_2d(const Scene2D& scene, std::span<const Vector3d> body_coordinates,
                             std::span<const VectorXd> node_coordinates, PointPairs2D& point_pairs,
                             LargeArray<Interaction2D>& out) {
  const DeformableBodies& d = scene.deformable;
  const std::vector<MeshContactor>& tactors = d.meshes.contactors;
  const auto driven = fully_driven_nodes(scene);
  const SeeRows see(scene);
  const std::size_t colours = see.colours();
  const auto row_in = [&](const std::vector<std::int32_t>& table, int cd_colour, int an_colour) {
    return table[static_cast<std::size_t>(cd_colour) * colours + static_cast<std::size_t>(an_colour)];
  };
  const RigidBodies2D& b = scene.bodies;
  const auto mesh_side_driven = [&](const Interaction2D& c, int side) {
    const MeshSide2D s = mesh_side(scene, c, side);
    for (int k = 0; k < 2; ++k)
      if (s.weights(k) != 0.0 && !driven[static_cast<std::size_t>(s.mesh)]
                                        [static_cast<std::size_t>(s.nodes[static_cast<std::size_t>(k)])])
        return false;
    return true;
  };
  const auto add = [&](PairFamily2D family, std::int32_t cd, std::int32_t an, std::int32_t row,
                       const Frame& f) {
    Interaction2D& c = out.emplace_back();
    c.family = family;
    c.candidate = cd;
    c.antagonist = an;
    c.visibility = row;
    c.law = scene.visibility[static_cast<std::size_t>(row)].law;
    c.normal = f.normal;
    c.point = f.point;
    c.gap_begin = f.gap;
    return &c;
  };
  // A side's local (t, n) velocity at the beginning of the step: its nodes' by their weights on a
  // mesh, (v + ω × lever) on a rigid body.
  const auto side_velocity_begin = [&](const Interaction2D& c, int side) {
    if (side_on_mesh(c.family, side)) {
      const MeshSideRows rows = mesh_side_rows(scene, c, side);
      return mesh_side_local_velocity(rows, d.states[static_cast<std::size_t>(rows.side.mesh)].v_begin);
    }
    const Vector3d& v =
        b.velocity_begin[static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body)];
    const Vector2d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
    return Vector2d(v.head<2>().dot(c.tangent()) + v.z() * lever(0),
                    v.head<2>().dot(c.normal) + v.z() * lever(1));
  };
  const auto relative_velocity_begin = [&](Interaction2D& c) {
    c.velocity_begin = side_velocity_begin(c, 0) - side_velocity_begin(c, 1);
  };

  // CLALp (mod_CLALp creation_tab_visu and compute_one_contact: mailx-2d-contact.md §5).
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::CLALp)]) {
    const std::vector<std::int32_t> rows = see.table("CLxxx", "ALpxx");
    for (std::size_t icl = 0; icl < tactors.size(); ++icl) {
      const MeshContactor& cl = tactors[icl];
      if (cl.shape != MeshContactorShape::candidate_point) continue;
      const VectorXd& xc = node_coordinates[static_cast<std::size_t>(cl.mesh)];
      const Vector2d ca = node_at(xc, cl.nodes[0]), cb = node_at(xc, cl.nodes[1]);
      const Vector2d p = (1.0 - cl.apab) * ca + cl.apab * cb;
      const Vector2d cl_normal = left_normal(ca, cb);
      double dist_min = 1e20, gap_min = 1e20;
      std::int32_t best = -1, best_node = -1, best_row = -1;
      for (std::size_t ial = 0; ial < tactors.size(); ++ial) {
        const MeshContactor& al = tactors[ial];
        if (al.shape != MeshContactorShape::polyline) continue;
        // Points and segments of one body with one colour do not see each other.
        if (al.mesh == cl.mesh && al.color == cl.color) continue;
        const std::int32_t row = row_in(rows, see.mesh_colour(icl), see.mesh_colour(ial));
        if (row < 0) continue;
        const VectorXd& xa = node_coordinates[static_cast<std::size_t>(al.mesh)];
        const auto nb = static_cast<std::int32_t>(al.nodes.size());
        const auto X = [&](std::int32_t k) { return node_at(xa, al.nodes[static_cast<std::size_t>(k)]); };
        const auto segment_normal = [&](std::int32_t k) { return left_normal(X(k), X(k + 1)); };
        // The closest node whose segment faces the point (the last node keeps the previous
        // segment's test, as LMGC90's loop does).
        double dist_l_min = 1e20, pscal = 0.0;
        std::int32_t inode = -1;
        for (std::int32_t k = 0; k < nb; ++k) {
          const double dist = (p - X(k)).norm();
          if (k < nb - 1) pscal = segment_normal(k).dot(cl_normal);
          if (dist - dist_l_min < -1e-7 && pscal < -1e-3) {
            dist_l_min = dist;
            inode = k;
          }
        }
        if (inode < 0) continue;
        // The segment next to that node that faces the point and on whose side the point lies.
        const auto facing = [&](std::int32_t k) { return segment_normal(k).dot(cl_normal) < -1e-3; };
        const bool closed = (X(nb - 1) - X(inode)).squaredNorm() < 1e-14;
        std::int32_t segment = -1;
        if (inode == 0) {
          if (facing(0) && (X(1) - X(0)).dot(p - X(0)) >= 0.0)
            segment = 0;
          else if (closed && facing(nb - 2))
            inode = nb - 1, segment = nb - 2;
        } else if (inode == nb - 1) {
          if (facing(nb - 2) && (X(nb - 2) - X(nb - 1)).dot(p - X(nb - 1)) >= 0.0)
            segment = nb - 2;
          else if (closed && facing(0))  // LMGC90 tests the last node against itself here: always "closed"
            inode = 0, segment = 0;
        } else {
          if (facing(inode) && (X(inode + 1) - X(inode)).dot(p - X(inode)) >= 0.0)
            segment = inode;
          else if (facing(inode - 1))
            segment = inode - 1;
        }
        if (segment < 0) continue;
        const Vector2d a = X(segment), bb = X(segment + 1);
        if ((p - a).norm() > (bb - a).norm()) continue;
        const double g = std::fabs((p - a).dot(left_normal(a, bb)));
        if (g - gap_min < -1e-7 && g <= scene.visibility[static_cast<std::size_t>(row)].alert &&
            dist_l_min - dist_min < 1e-3) {
          dist_min = dist_l_min;
          gap_min = g;
          best = static_cast<std::int32_t>(ial);
          best_node = inode;
          best_row = row;
        }
      }
      if (best < 0) continue;
      // Fine detection on the segment next to the closest node.
      const MeshContactor& al = tactors[static_cast<std::size_t>(best)];
      const VectorXd& xa = node_coordinates[static_cast<std::size_t>(al.mesh)];
      const auto nb = static_cast<std::int32_t>(al.nodes.size());
      const auto X = [&](std::int32_t k) { return node_at(xa, al.nodes[static_cast<std::size_t>(k)]); };
      std::int32_t s = 0;
      if (best_node == 0)
        s = 0;
      else if (best_node == nb - 1)
        s = nb - 2;
      else
        s = (X(best_node + 1) - X(best_node)).dot(p - X(best_node)) >= 0.0 ? best_node : best_node - 1;
      const Vector2d a = X(s), bb = X(s + 1);
      const double L = (bb - a).norm();
      const Vector2d t = (bb - a) / L, n(-t.y(), t.x());
      double beta = (p - a).dot(t) / L;
      const Vector2d projection = a + beta * L * t;
      const double gap = (p - projection).dot(n);
      const double alert = scene.visibility[static_cast<std::size_t>(best_row)].alert;
      if (gap > alert) continue;
      Frame f;
      if (beta >= kVertexTolerance && beta - 1.0 <= -kVertexTolerance) {
        f = Frame{gap, n, projection, beta};
      } else {
        // At a vertex of the polyline (mailx-2d-contact.md §5.2): the normal from the vertex to the
        // point, or the segment's where they meet, or the mean of the two segments' at the vertex.
        const bool first_end = beta < kVertexTolerance;
        beta = first_end ? 0.0 : 1.0;
        const Vector2d vertex = first_end ? a : bb;
        const std::int32_t end_node = first_end ? 0 : nb - 1;
        const std::int32_t other = first_end ? s - 1 : s + 1;  // the adjacent segment
        const Vector2d dv = p - vertex;
        Vector2d normal = n;
        double vertex_gap = gap;
        if (dv.norm() > alert * 1e-3) {
          normal = dv / dv.norm();
          if (n.dot(normal) < 0.0) normal = -normal;
          vertex_gap = dv.dot(normal);
        } else if (best_node != end_node && other >= 0 && other < nb - 1) {
          const Vector2d e = X(other + 1) - X(other);
          normal = 0.5 * (n + Vector2d(-e.y(), e.x()) / e.norm());
          normal /= normal.norm();
          vertex_gap = dv.dot(normal);
        }
        f = Frame{vertex_gap, normal, 0.5 * (p + vertex), beta};
      }
      Interaction2D probe;
      probe.family = PairFamily2D::CLALp;
      probe.candidate = static_cast<std::int32_t>(icl);
      probe.antagonist = best;
      probe.antagonist_segment = s + 1;
      probe.lever_candidate = Vector2d(1.0 - cl.apab, cl.apab);
      probe.lever_antagonist = Vector2d(1.0 - f.beta, f.beta);
      if (mesh_side_driven(probe, 0) && mesh_side_driven(probe, 1)) continue;
      Interaction2D* c = add(PairFamily2D::CLALp, static_cast<std::int32_t>(icl), best, best_row, f);
      c->candidate_body = cl.mesh;
      c->antagonist_body = al.mesh;
      c->antagonist_segment = s + 1;
      c->lever_candidate = probe.lever_candidate;
      c->lever_antagonist = probe.lever_antagonist;
      c->length = candidate_point_length(scene, cl, node_coordinates[static_cast<std::size_t>(cl.mesh)]);
      relative_velocity_begin(*c);
    }
  }

  // CLJCx (mod_CLJCx: mailx-2d-contact.md §7): the first JONCx whose box holds the point.
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::CLJCx)]) {
    const std::vector<std::int32_t> rows = see.table("CLxxx", "JONCx");
    for (std::size_t icl = 0; icl < tactors.size(); ++icl) {
      const MeshContactor& cl = tactors[icl];
      if (cl.shape != MeshContactorShape::candidate_point) continue;
      const VectorXd& xc = node_coordinates[static_cast<std::size_t>(cl.mesh)];
      const Vector2d p = (1.0 - cl.apab) * node_at(xc, cl.nodes[0]) + cl.apab * node_at(xc, cl.nodes[1]);
      for (std::size_t j = 0; j < scene.contactors.size(); ++j) {
        const Contactor2D& jc = scene.contactors[j];
        if (jc.shape != ContactorShape2D::joncx || !b.visible[static_cast<std::size_t>(jc.body)]) continue;
        const std::int32_t row = row_in(rows, see.mesh_colour(icl), see.rigid_colour(j));
        if (row < 0) continue;
        const double alert = scene.visibility[static_cast<std::size_t>(row)].alert;
        const Vector3d& q = body_coordinates[static_cast<std::size_t>(jc.body)];
        const double cs = std::cos(q.z()), sn = std::sin(q.z());
        const Vector2d e1(cs, sn), e2(-sn, cs);
        const Vector2d centre = q.head<2>() + jc.shift.x() * e1 + jc.shift.y() * e2;
        const Vector2d dp = p - centre;
        const double d1 = dp.dot(e1), d2 = dp.dot(e2);
        if (std::fabs(d1) > jc.half_length + jc.half_width + 1.005 * alert ||
            std::fabs(d2) > jc.half_width + 1.005 * alert)
          continue;
        Vector2d local_normal;
        double gap = 0.0;
        if (std::fabs(d1) <= jc.half_length) {
          local_normal = Vector2d(0.0, d2 >= 0.0 ? 1.0 : -1.0);
          gap = std::fabs(d2) - jc.half_width;
        } else {
          const Vector2d r(d1 - std::copysign(jc.half_length, d1), d2);
          local_normal = r / r.norm();
          gap = r.norm() - jc.half_width;
        }
        if (gap <= alert) {
          Frame f;
          f.gap = gap;
          f.normal = local_normal.x() * e1 + local_normal.y() * e2;
          f.point = p - gap * f.normal;  // on the JONCx surface
          Interaction2D probe;
          probe.family = PairFamily2D::CLJCx;
          probe.candidate = static_cast<std::int32_t>(icl);
          probe.lever_candidate = Vector2d(1.0 - cl.apab, cl.apab);
          const bool rigid_fixed = b.inverse_mass[static_cast<std::size_t>(jc.body)].isZero(0.0);
          if (!(rigid_fixed && mesh_side_driven(probe, 0))) {
            Interaction2D* c = add(PairFamily2D::CLJCx, static_cast<std::int32_t>(icl),
                                   static_cast<std::int32_t>(j), row, f);
            c->candidate_body = cl.mesh;
            c->antagonist_body = jc.body;
            c->lever_candidate = probe.lever_candidate;
            const Vector2d lever = f.point - centre;
            const Vector2d t = c->tangent();
            c->lever_antagonist = Vector2d(cross_2d(lever, t), cross_2d(lever, c->normal));
            c->length = candidate_point_length(scene, cl, xc);
            relative_velocity_begin(*c);
          }
        }
        break;  // at most one JONCx per point
      }
    }
  }

  // P2P2L (mod_P2P2L): the pairs of PT2DL points made at the first detection, every step; the normal
  // from the antagonist's point to the candidate's, the gap their distance.
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::P2P2L)]) {
    const auto point_of = [&](const MeshContactor& pt) {
      const VectorXd& x = node_coordinates[static_cast<std::size_t>(pt.mesh)];
      return Vector2d((1.0 - pt.apab) * node_at(x, pt.nodes[0]) + pt.apab * node_at(x, pt.nodes[1]));
    };
    if (!point_pairs.made) {
      // Every two PT2DL, the candidate the first in the case's order; the see table read both ways.
      const std::vector<std::int32_t> rows = see.table("PT2DL", "PT2DL");
      for (std::size_t i = 0; i < tactors.size(); ++i) {
        if (tactors[i].shape != MeshContactorShape::point) continue;
        for (std::size_t j = i + 1; j < tactors.size(); ++j) {
          if (tactors[j].shape != MeshContactorShape::point) continue;
          const std::int32_t forward = row_in(rows, see.mesh_colour(i), see.mesh_colour(j));
          const std::int32_t backward = row_in(rows, see.mesh_colour(j), see.mesh_colour(i));
          const std::int32_t row =
              forward < 0 ? backward : (backward < 0 ? forward : std::min(forward, backward));
          if (row < 0) continue;
          const double distance = (point_of(tactors[i]) - point_of(tactors[j])).norm();
          if (distance > scene.visibility[static_cast<std::size_t>(row)].alert) continue;
          point_pairs.pairs.push_back(
              PointPair2D{static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), row, distance < 1e-20});
        }
      }
      point_pairs.made = true;
    }
    for (const PointPair2D& pair : point_pairs.pairs) {
      const MeshContactor& cd = tactors[static_cast<std::size_t>(pair.candidate)];
      const MeshContactor& an = tactors[static_cast<std::size_t>(pair.antagonist)];
      const Vector2d xc = point_of(cd), xa = point_of(an);
      const double distance = (xc - xa).norm();
      Frame f;
      // Glued, or two points that have met (LMGC90 divides by their zero distance there): e_y.
      if (pair.glued || distance < 1e-20)
        f = Frame{pair.glued ? 0.0 : distance, Vector2d(0.0, 1.0), 0.5 * (xc + xa), 0.0};
      else
        f = Frame{distance, (xc - xa) / distance, 0.5 * (xc + xa), 0.0};
      Interaction2D* c = add(PairFamily2D::P2P2L, pair.candidate, pair.antagonist, pair.row, f);
      c->candidate_body = cd.mesh;
      c->antagonist_body = an.mesh;
      c->lever_candidate = Vector2d(1.0 - cd.apab, cd.apab);
      c->lever_antagonist = Vector2d(1.0 - an.apab, an.apab);
      relative_velocity_begin(*c);
    }
  }

  // PLALp (mod_PLALp: mailx-2d-contact.md §6): ALpxx, segment, polygon, vertex.
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::PLALp)]) {
    const std::vector<std::int32_t> rows = see.table("POLYG", "ALpxx");
    for (std::size_t ial = 0; ial < tactors.size(); ++ial) {
      const MeshContactor& al = tactors[ial];
      if (al.shape != MeshContactorShape::polyline) continue;
      const VectorXd& xa = node_coordinates[static_cast<std::size_t>(al.mesh)];
      for (std::size_t s = 0; s + 1 < al.nodes.size(); ++s) {
        const Vector2d a = node_at(xa, al.nodes[s]), bb = node_at(xa, al.nodes[s + 1]);
        const double L = (bb - a).norm();
        const Vector2d middle = 0.5 * (a + bb), n = left_normal(a, bb), t(n.y(), -n.x());
        for (std::size_t k = 0; k < scene.contactors.size(); ++k) {
          const Contactor2D& pg = scene.contactors[k];
          if (pg.shape != ContactorShape2D::polygon || !b.visible[static_cast<std::size_t>(pg.body)])
            continue;
          const std::int32_t row = row_in(rows, see.rigid_colour(k), see.mesh_colour(ial));
          if (row < 0) continue;
          const double alert = scene.visibility[static_cast<std::size_t>(row)].alert;
          const Vector3d& q = body_coordinates[static_cast<std::size_t>(pg.body)];
          const Vector2d centre = q.head<2>();
          if ((middle - centre).norm() - pg.bounding_radius - 0.5 * L - alert >= 0.0) continue;
          const double cs = std::cos(q.z()), sn = std::sin(q.z());
          for (std::int32_t v = 0; v < pg.vertex_count; ++v) {
            const Vector2d& local = scene.vertices[static_cast<std::size_t>(pg.first_vertex + v)];
            const Vector2d vertex =
                centre + Vector2d(cs * local.x() - sn * local.y(), sn * local.x() + cs * local.y());
            if (n.dot(vertex - centre) >= 0.0 || (middle - vertex).norm() - 0.5 * L - alert >= 0.0) continue;
            const double beta = (vertex - a).dot(t) / L;
            const double gap = (vertex - a).dot(n);
            if (gap > alert || beta < -kVertexTolerance || beta > 1.0 + kVertexTolerance) continue;
            const Vector2d projection = a + beta * L * t;
            Frame f{gap, n, 0.5 * (vertex + projection), beta};
            Interaction2D probe;
            probe.family = PairFamily2D::PLALp;
            probe.antagonist = static_cast<std::int32_t>(ial);
            probe.antagonist_segment = static_cast<std::int32_t>(s) + 1;
            probe.lever_antagonist = Vector2d(1.0 - beta, beta);
            if (b.inverse_mass[static_cast<std::size_t>(pg.body)].isZero(0.0) && mesh_side_driven(probe, 1))
              continue;
            Interaction2D* c = add(PairFamily2D::PLALp, static_cast<std::int32_t>(k),
                                   static_cast<std::int32_t>(ial), row, f);
            c->candidate_body = pg.body;
            c->antagonist_body = al.mesh;
            c->candidate_vertex = v + 1;
            c->antagonist_segment = probe.antagonist_segment;
            const Vector2d lever = vertex - centre;
            c->lever_candidate = Vector2d(cross_2d(lever, t), cross_2d(lever, n));
            c->lever_antagonist = probe.lever_antagonist;
            c->length = pg.bounding_radius;
            relative_velocity_begin(*c);
          }
        }
      }
    }
  }

  // DKALp (mod_DKALp: disks, then ALpxx, then segments): a disk within reach of a segment's bounding
  // circle is tested against it; beyond the segment's ends (up to the radius plus the alert), the
  // end node is the antagonist point. One contact per disk and segment.
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::DKALp)]) {
    const std::vector<std::int32_t> rows = see.table("DISKx", "ALpxx");
    for (std::size_t k = 0; k < scene.contactors.size(); ++k) {
      const Contactor2D& dk = scene.contactors[k];
      if (dk.shape != ContactorShape2D::disk || !b.visible[static_cast<std::size_t>(dk.body)]) continue;
      const Vector3d& q = body_coordinates[static_cast<std::size_t>(dk.body)];
      const Vector2d centre = disk_centre(dk, q);
      for (std::size_t ial = 0; ial < tactors.size(); ++ial) {
        const MeshContactor& al = tactors[ial];
        if (al.shape != MeshContactorShape::polyline) continue;
        const std::int32_t row = row_in(rows, see.rigid_colour(k), see.mesh_colour(ial));
        if (row < 0) continue;
        const double alert = scene.visibility[static_cast<std::size_t>(row)].alert;
        const VectorXd& xa = node_coordinates[static_cast<std::size_t>(al.mesh)];
        for (std::size_t s = 0; s + 1 < al.nodes.size(); ++s) {
          const Vector2d a = node_at(xa, al.nodes[s]), bb = node_at(xa, al.nodes[s + 1]);
          const double L = (bb - a).norm();
          const Vector2d middle = 0.5 * (a + bb);
          const double reach = dk.radius + 0.5 * L + alert;
          if ((middle - centre).squaredNorm() >= reach * reach) continue;
          Vector2d n = left_normal(a, bb), t(n.y(), -n.x());
          const double along = (centre - a).dot(t);
          Frame f;
          if (along >= 0.0 && along <= L) {
            f = Frame{(centre - a).dot(n) - dk.radius, n, a + along * t, along / L};
          } else if (along < 0.0 && along > -(dk.radius + alert)) {
            n = (centre - a) / (centre - a).norm();
            f = Frame{(centre - a).dot(n) - dk.radius, n, a, 0.0};
          } else if (along > L && along < L + dk.radius + alert) {
            n = (centre - bb) / (centre - bb).norm();
            f = Frame{(centre - bb).dot(n) - dk.radius, n, bb, 1.0};
          } else {
            continue;
          }
          if (f.gap > alert || f.gap < -dk.radius) continue;
          Interaction2D probe;
          probe.family = PairFamily2D::DKALp;
          probe.antagonist = static_cast<std::int32_t>(ial);
          probe.antagonist_segment = static_cast<std::int32_t>(s) + 1;
          probe.lever_antagonist = Vector2d(1.0 - f.beta, f.beta);
          if (b.inverse_mass[static_cast<std::size_t>(dk.body)].isZero(0.0) && mesh_side_driven(probe, 1))
            continue;
          Interaction2D* c =
              add(PairFamily2D::DKALp, static_cast<std::int32_t>(k), static_cast<std::int32_t>(ial), row, f);
          c->candidate_body = dk.body;
          c->antagonist_body = al.mesh;
          c->antagonist_segment = probe.antagonist_segment;
          // Levers from the body's centre to the point on the segment (mod_DKALp), through the disk's
          // offset on its body.
          const Vector2d lever = f.point - q.head<2>();
          c->lever_candidate = Vector2d(cross_2d(lever, c->tangent()), cross_2d(lever, c->normal));
          c->lever_antagonist = probe.lever_antagonist;
          relative_velocity_begin(*c);
        }
      }
    }
  }

  // DKDKL (mod_DKDKL): a rigid DISKx against each DISKL it sees, within the alert; the normal from the
  // DISKL's centre to the disk's, the point on the disk.
  if (scene.plan.families[static_cast<std::size_t>(PairFamily2D::DKDKL)]) {
    const std::vector<std::int32_t> rows = see.table("DISKx", "DISKL");
    for (std::size_t k = 0; k < scene.contactors.size(); ++k) {
      const Contactor2D& dk = scene.contactors[k];
      if (dk.shape != ContactorShape2D::disk || !b.visible[static_cast<std::size_t>(dk.body)]) continue;
      const Vector3d& q = body_coordinates[static_cast<std::size_t>(dk.body)];
      const Vector2d centre = disk_centre(dk, q);
      for (std::size_t l = 0; l < tactors.size(); ++l) {
        const MeshContactor& dl = tactors[l];
        if (dl.shape != MeshContactorShape::disk) continue;
        const std::int32_t row = row_in(rows, see.rigid_colour(k), see.mesh_colour(l));
        if (row < 0) continue;
        const double alert = scene.visibility[static_cast<std::size_t>(row)].alert;
        // get_coorTT_DISKL: the centre r − h behind the edge's point, on the edge's left.
        const VectorXd& x = node_coordinates[static_cast<std::size_t>(dl.mesh)];
        const Vector2d a = node_at(x, dl.nodes[0]), bb = node_at(x, dl.nodes[1]);
        const double radius = dl.disk_radius();
        const Vector2d an_centre =
            (1.0 - dl.apab) * a + dl.apab * bb - (radius - dl.arc_height) * left_normal(a, bb);
        const Vector2d between = centre - an_centre;
        const double distance = between.norm();
        const double gap = distance - (dk.radius + radius);
        if (gap > alert) continue;
        // Concentric (LMGC90 divides by the zero distance there): e_y.
        const Vector2d n = distance > 0.0 ? Vector2d(between / distance) : Vector2d(0.0, 1.0);
        Interaction2D* c = add(PairFamily2D::DKDKL, static_cast<std::int32_t>(k),
                               static_cast<std::int32_t>(l), row, Frame{gap, n, centre - dk.radius * n, 0.0});
        c->candidate_body = dk.body;
        c->antagonist_body = dl.mesh;
        const Vector2d lever = c->point - q.head<2>();
        c->lever_candidate = Vector2d(cross_2d(lever, c->tangent()), cross_2d(lever, c->normal));
        c->lever_antagonist = bb - a;  // the edge: mesh_side_rows builds the DISKL's maps from it
        c->length = dk.radius * radius / (dk.radius + radius);
        relative_velocity_begin(*c);
      }
    }
  }
}

}  // namespace lmgc::solver
