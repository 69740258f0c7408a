#include "solver/model/build_scene_3d.hpp"

#include <stdexcept>

#include "grammar/tact_behav/contactor_pairs.hpp"
#include "grammar/tact_behav/see_table.hpp"
#include "solver/bodies/rigid_3d_properties.hpp"
#include "solver/detection/point_contact.hpp"
#include "solver/model/build_scene_2d.hpp"  // contact_law_of: the law table is shared
#include "solver/model/driven_dofs.hpp"

namespace lmgc::solver {

namespace {
using Eigen::Matrix3d;
using Eigen::Vector3d;

}  // namespace

Rigid3DContactorShape rigid_3d_shape(const grammar::Contactor& t) {
  const auto value = [&](std::size_t i) { return i < t.values.size() ? t.values[i].value : 0.0; };
  Rigid3DContactorShape shape;
  shape.type = t.type.value;
  if (shape.type == "SPHER" || shape.type == "SPHEb") {
    shape.radius = value(0);
    if (shape.type == "SPHEb") shape.shift = Vector3d(value(1), value(2), value(3));
  } else if (shape.type == "PLANx" || shape.type == "CYLND" || shape.type == "DNLYC") {
    shape.half_axes =
        shape.type == "PLANx" ? Vector3d(value(0), value(1), value(2)) : Vector3d(0.0, 0.0, value(0));
    if (shape.type != "PLANx") shape.radius = value(1);
    if (!t.frame.empty()) {
      const grammar::LocalFrame& f = t.frame.front();
      for (int k = 0; k < 3; ++k) {
        shape.frame(k, 0) = f.alpha[static_cast<std::size_t>(k)].value;
        shape.frame(k, 1) = f.beta[static_cast<std::size_t>(k)].value;
        shape.frame(k, 2) = f.gamma[static_cast<std::size_t>(k)].value;
        shape.shift(k) = f.shift[static_cast<std::size_t>(k)].value;
      }
    }
  } else if (shape.type == "PT3Dx") {
    shape.shift = Vector3d(value(0), value(1), value(2));
  } else if (shape.type == "POLYR") {
    for (const auto& v : t.vertices) shape.vertices.emplace_back(v[0].value, v[1].value, v[2].value);
    for (const auto& f : t.faces)
      shape.faces.push_back({static_cast<std::int32_t>(f[0].value - 1),
                             static_cast<std::int32_t>(f[1].value - 1),
                             static_cast<std::int32_t>(f[2].value - 1)});
  }
  return shape;
}

bool runs_contactor_3d(std::string_view type) {
  for (std::string_view run : {"SPHER", "SPHEb", "PLANx", "POLYR", "PT3Dx", "CYLND", "DNLYC"})
    if (type == run) return true;
  return false;
}

bool build_scene_3d(const SceneInput3D& in, Scene3D& scene, grammar::DiagnosticSink& sink) {
  bool ok = true;
  scene = Scene3D{};
  scene.gravity = in.gravity;
  std::vector<std::int32_t> body_of_rank;  // RBDY3 rank (1-based) -> body index
  RigidBodies3D& b = scene.bodies;
  for (const grammar::Body& body : in.bodies->bodies) {
    if (body.type != grammar::BodyType::rbdy3 || !body.rigid_bulk || body.nodes.empty()) continue;
    const auto index = static_cast<std::int32_t>(b.size());
    body_of_rank.push_back(index);
    b.resize(b.size() + 1);
    const grammar::RigidBulk& bulk = *body.rigid_bulk;
    const auto& x = body.nodes.front().coordinates;
    const auto coordinate = [&](std::size_t i) { return i < x.size() ? x[i].value : 0.0; };
    const Vector3d node(coordinate(0), coordinate(1), coordinate(2));

    std::vector<Rigid3DContactorShape> shapes;
    std::vector<Contactor3D> contactors;
    std::int32_t rank = 0;
    bool unsupported = false;  // reported once, at the contactor; the body is not sized then
    for (const grammar::Contactor& t : body.contactors) {
      Contactor3D c;
      c.body = index;
      c.rank = ++rank;
      c.type = t.type.value;
      c.color = t.color.value;
      if (!runs_contactor_3d(c.type)) {
        sink.report("L4001", grammar::Location{in.bodies_path, t.type.span},
                    "contactor '" + c.type + "' is not handled by the rigid 3D solver yet");
        ok = false;
        unsupported = true;
        continue;
      }
      const Rigid3DContactorShape shape = rigid_3d_shape(t);
      if (c.type == "SPHER" || c.type == "SPHEb") {
        c.shape = ContactorShape3D::sphere;
        c.radius = shape.radius;
        c.shift = shape.shift;
        c.bounding_radius = c.radius;
      } else if (c.type == "PLANx") {
        c.shape = ContactorShape3D::plane;
        c.half_axes = shape.half_axes;
        c.local_frame = shape.frame;
        c.shift = shape.shift;
        c.bounding_radius = c.half_axes.norm();
      } else if (c.type == "POLYR") {
        c.shape = ContactorShape3D::polyhedron;
      } else if (c.type == "PT3Dx") {
        c.shape = ContactorShape3D::point;
        c.shift = shape.shift;
      } else if (c.type == "CYLND" || c.type == "DNLYC") {
        c.shape = c.type == "CYLND" ? ContactorShape3D::cylinder : ContactorShape3D::tube;
        c.radius = shape.radius;
        c.half_axes = shape.half_axes;  // (0, 0, High)
        c.local_frame = shape.frame;
        c.shift = shape.shift;
        c.bounding_radius = c.half_axes.z() + c.radius;
      } else {
        sink.report("L4001", grammar::Location{in.bodies_path, t.type.span},
                    "contactor '" + c.type + "' is not handled by the rigid 3D solver yet");
        ok = false;
        unsupported = true;
        continue;
      }
      shapes.push_back(shape);
      contactors.push_back(c);
    }

    if (unsupported) continue;
    const auto density = in.densities.find(bulk.behav.value);
    if (density == in.densities.end()) {
      sink.report("L2001", grammar::Location{in.bodies_path, bulk.behav.span},
                  "bulk behaviour '" + bulk.behav.value + "' is not defined in BULK_BEHAV.DAT");
      ok = false;
    }
    const Vector3d given_inertia(bulk.principal_inertia[0].value, bulk.principal_inertia[1].value,
                                 bulk.principal_inertia[2].value);
    RigidBody3DProperties p;
    try {
      p = rigid_3d_properties(density == in.densities.end() ? 0.0 : density->second, bulk.avrd.value,
                              given_inertia, shapes);
    } catch (const std::invalid_argument& error) {
      sink.report("L4001", grammar::Location{in.bodies_path, body.number.span},
                  std::string("RBDY3 body without mass: ") + error.what());
      ok = false;
      continue;
    }
    const auto i = static_cast<std::size_t>(index);
    b.reference[i] = node + p.centre_shift;
    b.mass[i] = p.mass;
    b.inertia[i] = p.inertia;
    b.frame_initial[i] = b.frame_detection[i] = b.frame[i] = p.frame;
    // Offsets from the centre of inertia and embedded frames, in the principal axes (mod_RBDY3).
    for (std::size_t k = 0; k < contactors.size(); ++k) {
      Contactor3D& c = contactors[k];
      c.shift = p.contactor_shifts[k];
      if (c.shape == ContactorShape3D::plane || c.shape == ContactorShape3D::cylinder ||
          c.shape == ContactorShape3D::tube)
        c.local_frame = p.contactor_frames[k];
      if (c.shape == ContactorShape3D::polyhedron) {
        Polyhedron shape;
        shape.vertices = p.contactor_vertices[k];
        shape.faces = p.contactor_faces[k];
        finish_polyhedron(shape);
        c.bounding_radius = shape.radius;
        c.polyhedron = static_cast<std::int32_t>(scene.polyhedra.size());
        scene.polyhedra.push_back(std::move(shape));
      }
      scene.contactors.push_back(c);
    }
  }

  // Contact laws and visibility rows (RBDY3 against RBDY3).
  // The laws the solver has; a card of another keyword is reported when a visibility row uses it
  // (below), and the scene is then not run.
  for (const grammar::TactLaw& card : in.tact_behav->laws) {
    ContactLaw law;
    if (contact_law_of(card, law)) scene.laws.push_back({card.nickname.value, law});
  }
  for (const grammar::SeeEntry& see : grammar::lmgc90_see_order(in.tact_behav->sees)) {
    if (see.candidate_body.value != "RBDY3" || see.antagonist_body.value != "RBDY3") continue;
    Visibility3D v;
    v.candidate_type = grammar::see_name(see.candidate_contactor.value);
    v.candidate_color = see.candidate_colour.value;
    v.antagonist_type = grammar::see_name(see.antagonist_contactor.value);
    v.antagonist_color = see.antagonist_colour.value;
    v.alert = see.alert.value;
    if (!pair_family_3d(v.candidate_type, v.antagonist_type, v.family)) {
      sink.report("L4001", grammar::Location{in.tact_behav_path, see.candidate_contactor.span},
                  "pair " + v.candidate_type + "/" + v.antagonist_type +
                      " is not detected by the rigid 3D solver yet");
      ok = false;
      continue;
    }
    bool found = false;
    for (std::size_t k = 0; k < in.tact_behav->laws.size(); ++k) {
      const grammar::TactLaw& card = in.tact_behav->laws[k];
      if (card.nickname.value != see.law_nickname.value) continue;
      found = true;
      ContactLaw law;
      if (!contact_law_of(card, law) || !provided_in_3d(law)) {
        sink.report("L4002", grammar::Location{in.tact_behav_path, card.keyword.span},
                    "contact law '" + card.keyword.value + "' is not solved by the rigid 3D solver yet");
        ok = false;
      } else if ((std::holds_alternative<ElasticWire>(law) || std::holds_alternative<ElasticRod>(law)) &&
                 v.family != PairFamily3D::PTPT3) {
        // Only PTPT3 sets the reference length gapREF; LMGC90 stops on gapREF <= 1e-18.
        sink.report("L2018", grammar::Location{in.tact_behav_path, see.law_nickname.span},
                    "law '" + card.nickname.value + "' (" + card.keyword.value +
                        ") needs a reference length, which only PT3Dx/PT3Dx (PTPT3) links have");
        ok = false;
      }
      // The first card of the nickname is the first law of scene.laws that has it.
      for (std::size_t l = 0; l < scene.laws.size(); ++l)
        if (scene.laws[l].nickname == card.nickname.value) {
          v.law = static_cast<std::int32_t>(l);
          break;
        }
      break;
    }
    if (!found) {
      sink.report("L2002", grammar::Location{in.tact_behav_path, see.law_nickname.span},
                  "law '" + see.law_nickname.value + "' used by this visibility row is not defined");
      ok = false;
    }
    scene.visibility.push_back(v);
  }

  // Driven dofs (datbox-inputs.md §5): 6 dofs, rotations in body axes.
  if (in.drv_dof && !read_driven_dofs(*in.drv_dof, "RBDY3", body_of_rank, 6, in.evolutions, in.drv_dof_path,
                                      scene.driven, sink))
    ok = false;
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force)
      b.driven_mask[static_cast<std::size_t>(d.body)] |= static_cast<std::uint8_t>(1u << d.dof);

  // Initial state (DOF.INI): X, V and the principal frame by body rank.
  if (in.dof_ini)
    for (const auto& [i, node] : initial_dof_nodes(*in.dof_ini, "RBDY3", body_of_rank)) {
      for (std::size_t d = 0; d < 6; ++d) {
        if (d < 3 && d < node->x.size())
          b.displacement_begin[i](static_cast<Eigen::Index>(d)) = node->x[d].value;
        if (d < node->v.size()) b.velocity_begin[i](static_cast<Eigen::Index>(d)) = node->v[d].value;
      }
      if (node->frame.size() >= 9) {
        Matrix3d frame;
        for (int column = 0; column < 3; ++column)
          for (int k = 0; k < 3; ++k)
            frame(k, column) = node->frame[static_cast<std::size_t>(3 * column + k)].value;
        b.frame_initial[i] = b.frame_detection[i] = b.frame[i] = frame;
      }
      b.displacement[i] = b.displacement_begin[i];
      b.velocity[i] = b.velocity_begin[i];
    }

  // Inverse masses (0 on driven dofs) and the plan.
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vector6d inverse;
    inverse << Vector3d::Constant(b.mass[i] > 0.0 ? 1.0 / b.mass[i] : 0.0),
        Vector3d(b.inertia[i](0) > 0.0 ? 1.0 / b.inertia[i](0) : 0.0,
                 b.inertia[i](1) > 0.0 ? 1.0 / b.inertia[i](1) : 0.0,
                 b.inertia[i](2) > 0.0 ? 1.0 / b.inertia[i](2) : 0.0);
    for (int d = 0; d < 6; ++d)
      if (b.driven_mask[i] & (1u << d)) inverse(d) = 0.0;
    b.inverse_mass[i] = inverse;
  }
  scene.point_links = link_points_3d(scene);
  scene.plan = {};
  for (const Visibility3D& v : scene.visibility) scene.plan.families[static_cast<int>(v.family)] = true;
  return ok;
}

}  // namespace lmgc::solver
