#include "solver/driver/case_input.hpp"

#include <set>

#include "grammar/bodies/writer.hpp"
#include "grammar/command/expand.hpp"
#include "grammar/tact_behav/contactor_pairs.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "solver/bodies/rigid_2d_properties.hpp"
#include "solver/bodies/rigid_3d_properties.hpp"
#include "solver/io/postpro_3d.hpp"
#include "solver/io/state_files_2d.hpp"
#include "solver/model/build_scene_2d.hpp"
#include "solver/model/build_scene_3d.hpp"

namespace lmgc::solver {

namespace {

std::string datbox_path(const case_folder::CaseFiles& files, const char* name) {
  return (files.case_dir / "DATBOX" / name).string();
}

// The POSTPRO.DAT commands the 2D post-processor provides (with three_d: those the 3D one provides);
// the others are noted and skipped.
std::vector<PostproCommand2D> postpro_commands_2d(const case_folder::CaseFiles& files,
                                                  grammar::DiagnosticSink& sink, bool three_d = false) {
  std::vector<PostproCommand2D> commands;
  if (!files.postpro) return commands;
  for (const grammar::PostproCommand& card : files.postpro->commands) {
    PostproCommand2D command;
    if (!postpro_kind_of(card.name.value, command.kind) || (three_d && !Postpro3D::provides(command.kind))) {
      sink.report(
          "L4004", grammar::Location{datbox_path(files, "POSTPRO.DAT"), card.name.span},
          "POSTPRO command '" + card.name.value + "' is not computed by lmgc-solve yet; it is skipped");
      continue;
    }
    command.period = card.period.value > 0 ? static_cast<int>(card.period.value) : 1;
    // BODY TRACKING / TORQUE EVOLUTION: a count line, then one body rank per line.
    if (command.kind == PostproKind2D::body_tracking || command.kind == PostproKind2D::torque_evolution) {
      for (std::size_t k = 1; k < card.arguments.size(); ++k)
        if (!card.arguments[k].integers.empty())
          command.bodies.push_back(card.arguments[k].integers.front().value);
    }
    // NEW MECAx SETS: the count of sets; per set its count of members; per member a (body, node
    // count) line, then the node numbers one per line (mailx-2d.md §8).
    if (command.kind == PostproKind2D::new_meca_sets) {
      std::vector<std::int64_t> values;
      for (const grammar::PostproArgument& a : card.arguments)
        for (const grammar::Integer& i : a.integers) values.push_back(i.value);
      std::size_t at = 0;
      const auto next = [&]() { return at < values.size() ? values[at++] : 0; };
      const std::int64_t sets = next();
      for (std::int64_t k = 0; k < sets && at < values.size(); ++k) {
        std::vector<std::pair<std::int64_t, std::int64_t>> set;
        const std::int64_t members = next();
        for (std::int64_t m = 0; m < members && at < values.size(); ++m) {
          const std::int64_t body = next(), nodes = next();
          for (std::int64_t n = 0; n < nodes && at < values.size(); ++n) set.emplace_back(body, next());
        }
        command.sets.push_back(std::move(set));
      }
    }
    if (command.kind == PostproKind2D::average_velocity_evolution && !card.arguments.empty())
      command.color = card.arguments.front().word.value;
    commands.push_back(std::move(command));
  }
  return commands;
}

// The parts of a scene input both dimensions read the same way: the ASTs, the densities of the
// bulk behaviours, the paths for diagnostics (gravity is left to the caller).
template <class SceneInput>
void fill_scene_input(const case_folder::CaseFiles& files, SceneInput& input) {
  static const grammar::TactBehavFile kNoLaws;
  input.bodies = &*files.bodies;
  input.tact_behav = files.tact_behav ? &*files.tact_behav : &kNoLaws;
  input.drv_dof = files.drv_dof ? &*files.drv_dof : nullptr;
  input.dof_ini = files.dof_ini ? &*files.dof_ini : nullptr;
  input.evolutions = &files.evolutions;
  for (const grammar::BulkLaw& law : files.bulk_behav->laws) {
    double density = 0.0;
    if (!law.density_field && grammar::bulk_density(*files.bulk_behav, law.nickname.value, density))
      input.densities.emplace(law.nickname.value, density);
  }
  input.bodies_path = datbox_path(files, "BODIES.DAT");
  input.tact_behav_path = datbox_path(files, "TACT_BEHAV.DAT");
  input.drv_dof_path = datbox_path(files, "DRV_DOF.DAT");
}

// Two PT2DL points of a P2P2L row that coincide are glued (mod_P2P2L compute_contact: a fixed frame,
// gap 0), which LMGC90 accepts only with COUPLED_DOF (or TEX_SOL, which lmgc does not run): it stops
// on any other law. Tested on the initial configuration (reference nodes + DOF.INI's X), where the
// run's first detection makes the pairs. lmgc-check reports it too (report_solver_support).
bool glued_points_have_a_glue(const case_folder::CaseFiles& files, const Scene2D& scene,
                              grammar::DiagnosticSink& sink) {
  const std::vector<MeshContactor>& tactors = scene.deformable.meshes.contactors;
  const auto point = [&](const MeshContactor& t) {
    const fem::MeshBody& body = scene.deformable.meshes.bodies[static_cast<std::size_t>(t.mesh)];
    const Eigen::VectorXd& x = scene.deformable.states[static_cast<std::size_t>(t.mesh)].x_begin;
    const auto at = [&](std::int32_t n) {
      const auto i = static_cast<std::size_t>(2 * n);
      return Eigen::Vector2d(body.coordinates[i] + x(static_cast<Eigen::Index>(i)),
                             body.coordinates[i + 1] + x(static_cast<Eigen::Index>(i + 1)));
    };
    return Eigen::Vector2d((1.0 - t.apab) * at(t.nodes[0]) + t.apab * at(t.nodes[1]));
  };
  for (const Visibility2D& v : scene.visibility) {
    if (v.family != PairFamily2D::P2P2L ||
        std::holds_alternative<CoupledDof>(scene.laws[static_cast<std::size_t>(v.law)].law))
      continue;
    for (std::size_t i = 0; i < tactors.size(); ++i)
      for (std::size_t j = i + 1; j < tactors.size(); ++j) {
        const MeshContactor &a = tactors[i], &b = tactors[j];
        if (a.shape != MeshContactorShape::point || b.shape != MeshContactorShape::point) continue;
        const bool seen = (a.color == v.candidate_color && b.color == v.antagonist_color) ||
                          (b.color == v.candidate_color && a.color == v.antagonist_color);
        if (!seen || (point(a) - point(b)).norm() >= 1e-20) continue;
        grammar::SourceSpan row_span{};
        for (const grammar::SeeEntry& see : files.tact_behav->sees)
          if (see.law_nickname.value == v.law_nickname &&
              grammar::see_name(see.candidate_contactor.value) == "PT2DL")
            row_span = see.law_nickname.span;
        sink.report("L2018", grammar::Location{datbox_path(files, "TACT_BEHAV.DAT"), row_span},
                    "PT2DL " + std::to_string(a.rank) + " of MAILx " + std::to_string(a.mesh + 1) +
                        " and PT2DL " + std::to_string(b.rank) + " of MAILx " + std::to_string(b.mesh + 1) +
                        " coincide: a P2P2L pair of coinciding points is glued, and LMGC90 glues them "
                        "only with COUPLED_DOF; their law " +
                        v.law_nickname + " is " +
                        std::string(law_keyword(scene.laws[static_cast<std::size_t>(v.law)].law)));
        return false;
      }
  }
  return true;
}

}  // namespace

bool prepare_run_2d(const case_folder::CaseFiles& files, Scene2D& scene, RunOutputs2D& outputs,
                    grammar::DiagnosticSink& sink, fem::Hypothesis hypothesis) {
  if (!files.bodies || !files.bulk_behav) return false;
  for (const grammar::Body& body : files.bodies->bodies)
    if (body.type == grammar::BodyType::rbdy3) {
      sink.report(
          "L4003", grammar::Location{datbox_path(files, "BODIES.DAT"), body.type_span},
          "lmgc-solve runs cases of RBDY2 (and MAILx) bodies only or of RBDY3 bodies only for now; this "
          "body is RBDY3");
      return false;
    }
  // Contact with deformable bodies: every 2D pair with a mesh side is run; a visibility row
  // that names a MAILx body with another pair refuses the case.
  // A row between contactor types the case does not both have never makes a contact (not refused).
  std::set<std::string> contactor_types;
  for (const grammar::Body& body : files.bodies->bodies)
    for (const grammar::Contactor& c : body.contactors)
      contactor_types.insert(std::string(grammar::see_name(c.type.value)));
  if (files.tact_behav)
    for (const grammar::SeeEntry& see : files.tact_behav->sees) {
      if (see.candidate_body.value != "MAILx" && see.antagonist_body.value != "MAILx") continue;
      if (!contactor_types.count(std::string(grammar::see_name(see.candidate_contactor.value))) ||
          !contactor_types.count(std::string(grammar::see_name(see.antagonist_contactor.value))))
        continue;
      PairFamily2D family;
      if (contactor_pair_family_2d(grammar::see_name(see.candidate_contactor.value),
                                   grammar::see_name(see.antagonist_contactor.value), family) &&
          is_mesh_family(family))
        continue;
      sink.report("L4003", grammar::Location{datbox_path(files, "TACT_BEHAV.DAT"), see.candidate_body.span},
                  "contact with deformable (MAILx) bodies is run by lmgc for the pairs CLALp, CLJCx, P2P2L, "
                  "PLALp, DKALp "
                  "and DKDKL "
                  "only; this visibility row pairs " +
                      see.candidate_contactor.value + " and " + see.antagonist_contactor.value);
      return false;
    }
  SceneInput2D input;
  fill_scene_input(files, input);
  if (files.bulk_behav->has_gravity)
    input.gravity = Eigen::Vector2d(files.bulk_behav->gravity[0].value, files.bulk_behav->gravity[1].value);
  if (!build_scene_2d(input, scene, sink)) return false;
  if (!build_deformable_bodies(files, hypothesis, scene.deformable, sink)) return false;
  if (!glued_points_have_a_glue(files, scene, sink)) return false;

  outputs.case_dir = files.case_dir;
  if (files.dof_ini) {
    outputs.initial_step = files.dof_ini->step.value;
    outputs.initial_time = files.dof_ini->time.value;
  }
  if (files.exact_state) outputs.exact_state = &*files.exact_state;
  outputs.postpro = postpro_commands_2d(files, sink);
  if (files.vloc_rloc_ini) outputs.warm_start = &*files.vloc_rloc_ini;
  return true;
}

bool is_rigid_3d_case(const case_folder::CaseFiles& files) {
  if (!files.bodies || files.bodies->bodies.empty()) return false;
  for (const grammar::Body& body : files.bodies->bodies)
    if (body.type != grammar::BodyType::rbdy3) return false;
  return true;
}

bool prepare_run_3d(const case_folder::CaseFiles& files, Scene3D& scene, RunOutputs3D& outputs,
                    grammar::DiagnosticSink& sink) {
  if (!files.bodies || !files.bulk_behav) return false;
  SceneInput3D input;
  fill_scene_input(files, input);
  if (files.bulk_behav->has_gravity)
    input.gravity = Eigen::Vector3d(files.bulk_behav->gravity[0].value, files.bulk_behav->gravity[1].value,
                                    files.bulk_behav->gravity[2].value);
  bool ok = build_scene_3d(input, scene, sink);
  if (!ok) return false;
  outputs.case_dir = files.case_dir;
  if (files.dof_ini) {
    outputs.initial_step = files.dof_ini->step.value;
    outputs.initial_time = files.dof_ini->time.value;
  }
  if (files.exact_state) outputs.exact_state = &*files.exact_state;
  outputs.postpro = postpro_commands_2d(files, sink, /*three_d=*/true);
  if (files.vloc_rloc_ini) outputs.warm_start = &*files.vloc_rloc_ini;
  if (files.ptpt3_network) outputs.ptpt3_network = &*files.ptpt3_network;
  return true;
}

void report_solver_support(const case_folder::CaseFiles& files, grammar::DiagnosticSink& sink) {
  // The scene builders take checked data: a case with errors is not prepared (lmgc-solve does not
  // run it either).
  if (!files.bodies || !files.bulk_behav || sink.has_errors()) return;
  grammar::DiagnosticSink scratch(static_cast<std::size_t>(-1));
  if (is_rigid_3d_case(files)) {
    Scene3D scene;
    RunOutputs3D outputs;
    prepare_run_3d(files, scene, outputs, scratch);
  } else {
    Scene2D scene;
    RunOutputs2D outputs;
    prepare_run_2d(files, scene, outputs, scratch);
  }
  for (const grammar::Diagnostic& d : scratch.items())
    // L3011: an element the validation does not examine (T6, Q8, H8) inverted at a Gauss point.
    // L2018: P2P2L points that coincide under another law than COUPLED_DOF (glued_points_have_a_glue).
    if (d.code == "L4001" || d.code == "L4002" || d.code == "L4003" || d.code == "L4004" ||
        d.code == "L3011" || d.code == "L2018")
      sink.report(d);
}

std::vector<case_folder::OutputFile> echo_files_2d(const case_folder::CaseFiles& files) {
  std::vector<case_folder::OutputFile> out = case_folder::echo_files(files);
  if (!files.bodies) return out;
  grammar::BodiesFile bodies = *files.bodies;
  for (grammar::Body& body : bodies.bodies)
    if (body.type == grammar::BodyType::rbdy2) normalise_rigid_body_2d(body);
  for (case_folder::OutputFile& file : out)
    if (file.relative_path == "OUTBOX/BODIES.OUT") file.content = grammar::write_bodies(bodies);
  return out;
}

std::vector<case_folder::OutputFile> echo_files_3d(const case_folder::CaseFiles& files) {
  std::vector<case_folder::OutputFile> out = case_folder::echo_files(files);
  if (!files.bodies) return out;
  // BODIES.OUT after LMGC90's RBDY3 pre-computations (mod_RBDY3): the node moved to the centre of
  // inertia, avrd and the per-density principal inertia filled in, SPHEb offsets from the centre,
  // POLYR vertices in the principal frame.
  grammar::BodiesFile bodies = *files.bodies;
  for (grammar::Body& body : bodies.bodies) {
    if (body.type != grammar::BodyType::rbdy3 || !body.rigid_bulk || body.nodes.empty()) continue;
    std::vector<Rigid3DContactorShape> shapes;
    for (const grammar::Contactor& t : body.contactors) shapes.push_back(rigid_3d_shape(t));
    grammar::RigidBulk& bulk = *body.rigid_bulk;
    RigidBody3DProperties p;
    try {
      p = rigid_3d_properties(
          1.0, bulk.avrd.value,
          Eigen::Vector3d(bulk.principal_inertia[0].value, bulk.principal_inertia[1].value,
                          bulk.principal_inertia[2].value),
          shapes);
    } catch (const std::invalid_argument&) {
      continue;  // reported when the scene is built
    }
    bulk.avrd.value = p.avrd;
    for (int k = 0; k < 3; ++k)
      bulk.principal_inertia[static_cast<std::size_t>(k)].value = p.geometric_inertia(k);
    auto& node = body.nodes.front().coordinates;
    for (std::size_t k = 0; k < 3 && k < node.size(); ++k)
      node[k].value += p.centre_shift(static_cast<int>(k));
    for (std::size_t k = 0; k < body.contactors.size(); ++k) {
      grammar::Contactor& t = body.contactors[k];
      if (t.type.value == "SPHEb" && t.values.size() >= 4)
        for (int d = 0; d < 3; ++d)
          t.values[static_cast<std::size_t>(d + 1)].value = p.contactor_shifts[k](d);
      // POLYR: vertices about the centre of inertia in the principal frame, faces reoriented
      // (write_BDARY_POLYR writes shift + local vertex).
      if (t.type.value == "POLYR" && p.contactor_vertices[k].size() == t.vertices.size() &&
          p.contactor_faces[k].size() == t.faces.size()) {
        for (std::size_t v = 0; v < t.vertices.size(); ++v)
          for (int d = 0; d < 3; ++d)
            t.vertices[v][static_cast<std::size_t>(d)].value =
                p.contactor_shifts[k](d) + p.contactor_vertices[k][v](d);
        for (std::size_t f = 0; f < t.faces.size(); ++f)
          for (std::size_t d = 0; d < 3; ++d) t.faces[f][d].value = p.contactor_faces[k][f][d] + 1;
      }
    }
  }
  for (case_folder::OutputFile& file : out)
    if (file.relative_path == "OUTBOX/BODIES.OUT") file.content = grammar::write_bodies(bodies);
  return out;
}

}  // namespace lmgc::solver
