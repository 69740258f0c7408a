#include "solver/model/mesh_bodies.hpp"

#include <map>

namespace lmgc::solver {

namespace {

const grammar::ModelOption* option(const grammar::Model& model, std::string_view id) {
  for (const grammar::ModelOption& o : model.options)
    if (o.id.value == id) return &o;
  return nullptr;
}

}  // namespace

bool runs_mesh_contactor_2d(std::string_view type) {
  return type == "CLxxx" || type == "ALpxx" || type == "PT2DL" || type == "DISKL";
}

bool build_mesh_bodies(const case_folder::CaseFiles& files, fem::Hypothesis hypothesis, MeshBodies& out,
                       grammar::DiagnosticSink& sink) {
  out = {};
  if (!files.bodies) return true;
  const std::string models_path = (files.case_dir / "DATBOX" / "MODELS.DAT").string();
  const std::string bodies_path = (files.case_dir / "DATBOX" / "BODIES.DAT").string();
  const std::string bulk_path = (files.case_dir / "DATBOX" / "BULK_BEHAV.DAT").string();
  const auto refuse = [&](const std::string& path, grammar::SourceSpan span, const std::string& what) {
    sink.report("L4003", grammar::Location{path, span}, what);
    return false;
  };
  // The models lmgc runs: MECAx, small strain, linear isotropic elasticity.
  std::map<std::string, const grammar::Model*> models;
  std::map<std::string, bool> matlib, large_strain, own_large_strain;
  if (files.models)
    for (const grammar::Model& m : files.models->models) {
      models[m.nickname.value] = &m;
      const auto at = m.nickname.span;
      if (m.kind.value != "MECAx")
        return refuse(models_path, m.kind.span,
                      "model '" + m.nickname.value + "' is " + m.kind.value +
                          ": lmgc runs mechanical (MECAx) models only for now");
      if (!fem::find_element(m.element.value))
        return refuse(
            models_path, m.element.span,
            "model '" + m.nickname.value + "' uses the element " + m.element.value +
                ", which lmgc does not have yet (it has T3xxx, Q4xxx, Q4P0x, T6xxx, Q8xxx, TE4xx, H8xxx)");
      // Small strain with linear elasticity, or large strain in the total Lagrangian form with
      // MatLib's neo-Hookean material (fem/large_strain.hpp, fem/neo_hookean.hpp).
      const grammar::ModelOption* kine = option(m, "kine_");
      const grammar::ModelOption* form = option(m, "form_");
      const grammar::ModelOption* mater = option(m, "mater");
      const grammar::ModelOption* isext_option = option(m, "isext");
      const bool large = kine && kine->value.value == "large";
      if (kine && !large && kine->value.value != "small")
        return refuse(models_path, kine->value.span,
                      "model '" + m.nickname.value + "' asks for 'kine_ " + kine->value.value +
                          "': LMGC90 knows small and large");
      // Large strain: MatLib's neo-Hookean in the total Lagrangian form, or LMGC90's own material
      // ('isext no___': J2 plasticity on Q4P0x, which LMGC90 runs for 'form_ UpdtL' only; 'mater' is
      // not read there).
      const bool own_material = !isext_option || isext_option->value.value == "no___";
      if (large && own_material) {
        if (!form || form->value.value != "UpdtL")
          return refuse(models_path, form ? form->value.span : kine->value.span,
                        "model '" + m.nickname.value +
                            "' asks for large strain with LMGC90's own material in the form '" +
                            (form ? form->value.value : std::string("(none)")) +
                            "': LMGC90 runs it in the updated Lagrangian form (form_ UpdtL) only");
        if (m.element.value != "Q4P0x")
          return refuse(models_path, m.element.span,
                        "model '" + m.nickname.value +
                            "' asks for large strain with LMGC90's own material on " + m.element.value +
                            ": LMGC90 runs it on Q4P0x only");
      } else if (large) {
        if (!form || form->value.value != "TotaL")
          return refuse(
              models_path, form ? form->value.span : kine->value.span,
              "model '" + m.nickname.value + "' asks for large strain in the form '" +
                  (form ? form->value.value : std::string("(none)")) +
                  "' with MatLib: lmgc runs MatLib in the total Lagrangian form (form_ TotaL) only");
        if (!mater || mater->value.value != "neoh_")
          return refuse(models_path, mater ? mater->value.span : kine->value.span,
                        "model '" + m.nickname.value +
                            "' asks for large strain with another MatLib material than the neo-Hookean "
                            "('mater neoh_'): lmgc runs that one only for now");
      }
      if (large) {
        if (hypothesis == fem::Hypothesis::three_d)
          return refuse(models_path, kine->value.span,
                        "model '" + m.nickname.value + "': lmgc runs large strain in 2D only for now");
        if (hypothesis == fem::Hypothesis::plane_stress)
          return refuse(models_path, kine->value.span,
                        "model '" + m.nickname.value +
                            "': large strain in plane stress, which LMGC90 does not run either");
      } else if (mater && mater->value.value != "elas_") {
        return refuse(models_path, mater->value.span,
                      "model '" + m.nickname.value + "' asks for 'mater " + mater->value.value +
                          "': lmgc runs linear elasticity (elas_) in small strain only for now");
      }
      large_strain[m.nickname.value] = large;
      own_large_strain[m.nickname.value] = large && own_material;
      const grammar::ModelOption* aniso = option(m, "aniso");
      if (aniso && aniso->value.value != "iso__")
        return refuse(models_path, aniso->value.span,
                      "model '" + m.nickname.value + "' is anisotropic: lmgc runs isotropic elasticity only");
      // Options lmgc reads; any other changes the model (external fields, discrete or coupled
      // elements, ...) and is refused rather than ignored.
      for (const grammar::ModelOption& o : m.options) {
        const std::string& id = o.id.value;
        const std::string& value = o.value.value;
        const bool known = id == "isext" || id == "kine_" || id == "form_" || id == "aniso" ||
                           id == "mater" || id == "mstrg" || id == "cplth";
        const bool accepted = !known          ? false
                              : id == "isext" ? (value == "no___" || value == "MatL_")
                              : id == "form_" ? value == (!large         ? "xxxxx"
                                                          : own_material ? "UpdtL"
                                                                         : "TotaL")
                              : id == "cplth" ? value == "no___"
                                              : true;
        if (!accepted)
          return refuse(
              models_path, o.id.span,
              "model '" + m.nickname.value + "' asks for '" + id + " " + value +
                  "', which lmgc does not run yet (it runs small-strain linear elasticity, isext no___ or "
                  "MatL_, large-strain neo-Hookean with MatLib, form_ TotaL, and LMGC90's own J2 plasticity, "
                  "form_ UpdtL; no thermal coupling)");
      }
      const grammar::ModelOption* isext = option(m, "isext");
      matlib[m.nickname.value] = isext && isext->value.value == "MatL_";
      if (matlib[m.nickname.value] && hypothesis == fem::Hypothesis::plane_stress)
        return refuse(
            models_path, isext->value.span,
            "model '" + m.nickname.value +
                "' hands elasticity to MatLib ('isext MatL_'), whose 2D laws are plane strain: lmgc "
                "does not know what LMGC90 runs then in plane stress");
      (void)at;
    }
  // Materials: the ELAS laws, by nickname.
  std::map<std::string, std::int32_t> material_of;
  std::vector<fem::Material> materials;
  const auto material = [&](const grammar::Word& behav, fem::MaterialLaw law) -> std::int32_t {
    const std::string key = behav.value + "|" + std::to_string(static_cast<int>(law));
    auto it = material_of.find(key);
    if (it != material_of.end()) return it->second;
    if (!files.bulk_behav) return -1;
    const bool plastic = law == fem::MaterialLaw::j2_plasticity;
    for (const grammar::BulkLaw& card : files.bulk_behav->laws) {
      if (card.nickname.value != behav.value) continue;
      if (card.law_type.value != (plastic ? "ELAS_PLAS" : "ELAS") || card.density_field) return -1;
      fem::Material m;
      m.law = law;
      m.density = card.density.value;
      bool plasticity_read = false;
      for (const grammar::BulkBlock& block : card.blocks) {
        if (block.kind == grammar::BulkBlockKind::elas && !block.lines.empty() && !block.lines[0].field &&
            block.lines[0].values.size() >= 2) {
          m.young = block.lines[0].values[0].value;
          m.poisson = block.lines[0].values[1].value;
        }
        // PLAS: a von Mises criterion, isotropic hardening only (LMGC90's BULK_NL_ISO reads but
        // ignores kinematic hardening and viscoplasticity: a case asking for them is refused).
        if (plastic && block.kind == grammar::BulkBlockKind::plas && block.options.size() >= 2 &&
            block.options[0].value == "Von-Mises" && !block.lines.empty() && !block.lines[0].field) {
          const std::string& isoh = block.options[1].value;
          const auto& v = block.lines[0].values;
          const bool others_none = (block.options.size() < 3 || block.options[2].value == "none") &&
                                   (block.options.size() < 4 || block.options[3].value == "none");
          m.plasticity.hardening = isoh == "Swift"    ? fem::Hardening::swift
                                   : isoh == "linear" ? fem::Hardening::linear
                                                      : fem::Hardening::hollomon;
          const std::size_t needed = isoh == "Swift" ? 3 : 2;
          if ((isoh == "Swift" || isoh == "linear" || isoh == "Hollomon") && v.size() >= needed &&
              others_none) {
            for (std::size_t k = 0; k < needed; ++k) m.plasticity.coefficients[k] = v[k].value;
            plasticity_read = true;
          }
        }
      }
      if (!(m.young > 0.0) || (plastic && !plasticity_read)) return -1;
      const auto id = static_cast<std::int32_t>(materials.size());
      materials.push_back(m);
      material_of.emplace(key, id);
      return id;
    }
    return -1;
  };
  const int dimension = hypothesis == fem::Hypothesis::three_d ? 3 : 2;
  for (const grammar::Body& body : files.bodies->bodies) {
    if (body.type != grammar::BodyType::mailx) continue;
    fem::MeshBody mesh;
    mesh.dimension = dimension;
    mesh.hypothesis = hypothesis;
    for (const grammar::Node& node : body.nodes)
      for (int c = 0; c < dimension; ++c)
        mesh.coordinates.push_back(c < static_cast<int>(node.coordinates.size())
                                       ? node.coordinates[static_cast<std::size_t>(c)].value
                                       : 0.0);
    bool lumped = true, any = false, body_matlib = false;
    for (const grammar::Element& e : body.elements) {
      // The element's mechanical model (a MAILx element may carry a thermal one too).
      const grammar::ModelReference* reference = nullptr;
      for (const grammar::ModelReference& r : e.models) {
        auto it = models.find(r.model.value);
        if (it != models.end() && it->second->kind.value == "MECAx") reference = &r;
      }
      if (!reference)
        return refuse(bodies_path, e.type.span,
                      "element " + e.type.value + " has no mechanical (MECAx) model");
      const grammar::Model& model = *models.at(reference->model.value);
      const fem::ElementEntry& entry = *fem::find_element(model.element.value);
      if (static_cast<std::size_t>(entry.nodes) != e.nodes.size())
        return refuse(bodies_path, e.type.span,
                      "element " + e.type.value + " has " + std::to_string(e.nodes.size()) +
                          " nodes; its model's " + std::string(entry.name) + " has " +
                          std::to_string(entry.nodes));
      if (entry.dimension != dimension)
        return refuse(models_path, model.element.span,
                      "the element " + std::string(entry.name) + " is not of the case's dimension");
      fem::MeshElement element;
      element.kind = entry.kind;
      for (std::size_t k = 0; k < e.nodes.size(); ++k) {
        const std::int64_t n = e.nodes[k].value;
        if (n < 1 || static_cast<std::size_t>(n) > body.nodes.size())
          return refuse(bodies_path, e.nodes[k].span,
                        "node " + std::to_string(n) + " is not a node of this body");
        element.nodes[k] = static_cast<std::int32_t>(n - 1);
      }
      const bool large = large_strain[model.nickname.value];
      const fem::MaterialLaw law = !large                                   ? fem::MaterialLaw::linear_elastic
                                   : own_large_strain[model.nickname.value] ? fem::MaterialLaw::j2_plasticity
                                                                            : fem::MaterialLaw::neo_hookean;
      element.material = material(reference->behav, law);
      if (element.material < 0)
        return refuse(
            bulk_path, reference->behav.span,
            "bulk behaviour '" + reference->behav.value +
                "' is not what its model needs: an ELAS law with a density, a Young's modulus and a "
                "Poisson's "
                "ratio (an ELAS_PLAS law with a von Mises criterion and linear, Swift or Hollomon isotropic "
                "hardening, nothing kinematic or viscous, for LMGC90's own large-strain material)");
      const grammar::ModelOption* mstrg = option(model, "mstrg");
      const bool lump = mstrg && mstrg->value.value == "lump_";  // anything else: consistent (mailx-2d.md §3)
      if (any && lump != lumped)
        return refuse(models_path, model.nickname.span,
                      "a body whose elements mix lumped and consistent masses");
      const auto kinematics = large ? fem::Kinematics::total_lagrangian : fem::Kinematics::small_strain;
      if (any && kinematics != mesh.kinematics)
        return refuse(models_path, model.nickname.span, "a body whose elements mix small and large strain");
      mesh.kinematics = kinematics;
      lumped = lump;
      any = true;
      body_matlib = matlib[model.nickname.value];
      mesh.elements.push_back(element);
    }
    mesh.lumped_mass = lumped;
    mesh.materials = materials;
    // Contactors: ranked in the body's list, every type counted; serials per type over the case.
    const auto mesh_index = static_cast<std::int32_t>(out.bodies.size());
    std::int32_t rank = 0;
    for (const grammar::Contactor& t : body.contactors) {
      ++rank;
      MeshContactor c;
      c.type = t.type.value;
      c.color = t.color.value;
      c.mesh = mesh_index;
      c.rank = rank;
      if (!runs_mesh_contactor_2d(c.type) || dimension != 2) {
        return refuse(
            bodies_path, t.type.span,
            "contactor " + c.type +
                " on a MAILx body is not run by lmgc yet (CLxxx, ALpxx, PT2DL and DISKL in 2D are)");
      }
      c.shape = c.type == "CLxxx"   ? MeshContactorShape::candidate_point
                : c.type == "PT2DL" ? MeshContactorShape::point
                : c.type == "DISKL" ? MeshContactorShape::disk
                                    : MeshContactorShape::polyline;
      if (c.shape != MeshContactorShape::polyline) c.apab = t.values.empty() ? 0.0 : t.values.front().value;
      if (c.shape == MeshContactorShape::disk) {
        c.arc_height = t.values.size() > 1 ? t.values[1].value : 0.0;
        c.arc_half_chord = t.values.size() > 2 ? t.values[2].value : 0.0;
        // LMGC90 divides by the sagitta (get_radius_DISKL); a flat or inward arc is no disk.
        if (!(c.arc_height > 0.0))
          return refuse(bodies_path, t.type.span,
                        "DISKL needs a positive arc height bdyr (its radius is (bdyr² + brpm²)/(2 bdyr))");
      }
      std::vector<const grammar::Integer*> nodes;
      for (const grammar::Integer& n : t.nodes) nodes.push_back(&n);
      for (const grammar::ContactorContinuation& more : t.continuations) {
        // A '+ALpxx' segment starts where the previous one ended (LMGC90 stops on a "non continuous
        // line"): its second node extends the polyline.
        if (more.nodes.size() < 2) continue;
        if (more.nodes[0].value != nodes.back()->value)
          return refuse(bodies_path, more.nodes[0].span,
                        "this segment does not start where the previous one ended (node " +
                            std::to_string(nodes.back()->value) + ")");
        nodes.push_back(&more.nodes[1]);
      }
      for (const grammar::Integer* n : nodes) {
        if (n->value < 1 || static_cast<std::size_t>(n->value) > body.nodes.size())
          return refuse(bodies_path, n->span,
                        "node " + std::to_string(n->value) + " is not a node of this body");
        c.nodes.push_back(static_cast<std::int32_t>(n->value - 1));
      }
      if (c.nodes.size() < 2)
        return refuse(bodies_path, t.type.span, "contactor " + c.type + " needs two nodes");
      c.serial = 1;
      for (const MeshContactor& other : out.contactors) c.serial += other.type == c.type;
      out.contactors.push_back(std::move(c));
    }
    out.bodies.push_back(std::move(mesh));
    out.matlib.push_back(body_matlib);
  }
  for (auto& mesh : out.bodies) mesh.materials = materials;
  return true;
}

}  // namespace lmgc::solver
