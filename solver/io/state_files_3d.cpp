#include "solver/io/state_files_3d.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <string_view>
#include <tuple>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"

namespace lmgc::solver {

grammar::DofFile dof_file_3d(const Scene3D& scene, const RunState3D& state) {
  grammar::DofFile file;
  file.step = grammar::Integer{state.step};
  file.time = grammar::Real{state.time};
  grammar::DofSection section;
  section.closed = true;
  const RigidBodies3D& b = scene.bodies;
  section.bodies.reserve(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    grammar::DofBody body;
    body.body_type = grammar::Word{"RBDY3"};
    body.number = grammar::Integer{static_cast<std::int64_t>(i + 1)};
    grammar::DofNode node;
    node.node_type = grammar::Word{"NO6xx"};
    node.number = grammar::Integer{1};
    for (int d = 0; d < 6; ++d) {
      node.x.push_back(grammar::Real{b.displacement[i](d)});
      node.v.push_back(grammar::Real{b.velocity[i](d)});
    }
    // a, b, g: the principal axes (columns of the frame) in global coordinates.
    for (int axis = 0; axis < 3; ++axis)
      for (int d = 0; d < 3; ++d) node.frame.push_back(grammar::Real{b.frame[i](d, axis)});
    body.nodes.push_back(std::move(node));
    section.bodies.push_back(std::move(body));
  }
  file.sections.push_back(std::move(section));
  // The MAILx module writes its dashed line even when it has no body (state-and-outputs.md §1.3).
  file.sections.push_back(grammar::DofSection{{}, true});
  return file;
}

namespace {

// The family a Vloc_Rloc block type names; false for the others.
bool family_of_name(std::string_view name, PairFamily3D& family) {
  for (int k = 0; k < kPairFamily3DCount; ++k)
    if (pair_family_name(static_cast<PairFamily3D>(k)) == name) {
      family = static_cast<PairFamily3D>(k);
      return true;
    }
  return false;
}

// PRPRx and PRPLx carry the CDVER integer after the candidate's rank.
bool has_vertex_column(PairFamily3D f) {
  return f == PairFamily3D::PRPRx || f == PairFamily3D::PRPLx;
}

// The contactor type LMGC90's contact modules write: spheres of clusters (SPHEb) belong to the
// SPHER module and are written SPHER (1_ClusterSP_2_PL reference files).
std::string_view written_type(const Contactor3D& c) {
  switch (c.shape) {
    case ContactorShape3D::sphere:
      return "SPHER";
    case ContactorShape3D::plane:
      return "PLANx";
    case ContactorShape3D::polyhedron:
      return "POLYR";
    case ContactorShape3D::cylinder:
      return "CYLND";
    case ContactorShape3D::tube:
      return "DNLYC";
    case ContactorShape3D::point:
      return "PT3Dx";
  }
  return "PLANx";
}

// Index (t, n, s) storage of the local component a label letter names.
int local_index(char letter) {
  return letter == 't' ? 0 : letter == 'n' ? 1 : 2;
}

// The value written under a Vloc_Rloc label of a 3D module (interaction_catalogue.cpp labels).
double labelled_value(std::string_view label, const Interaction3D& c, double h) {
  if (label.size() < 4) return 0.0;
  if (label.starts_with("rl")) return c.r(local_index(label[2])) / h;
  if (label.starts_with("vl")) return c.u(local_index(label[2]));
  // gTT =, gapTT, gap =: the end-of-step gap set by the NLGS post-processing.
  if (label.starts_with("g")) return c.gap_begin + h * c.u(1);
  if (label.starts_with("coo")) return c.point(std::clamp(label[3] - '1', 0, 2));
  if (label[1] == '(') return c.frame(local_index(label[0]), std::clamp(label[2] - '1', 0, 2));
  return 0.0;
}

}  // namespace

grammar::VlocRlocFile vloc_rloc_file_3d(const Scene3D& scene, const RunState3D& state) {
  using grammar::Integer;
  using grammar::Real;
  using grammar::Word;
  grammar::VlocRlocFile file;
  file.step = Integer{state.step};
  file.time = Real{state.time};
  const double h = state.h;
  // Serial index of each contactor among the scene's contactors of its shape (spheres: SPHER and
  // SPHEb, LMGC90's SPHER list): the trailing iantac of SPSPx, SPCDx and SPDCx.
  std::vector<std::int64_t> serial(scene.contactors.size(), 0);
  std::array<std::int64_t, 8> per_shape{};  // by ContactorShape3D
  for (std::size_t k = 0; k < scene.contactors.size(); ++k)
    serial[k] = ++per_shape[static_cast<std::size_t>(scene.contactors[k].shape)];
  // LMGC90's 3D module order (state-and-outputs.md §1.1): ... PRPLx, PRPRx, ... SPPLx, SPPRx, SPSPx.
  constexpr PairFamily3D kWriteOrder[] = {PairFamily3D::CDCDx, PairFamily3D::CDPLx, PairFamily3D::PRPLx,
                                          PairFamily3D::PRPRx, PairFamily3D::PTPT3, PairFamily3D::SPCDx,
                                          PairFamily3D::SPDCx, PairFamily3D::SPPLx, PairFamily3D::SPPRx,
                                          PairFamily3D::SPSPx};
  static_assert(std::size(kWriteOrder) == kPairFamily3DCount);
  for (PairFamily3D family : kWriteOrder) {
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < state.contacts.size(); ++k)
      if (state.contacts[k].family == family) members.push_back(k);
    if (members.empty()) continue;
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(pair_family_name(family));
    // Written by candidate contactor, then in detection order (LMGC90's adjacency rank).
    std::vector<std::size_t> order(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) order[m] = m;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return state.contacts[members[a]].candidate < state.contacts[members[b]].candidate;
    });
    for (std::size_t m : order) {
      const Interaction3D& c = state.contacts[members[m]];
      const Contactor3D& cd = scene.contactors[static_cast<std::size_t>(c.candidate)];
      const Contactor3D& an = scene.contactors[static_cast<std::size_t>(c.antagonist)];
      const NamedLaw& law = scene.laws[static_cast<std::size_t>(c.law)];
      grammar::VlocRlocInteraction out;
      out.type = Word{std::string(kind->type)};
      out.number = Integer{static_cast<std::int64_t>(m + 1)};
      out.title = std::string(kind->title);
      // Data line: the CDVER column is blank (9X) for spheres, an integer for polyhedra (the
      // PRPLx vertex, 0 for PRPRx); SPSPx ends with iantac.
      out.words = {
          Word{"RBDY3"}, Word{std::string(written_type(cd))}, Word{law.nickname},
          Word{"RBDY3"}, Word{std::string(written_type(an))}, Word{std::string(status_name(c.status))}};
      out.integers = {Integer{cd.body + 1}, Integer{cd.rank}};
      if (has_vertex_column(family)) out.integers.push_back(Integer{c.vertex});
      out.integers.push_back(Integer{an.body + 1});
      out.integers.push_back(Integer{an.rank});
      // SPSPx, SPCDx, SPDCx and PTPT3 end with iantac (PTPT3 under its title's "iadj").
      if (family == PairFamily3D::SPSPx || family == PairFamily3D::SPCDx || family == PairFamily3D::SPDCx ||
          family == PairFamily3D::PTPT3)
        out.integers.push_back(Integer{serial[static_cast<std::size_t>(c.antagonist)]});
      for (const grammar::VectorLineKind& line : kind->vectors) {
        grammar::VlocRlocVector v;
        for (int k = 0; k < line.count; ++k) {
          v.labels.emplace_back(line.labels[k]);
          v.values.push_back(Real{labelled_value(line.labels[k], c, h)});
        }
        out.vectors.push_back(std::move(v));
      }
      const grammar::LawKind* law_kind = grammar::find_law_kind(law_keyword(law.law));
      const int internals = law_kind ? law_kind->internals_3d.count : 0;
      if (internals > 0) {
        // A scene whose laws keep no state has no internals to write but zeros.
        const LawState3D none;
        const auto& internal = (state.law_states.empty() ? none : state.law_states[members[m]]).internal;
        std::vector<Real> values;
        for (int k = 0; k < internals; ++k)
          values.push_back(Real{
              static_cast<std::size_t>(k) < internal.size() ? internal[static_cast<std::size_t>(k)] : 0.0});
        out.internal_comment = grammar::internal_variables_comment(law_kind->internals_3d);
        out.internal_lines.push_back(std::move(values));
      }
      file.interactions.push_back(std::move(out));
    }
  }
  return file;
}

WarmStart3D warm_start_3d(const grammar::VlocRlocFile& file, const Scene3D& scene, double h) {
  // Contactor index by (body number, contactor rank).
  std::map<std::pair<std::int64_t, std::int64_t>, std::int32_t> by_rank;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k)
    by_rank[{scene.contactors[k].body + 1, scene.contactors[k].rank}] = static_cast<std::int32_t>(k);
  std::vector<std::pair<Interaction3D, LawState3D>> previous;
  for (const auto& b : file.interactions) {
    PairFamily3D family;
    if (!family_of_name(b.type.value, family)) continue;
    const auto& n = b.integers;
    const std::size_t an_at = has_vertex_column(family) ? 3 : 2;
    if (n.size() < an_at + 2) continue;
    const auto cd = by_rank.find({n[0].value, n[1].value});
    const auto an = by_rank.find({n[an_at].value, n[an_at + 1].value});
    if (cd == by_rank.end() || an == by_rank.end()) continue;
    const Contactor3D& candidate = scene.contactors[static_cast<std::size_t>(cd->second)];
    const Contactor3D& antagonist = scene.contactors[static_cast<std::size_t>(an->second)];
    PairFamily3D expected;
    if (!pair_family_3d(std::string(written_type(candidate)), std::string(written_type(antagonist)),
                        expected) ||
        expected != family)
      continue;
    Interaction3D c;
    c.family = family;
    if (has_vertex_column(family)) c.vertex = static_cast<std::int32_t>(n[2].value);
    c.candidate = cd->second;
    c.antagonist = an->second;
    c.candidate_body = candidate.body;
    c.antagonist_body = antagonist.body;
    // The law named on the data line (A5 words: cdbdy, cdtac, behav, anbdy, antac, sttus).
    if (b.words.size() >= 3)
      for (std::size_t l = 0; l < scene.laws.size(); ++l)
        if (scene.laws[l].nickname == b.words[2].value) c.law = static_cast<std::int32_t>(l);
    for (const auto& line : b.vectors)
      for (std::size_t k = 0; k < line.values.size() && k < line.labels.size(); ++k) {
        const std::string_view label = line.labels[k];
        if (label.size() < 3) continue;
        if (label.starts_with("rl"))
          c.r(local_index(label[2])) = line.values[k].value * h;
        else if (label.starts_with("vl"))
          c.u(local_index(label[2])) = line.values[k].value;
        else if (label.starts_with("coo"))
          c.point(std::clamp(label[3] - '1', 0, 2)) = line.values[k].value;
      }
    // PRPRx's warm-start key: the point about the candidate's centre in its frame, as read.
    const auto body = static_cast<std::size_t>(candidate.body);
    c.candidate_point =
        scene.bodies.frame_initial[body].transpose() *
        (c.point - scene.bodies.reference[body] - scene.bodies.displacement_begin[body].head<3>());
    if (!b.words.empty()) status_from_name(b.words.back().value, c.status);
    c.status_begin = c.status;
    LawState3D law_state;
    std::size_t k = 0;
    for (const auto& line : b.internal_lines)
      for (const auto& v : line)
        if (k < law_state.internal.size()) law_state.internal[k++] = v.value;
    previous.emplace_back(c, law_state);
  }
  std::stable_sort(previous.begin(), previous.end(), [](const auto& x, const auto& y) {
    const Interaction3D &a = x.first, &b = y.first;
    return std::tie(a.family, a.candidate, a.antagonist) < std::tie(b.family, b.candidate, b.antagonist);
  });
  // Two PTPT3 links of one pair (directly and across a period) are told apart by their rank among
  // the pair's links, as detection numbers them (PointLink3D::pair_rank).
  WarmStart3D warm;
  for (auto& [c, law_state] : previous) {
    if (!warm.interactions.empty()) {
      const Interaction3D& a = warm.interactions.back();
      if (c.family == PairFamily3D::PTPT3 && a.family == c.family && a.candidate == c.candidate &&
          a.antagonist == c.antagonist)
        c.vertex = a.vertex + 1;
    }
    warm.interactions.push_back(c);
    warm.law_states.push_back(law_state);
  }
  return warm;
}

}  // namespace lmgc::solver
