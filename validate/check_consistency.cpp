// Consistency of a case beyond names: one dimension for every body, node, element and contactor;
// elements and their models; models and the options LMGC90's own finite elements need; bulk
// behaviours and what their users need; contact laws and the interactions they may serve;
// evolution files. docs/lmgc90-facts/datbox-inputs.md §1, §2, §4, §5; contact-laws.md §0, §4; facts from
// LMGC90's mod_models.f90 (init_models), mod_nlgs.f90 and mod_nlgs_3D.f90 (prep_nlgs) cited per table.
#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <unordered_map>
#include <unordered_set>

#include "grammar/bodies/contactor_catalogue.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "validate/case_index.hpp"
#include "validate/checks.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

using grammar::Location;

// ---- tables ----------------------------------------------------------------------------------

// Dimension of the BODIES.DAT element types (0: bars and shells, any dimension).
struct ElementDimension {
  std::string_view element;
  int dimension;
};
constexpr ElementDimension kElementDimensions[] = {
    {"S2xxx", 0}, {"S3xxx", 0}, {"T3xxx", 2}, {"T6xxx", 2}, {"Q4xxx", 2}, {"Q8xxx", 2},
    {"H8xxx", 3}, {"H20xx", 3}, {"TE4xx", 3}, {"TE10x", 3}, {"PRI6x", 3}, {"PRI15", 3},
};

// The finite elements a MODELS.DAT model may name, with the BODIES.DAT element (node layout)
// each applies to: LMGC90 takes the element of the model and the connectivity of the body
// (mod_mecaMAILx.f90 load_models; element names of mod_a_mecaEF_iso.f90, mod_a_mecaEF_shb.f90,
// mod_a_therEF_iso.f90). Names not listed (bars, shells, joints, external elements) are not checked.
struct ModelElement {
  std::string_view model_element;
  std::string_view body_element;
};
constexpr ModelElement kModelElements[] = {
    {"T3xxx", "T3xxx"}, {"T6xxx", "T6xxx"}, {"Q4xxx", "Q4xxx"}, {"Q4P0x", "Q4xxx"}, {"Q8xxx", "Q8xxx"},
    {"Q8Rxx", "Q8xxx"}, {"H8xxx", "H8xxx"}, {"H20xx", "H20xx"}, {"H20Rx", "H20xx"}, {"TE4xx", "TE4xx"},
    {"TE10x", "TE10x"}, {"PRI6x", "PRI6x"}, {"PRI15", "PRI15"}, {"SHB6x", "PRI6x"},
};

// Laws that LMGC90's NLGS accepts only for some interaction families: prep_nlgs stops with
// "... not implemented for this contact element" otherwise. Laws not listed serve every family.
constexpr std::string_view kGapCzm2D[] = {"CLALp", "CLJCx", "PLALp", "DKALp"};
constexpr std::string_view kIqsCzm2D[] = {"DKDKx", "DKJCx", "PLPLx", "PLJCx", "DKDKL"};
constexpr std::string_view kGapMohr2D[] = {"CLALp", "CLJCx"};
constexpr std::string_view kWetCzm2D[] = {"DKDKx", "DKJCx", "PLPLx"};
constexpr std::string_view kPointRod2D[] = {"PTPT2"};
constexpr std::string_view kGapCzm3D[] = {"CSASp", "CSPRx", "PRASp"};
constexpr std::string_view kIqsCzm3D[] = {"PRPLx", "PRPRx", "SPSPx", "SPPLx", "SPPRx",
                                          "SPCDx", "SPDCx", "CDPLx", "CDCDx", "PTPT3"};
constexpr std::string_view kPointRod3D[] = {"PTPT3"};

struct LawFamilies {
  std::string_view law;
  int dimension;
  std::span<const std::string_view> families;
  std::string_view source;
};
constexpr LawFamilies kLawFamilies[] = {
    // mod_nlgs.f90:2081-2119 (contact length from CLALp/CLJCx, 0.35 for PLALp/DKALp)
    {"MAC_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"MSMP_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"MAL_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"MP_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"MP3_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"MP3_CZM_THER", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"TH_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"ABP_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"EXPO_CZM", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    {"EXPO_CZM_P", 2, kGapCzm2D, "mod_nlgs.f90:2118"},
    // mod_nlgs.f90:2313-2348 and 1507-1518 (contact length of disks and polygons)
    {"IQS_MAC_CZM", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_MAL_CZM", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_TH_CZM", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_ABP_CZM", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_EXPO_CZM", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_EXPO_CZM_P", 2, kIqsCzm2D, "mod_nlgs.f90:2347"},
    {"IQS_MOHR_DS_CLB", 2, kIqsCzm2D, "mod_nlgs.f90:1517"},
    {"GAP_MOHR_DS_CLB", 2, kGapMohr2D, "mod_nlgs.f90:1562"},
    {"IQS_WET_CZM", 2, kWetCzm2D, "mod_nlgs.f90:2505"},
    {"NARD_ROD", 2, kPointRod2D, "mod_nlgs.f90:2746"},
    // mod_nlgs_3D.f90:1831-1866 (contact surface of mesh patches)
    {"MAC_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"MP_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"MP3_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"MAL_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"TH_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"ABP_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"EXPO_CZM", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    {"EXPO_CZM_P", 3, kGapCzm3D, "mod_nlgs_3D.f90:1864"},
    // mod_nlgs_3D.f90:1994-2034 and 1466-1484 (contact surface of rigid contactors)
    {"IQS_MAC_CZM", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_MAL_CZM", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_TH_CZM", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_ABP_CZM", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_EXPO_CZM", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_EXPO_CZM_P", 3, kIqsCzm3D, "mod_nlgs_3D.f90:2032"},
    {"IQS_MOHR_DS_CLB", 3, kIqsCzm3D, "mod_nlgs_3D.f90:1483"},
    {"NARD_ROD", 3, kPointRod3D, "mod_nlgs_3D.f90:2410"},
};

// What LMGC90's own finite elements need from MODELS.DAT (mod_models.f90 init_models, for a
// model whose 'isext' is 'no___'; other values hand the model to an external library).
constexpr std::string_view kModelKinds[] = {"MECAx", "THERM", "POROx", "MULTI"};

const ModelElement* find_model_element(std::string_view name) {
  auto it = std::find_if(std::begin(kModelElements), std::end(kModelElements),
                         [&](const ModelElement& m) { return m.model_element == name; });
  return it == std::end(kModelElements) ? nullptr : &*it;
}

int element_dimension(std::string_view element) {
  for (const auto& e : kElementDimensions)
    if (e.element == element) return e.dimension;
  return 0;
}

std::string joined(std::span<const std::string_view> names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// The first 5 characters of an option value: what LMGC90 compares (get_eleop_value).
std::string_view option5(const grammar::Word& value) {
  return std::string_view(value.value).substr(0, std::min<std::size_t>(5, value.value.size()));
}

// ---- the checks ------------------------------------------------------------------------------

// L2013: a case runs in one dimension (LMGC90 reads RBDY2 bodies in 2D, RBDY3 bodies in 3D,
// datbox-inputs.md §1, §9 item 13); MAILx nodes, elements and contactors follow it.
void check_dimensions(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  const std::string path = datbox_path(files, "BODIES.DAT");
  const int dimension = case_dimension(files);
  // What decides the dimension: the first rigid body, else the first NO3xx MAILx node.
  Location decided{path, {}};
  for (const auto& body : files.bodies->bodies) {
    if (body.type != grammar::BodyType::mailx) {
      decided.span = body.type_span;
      break;
    }
    if (decided.span.line == 0)
      for (const auto& node : body.nodes)
        if (node.type.value == "NO3xx") {
          decided.span = node.type.span;
          break;
        }
  }
  const std::string why = fmt::format("the case is {}D because of this line", dimension);
  const BodyIndex index(*files.bodies);
  // RBDY2 and RBDY3 together: said once, at the first body of the less numerous type.
  const std::size_t planar = index.count(grammar::BodyType::rbdy2),
                    solid = index.count(grammar::BodyType::rbdy3);
  if (planar > 0 && solid > 0) {
    const grammar::BodyType fewer = planar < solid ? grammar::BodyType::rbdy2 : grammar::BodyType::rbdy3;
    const grammar::BodyType more =
        fewer == grammar::BodyType::rbdy2 ? grammar::BodyType::rbdy3 : grammar::BodyType::rbdy2;
    const grammar::Body* first_fewer = index.find(grammar::body_type_keyword(fewer), 1);
    const grammar::Body* first_more = index.find(grammar::body_type_keyword(more), 1);
    report_related(
        sink, "L2013", Location{path, first_fewer->type_span},
        fmt::format("the case mixes {} RBDY2 and {} RBDY3 bodies: LMGC90 reads RBDY2 bodies in 2D and RBDY3 "
                    "bodies in 3D, never both",
                    planar, solid),
        {{Location{path, first_more->type_span},
          fmt::format("the first {} body", grammar::body_type_keyword(more))}});
  }
  for (const auto& body : files.bodies->bodies) {
    const std::string owner = body_name(body, index.rank_of(body));
    if (body.type != grammar::BodyType::mailx) continue;
    // MAILx: mechanical nodes NO2xx (2D) or NO3xx (3D); NO1xx (thermal) fits both.
    for (const auto& node : body.nodes) {
      const int dofs = node_dofs(node.type.value);
      if ((dofs == 2 || dofs == 3) && dofs != dimension) {
        report_related(sink, "L2013", Location{path, node.type.span},
                       fmt::format("node {} of {} is a {} ({}D) node in a {}D case",
                                   &node - body.nodes.data() + 1, owner, node.type.value, dofs, dimension),
                       {{decided, why}});
        break;
      }
    }
    for (const auto& element : body.elements) {
      const int d = element_dimension(element.type.value);
      if (d != 0 && d != dimension) {
        report_related(sink, "L2013", Location{path, element.type.span},
                       fmt::format("element {} {} of {} is a {}D element in a {}D case", element.type.value,
                                   &element - body.elements.data() + 1, owner, d, dimension),
                       {{decided, why}});
        break;
      }
    }
    std::unordered_set<std::string> reported;
    for (const auto& c : body.contactors) {
      const grammar::ContactorKind* kind = grammar::find_contactor_kind(c.type.value);
      if (!kind || kind->dimension == dimension || !reported.insert(c.type.value).second) continue;
      report_related(sink, "L2013", Location{path, c.type.span},
                     fmt::format("contactor {} of {} is a {}D contactor in a {}D case", c.type.value, owner,
                                 kind->dimension, dimension),
                     {{decided, why}});
    }
  }
}

// L2009 (element/model), L2019 (model options), L2020 (bulk behaviour against its users).
void check_models_and_behaviours(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");
  const std::string models_path = datbox_path(files, "MODELS.DAT");
  const std::string bulk_path = datbox_path(files, "BULK_BEHAV.DAT");

  // MODELS.DAT: what init_models stops on, for every model of the file.
  if (files.models)
    for (const auto& model : files.models->models) {
      const std::string& element = model.element.value;
      if (element.rfind("EXT", 0) == 0 || element.rfind("Rxx", 0) == 0) continue;  // external elements
      const std::string_view kind = model.kind.value;
      // An unknown kind is the reader's (L1001).
      if (std::find(std::begin(kModelKinds), std::end(kModelKinds), kind) == std::end(kModelKinds)) continue;
      const grammar::Word* isext = model_option(model, "isext");
      if (!isext) {
        sink.report("L2019", Location{models_path, model.nickname.span},
                    fmt::format("model '{}' has no 'isext' option; LMGC90 stops with 'undefined option'",
                                model.nickname.value),
                    "add an option line 'isext  no___' (columns 23-27 and 30-34) for LMGC90's own elements");
        continue;
      }
      if (option5(*isext) != "no___") continue;  // handed to an external library
      auto missing = [&](std::string_view option, std::string_view values) {
        sink.report(
            "L2019", Location{models_path, model.nickname.span},
            fmt::format("model '{}' ({}, isext no___) has no '{}' option; LMGC90 needs one of {} (it stops "
                        "with 'undefined option')",
                        model.nickname.value, kind, option, values));
      };
      auto invalid = [&](const grammar::Word& value, std::string_view option, std::string_view allowed) {
        sink.report("L2019", Location{models_path, value.span},
                    fmt::format("option '{}' of model '{}' is '{}'; LMGC90's own {} elements accept {}",
                                option, model.nickname.value, value.value, kind, allowed),
                    "or hand the model to an external library through 'isext'");
      };
      if (kind == "THERM") {
        const grammar::Word* form = model_option(model, "form_");
        if (!form)
          missing("form_", "'class' or 'discr'");
        else if (option5(*form) != "class" && option5(*form) != "discr")
          invalid(*form, "form_", "'class' or 'discr'");
        continue;
      }
      const grammar::Word* kine = model_option(model, "kine_");
      if (!kine) {
        missing("kine_", "'small' or 'large'");
        continue;
      }
      if (option5(*kine) == "small") continue;
      if (option5(*kine) != "large") {
        invalid(*kine, "kine_", "'small' or 'large'");
        continue;
      }
      if (kind == "MULTI") {
        invalid(*kine, "kine_", "only 'small' (no large deformations for MULTI)");
        continue;
      }
      const grammar::Word* form = model_option(model, "form_");
      if (!form)
        missing("form_", "'UpdtL' with 'kine_ large'");
      else if (option5(*form) != "UpdtL")
        invalid(*form, "form_", "only 'UpdtL' with 'kine_ large'");
    }

  if (!files.bodies) return;
  std::unordered_map<std::string, const grammar::BulkLaw*> bulk;
  if (files.bulk_behav) bulk = bulk_laws_by_name(*files.bulk_behav);
  std::unordered_map<std::string, const grammar::Model*> models;
  if (files.models) models = models_by_name(*files.models);
  const BodyIndex index(*files.bodies);
  std::unordered_set<std::string> reported;  // one diagnostic per combination

  for (const auto& body : files.bodies->bodies) {
    const std::string owner = body_name(body, index.rank_of(body));
    // Rigid bodies take their mass from the density (Umas) of their behaviour.
    if (body.rigid_bulk) {
      auto it = bulk.find(body.rigid_bulk->behav.value);
      if (it != bulk.end()) {
        const grammar::BulkLawKind* kind = grammar::find_bulk_law_kind(it->second->law_type.value);
        if (kind && kind->first_line == grammar::BulkFirstLine::values)
          report_related(
              sink, "L2020", Location{bodies_path, body.rigid_bulk->behav.span},
              fmt::format("bulk behaviour '{}' of {} is a {} law, which has no density: a rigid body needs "
                          "'Umas'",
                          it->second->nickname.value, owner, it->second->law_type.value),
              {{Location{bulk_path, it->second->nickname.span}, "the behaviour is defined here"}},
              "give the body a RIGID behaviour");
      }
    }
    for (const auto& element : body.elements) {
      const std::string where =
          fmt::format("element {} {} of {}", element.type.value, &element - body.elements.data() + 1, owner);
      for (const auto& line : element.models) {
        auto m = models.find(line.model.value);
        if (m == models.end()) continue;  // L2004
        const grammar::Model& model = *m->second;
        // The model's element must have the element's nodes.
        const ModelElement* fe = find_model_element(model.element.value);
        if (fe && fe->body_element != element.type.value &&
            reported.insert("L2009|" + element.type.value + "|" + model.nickname.value).second)
          report_related(sink, "L2009", Location{bodies_path, line.model.span},
                         fmt::format("{} uses model '{}', whose finite element {} is for {} elements", where,
                                     model.nickname.value, model.element.value, fe->body_element),
                         {{Location{models_path, model.element.span}, "the model's element is given here"}});
        // The behaviour must carry what the model computes with.
        auto b = bulk.find(line.behav.value);
        if (b == bulk.end()) continue;  // L2001
        const grammar::BulkLaw& law = *b->second;
        std::string_view needed, block;
        const bool mechanical =
            model.kind.value == "MECAx" || model.kind.value == "POROx" || model.kind.value == "MULTI";
        const grammar::Word* mater = model_option(model, "mater");
        if (mechanical && !find_bulk_block(law, grammar::BulkBlockKind::elas) &&
            !find_bulk_block(law, grammar::BulkBlockKind::umat))
          needed = "Young's modulus and Poisson ratio", block = "ELAS";
        else if (mechanical && mater && option5(*mater).substr(0, 2) == "J2" &&
                 !find_bulk_block(law, grammar::BulkBlockKind::plas))
          needed = "a plasticity criterion and hardening", block = "PLAS";
        else if (model.kind.value == "THERM" && !find_bulk_block(law, grammar::BulkBlockKind::therm))
          needed = "heat capacity and conductivity", block = "THERM";
        if (!needed.empty() &&
            reported.insert("L2020|" + model.nickname.value + "|" + law.nickname.value).second)
          report_related(
              sink, "L2020", Location{bodies_path, line.behav.span},
              fmt::format("{} uses bulk behaviour '{}' ({}) with model '{}' ({}), which needs {} (an {} "
                          "block)",
                          where, law.nickname.value, law.law_type.value, model.nickname.value,
                          model.kind.value, needed, block),
              {{Location{bulk_path, law.nickname.span}, "the behaviour is defined here"}});
      }
    }
  }
}

// L2018: the law of a visibility row must exist in the case's dimension and serve the row's
// interaction family.
void check_law_families(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  const std::string path = datbox_path(files, "TACT_BEHAV.DAT");
  const int dimension = case_dimension(files);
  const auto laws = contact_laws_by_name(*files.tact_behav);
  std::unordered_set<std::string> present;
  for (const auto& body : files.bodies->bodies)
    for (const auto& c : body.contactors) present.insert(see_class(body, c));
  for (const auto& see : files.tact_behav->sees) {
    auto it = laws.find(see.law_nickname.value);
    if (it == laws.end()) continue;  // L2002
    const grammar::TactLaw& law = *it->second;
    if (!present.count(
            see_class(see.candidate_body.value, see.candidate_contactor.value, see.candidate_colour.value)) ||
        !present.count(see_class(see.antagonist_body.value, see.antagonist_contactor.value,
                                 see.antagonist_colour.value)))
      continue;  // the row never matches (L2010): LMGC90 never prepares it
    const grammar::LawKind* kind = grammar::find_law_kind(law.keyword.value);
    if (!kind) continue;
    const Location defined{path, law.keyword.span};
    const int internals = dimension == 2 ? kind->internals_2d.count : kind->internals_3d.count;
    if (internals < 0) {
      report_related(
          sink, "L2018", Location{path, see.law_nickname.span},
          fmt::format("law '{}' ({}) does not exist in {}D: LMGC90 stops on it ('Unsupported nbDIME')",
                      law.nickname.value, law.keyword.value, dimension),
          {{defined, "the law is defined here"}});
      continue;
    }
    const InteractionFamily* family =
        find_interaction_family(see.candidate_contactor.value, see.antagonist_contactor.value);
    if (!family) continue;  // L2014
    // P2P2L points that coincide under another law than COUPLED_DOF: the solver's L2018
    // (case_input.cpp glued_points_have_a_glue), which lmgc-check reports too.
    for (const LawFamilies& rule : kLawFamilies) {
      if (rule.law != law.keyword.value || rule.dimension != dimension) continue;
      if (std::find(rule.families.begin(), rule.families.end(), family->interaction) != rule.families.end())
        break;
      report_related(
          sink, "L2018", Location{path, see.law_nickname.span},
          fmt::format("law '{}' ({}) cannot serve {} interactions in {}D: LMGC90 stops with 'not "
                      "implemented for this contact element' ({})",
                      law.nickname.value, law.keyword.value, family->interaction, dimension, rule.source),
          {{defined, "the law is defined here"}},
          fmt::format("{} serves {}", law.keyword.value, joined(rule.families)));
      break;
    }
  }
}

// L2016: evolution files need strictly increasing times (read_G_evolution stops on equal
// consecutive times; the interpolation assumes increasing ones). datbox-inputs.md §5.
void check_evolutions(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  for (const auto& [name, evolution] : files.evolutions) {
    const std::string path = datbox_path(files, name);
    for (std::size_t k = 1; k < evolution.points.size(); ++k) {
      const grammar::Real& before = evolution.points[k - 1].time;
      const grammar::Real& time = evolution.points[k].time;
      if (time.value > before.value) continue;
      report_related(
          sink, "L2016", Location{path, time.span},
          fmt::format("time {} of evolution file '{}' is not after the time before it ({}); LMGC90 needs "
                      "strictly increasing times",
                      time.value, name, before.value),
          {{Location{path, before.span}, "the time before"}});
      break;
    }
  }
}

}  // namespace

void check_consistency(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (files.bodies) check_dimensions(files, sink);
  check_models_and_behaviours(files, sink);
  if (files.bodies && files.tact_behav) check_law_families(files, sink);
  check_evolutions(files, sink);
}

}  // namespace lmgc::validate
