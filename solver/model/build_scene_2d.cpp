#include "solver/model/build_scene_2d.hpp"

#include <cmath>
#include <set>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/tact_behav/see_table.hpp"
#include "solver/bodies/lmgc_pi.hpp"
#include "solver/bodies/rigid_2d_properties.hpp"
#include "solver/model/driven_dofs.hpp"
#include "solver/model/scene_builder_2d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

}  // namespace

bool contact_law_of(const grammar::TactLaw& card, ContactLaw& law) {
  std::vector<double> values;
  values.reserve(card.parameters.size());
  for (const grammar::Real& v : card.parameters) values.push_back(v.value);
  return law_from_card(card.keyword.value, values, law);
}

bool runs_contactor_2d(std::string_view type) {
  for (std::string_view run : {"DISKx", "DISKb", "xKSID", "JONCx", "PT2Dx", "POLYG"})
    if (type == run) return true;
  return false;
}

bool build_scene_2d(const SceneInput2D& in, Scene2D& scene, grammar::DiagnosticSink& sink) {
  bool ok = true;
  scene = Scene2D{};
  scene.gravity = in.gravity;
  std::vector<std::int32_t> body_of_rank;  // RBDY2 rank (1-based) -> body index
  for (grammar::Body body : in.bodies->bodies) {
    if (body.type != grammar::BodyType::rbdy2) continue;
    RigidContactorFrames2D frames;
    normalise_rigid_body_2d(body, &frames);
    const auto index = static_cast<std::int32_t>(scene.bodies.size());
    body_of_rank.push_back(index);
    const grammar::RigidBulk& bulk = *body.rigid_bulk;
    const auto& x = body.nodes.front().coordinates;
    RigidBodies2D& b = scene.bodies;
    b.reference.push_back(Vector3d(x[0].value, x[1].value, x.size() > 2 ? x[2].value : 0.0));
    for (auto* v : {&b.displacement_begin, &b.displacement, &b.velocity_begin, &b.velocity, &b.velocity_free,
                    &b.inverse_mass, &b.external_force, &b.impulse})
      v->push_back(Vector3d::Zero());
    auto density = in.densities.find(bulk.behav.value);
    if (density == in.densities.end()) {
      sink.report("L2001", grammar::Location{in.bodies_path, bulk.behav.span},
                  "bulk behaviour '" + bulk.behav.value + "' is not defined in BULK_BEHAV.DAT");
      ok = false;
    }
    const double rho = density == in.densities.end() ? 0.0 : density->second;
    const double mass = rho * lmgc_pi * bulk.avrd.value * bulk.avrd.value;
    b.mass.push_back(mass);
    b.inertia.push_back(mass * bulk.gyrd.value * bulk.gyrd.value);
    b.avrd.push_back(bulk.avrd.value);
    b.gyrd.push_back(bulk.gyrd.value);
    b.bulk_behav.push_back(0);
    b.driven_mask.push_back(0);
    b.visible.push_back(1);
    std::int32_t rank = 0;
    for (const grammar::Contactor& t : body.contactors) {
      Contactor2D c;
      c.body = index;
      c.rank = ++rank;
      c.type = t.type.value;
      c.color = t.color.value;
      const auto value = [&](std::size_t i) { return i < t.values.size() ? t.values[i].value : 0.0; };
      if (!runs_contactor_2d(c.type)) {
        sink.report("L4001", grammar::Location{in.bodies_path, t.type.span},
                    "contactor '" + c.type + "' is not handled by the rigid 2D solver");
        ok = false;
        continue;
      }
      if (c.type == "DISKx") {
        c.shape = ContactorShape2D::disk;
        c.type = "DISKx";
        c.radius = value(0);
      } else if (c.type == "DISKb") {
        // Cluster disks are DISKx contactors with an offset (LMGC90 names them DISKx in outputs).
        c.shape = ContactorShape2D::disk;
        c.type = "DISKx";
        c.radius = value(0);
        c.shift = Vector2d(value(1), value(2));
      } else if (c.type == "xKSID") {
        c.shape = ContactorShape2D::hollow_disk;
        c.type = "xKSID";
        c.radius = value(0);
      } else if (c.type == "JONCx") {
        c.shape = ContactorShape2D::joncx;
        c.half_length = value(0);
        c.half_width = value(1);
      } else if (c.type == "PT2Dx") {
        c.shape = ContactorShape2D::point;
        c.shift = Vector2d(value(0), value(1));
      } else if (c.type == "POLYG") {
        c.shape = ContactorShape2D::polygon;
        const std::size_t k = static_cast<std::size_t>(rank - 1);
        c.first_vertex = static_cast<std::int32_t>(scene.vertices.size());
        if (k < frames.shift.size() && k < frames.polygon_vertices.size()) {
          // As LMGC90 holds it: vertices about the polygon's centroid, the centroid's offset.
          c.shift = frames.shift[k];
          c.vertex_count = static_cast<std::int32_t>(frames.polygon_vertices[k].size());
          for (const Vector2d& v : frames.polygon_vertices[k]) scene.vertices.push_back(v);
        } else {
          std::vector<Vector2d> vertices;
          for (const auto& v : t.vertices) vertices.emplace_back(v[0].value, v[1].value);
          double area, polar;
          Vector2d centroid;
          polygon_mass_properties(vertices, area, centroid, polar);
          c.shift = centroid;
          c.vertex_count = static_cast<std::int32_t>(vertices.size());
          for (const Vector2d& v : vertices) scene.vertices.push_back(v - centroid);
        }
      } else {
        sink.report("L4001", grammar::Location{in.bodies_path, t.type.span},
                    "contactor '" + c.type + "' is not handled by the rigid 2D solver");
        ok = false;
        continue;
      }
      // Bounding radius around the contactor centre.
      switch (c.shape) {
        case ContactorShape2D::disk:
          c.bounding_radius = c.radius;
          break;
        case ContactorShape2D::hollow_disk:
          c.bounding_radius = c.radius;
          break;
        case ContactorShape2D::joncx:
          c.bounding_radius = c.half_length + c.half_width;
          break;
        case ContactorShape2D::point:
          c.bounding_radius = 0.0;
          break;
        case ContactorShape2D::polygon:
          c.bounding_radius = polygon_outer_radius(
              std::vector<Vector2d>(scene.vertices.begin() + c.first_vertex,
                                    scene.vertices.begin() + c.first_vertex + c.vertex_count));
          break;
      }
      scene.contactors.push_back(c);
    }
  }

  // Contact laws and visibility rows.
  // The laws the solver has; a card of another keyword is reported when a visibility row uses it
  // (below), and the scene is then not run.
  for (const grammar::TactLaw& card : in.tact_behav->laws) {
    ContactLaw law;
    if (contact_law_of(card, law)) scene.laws.push_back({card.nickname.value, law});
  }
  // The contactor types of the case: a row between types that are not both there never makes a
  // contact, and its law is not needed (LMGC90 runs such a case; its law is never called).
  std::set<std::string> contactor_types;
  for (const grammar::Body& body : in.bodies->bodies)
    for (const grammar::Contactor& c : body.contactors)
      contactor_types.insert(std::string(grammar::see_name(c.type.value)));
  // LMGC90 looks rows up in its own order (duplicates merged, then sorted): first match wins.
  for (const grammar::SeeEntry& see : grammar::lmgc90_see_order(in.tact_behav->sees)) {
    if (!contactor_types.count(std::string(grammar::see_name(see.candidate_contactor.value))) ||
        !contactor_types.count(std::string(grammar::see_name(see.antagonist_contactor.value))))
      continue;
    // Rows between RBDY2 bodies, and rows with a MAILx side whose pair has a mesh family
    // (CLALp, CLJCx, P2P2L, PLALp, DKALp, DKDKL); prepare_run_2d refuses the other MAILx rows.
    const bool rigid = see.candidate_body.value == "RBDY2" && see.antagonist_body.value == "RBDY2";
    PairFamily2D mesh_family;
    if (!rigid &&
        !(contactor_pair_family_2d(grammar::see_name(see.candidate_contactor.value),
                                   grammar::see_name(see.antagonist_contactor.value), mesh_family) &&
          is_mesh_family(mesh_family)))
      continue;
    Visibility2D v;
    v.candidate_type = grammar::see_name(see.candidate_contactor.value);
    v.candidate_color = see.candidate_colour.value;
    v.antagonist_type = grammar::see_name(see.antagonist_contactor.value);
    v.antagonist_color = see.antagonist_colour.value;
    v.law_nickname = see.law_nickname.value;
    v.alert = see.alert.value;
    bool found = false;
    for (const grammar::TactLaw& card : in.tact_behav->laws)
      if (card.nickname.value == v.law_nickname) {
        ContactLaw law;
        if (!contact_law_of(card, law) || !provided_in_2d(law)) {
          sink.report("L4002", grammar::Location{in.tact_behav_path, card.keyword.span},
                      "contact law '" + card.keyword.value + "' is not solved by lmgc in 2D yet");
          ok = false;
        }
        found = true;
        break;
      }
    if (!found) {
      sink.report("L2002", grammar::Location{in.tact_behav_path, see.law_nickname.span},
                  "law '" + v.law_nickname + "' used by this visibility row is not defined");
      ok = false;
    }
    scene.visibility.push_back(v);
  }

  // Driven dofs (datbox-inputs.md §5) and the initial state (DOF.INI): X and V by body rank.
  if (in.drv_dof && !read_driven_dofs(*in.drv_dof, "RBDY2", body_of_rank, 3, in.evolutions, in.drv_dof_path,
                                      scene.driven, sink))
    ok = false;
  if (in.dof_ini)
    for (const auto& [i, node] : initial_dof_nodes(*in.dof_ini, "RBDY2", body_of_rank)) {
      for (std::size_t d = 0; d < 3; ++d) {
        if (d < node->x.size())
          scene.bodies.displacement_begin[i](static_cast<Eigen::Index>(d)) = node->x[d].value;
        if (d < node->v.size())
          scene.bodies.velocity_begin[i](static_cast<Eigen::Index>(d)) = node->v[d].value;
      }
      scene.bodies.displacement[i] = scene.bodies.displacement_begin[i];
      scene.bodies.velocity[i] = scene.bodies.velocity_begin[i];
    }
  finalise_scene(scene);
  return ok;
}

}  // namespace lmgc::solver
