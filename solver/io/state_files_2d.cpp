#include "solver/io/state_files_2d.hpp"

#include <algorithm>
#include <map>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"

namespace lmgc::solver {

grammar::DofFile dof_file_2d(const Scene2D& scene, const RunState2D& state) {
  grammar::DofFile file;
  file.step = grammar::Integer{state.step};
  file.time = grammar::Real{state.time};
  grammar::DofSection section;
  section.closed = true;
  const RigidBodies2D& b = scene.bodies;
  section.bodies.reserve(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    grammar::DofBody body;
    body.body_type = grammar::Word{"RBDY2"};
    body.number = grammar::Integer{static_cast<std::int64_t>(i + 1)};
    grammar::DofNode node;
    node.node_type = grammar::Word{"NO3xx"};
    node.number = grammar::Integer{1};
    for (int d = 0; d < 3; ++d) {
      node.x.push_back(grammar::Real{b.displacement[i](d)});
      node.v.push_back(grammar::Real{b.velocity[i](d)});
    }
    body.nodes.push_back(std::move(node));
    section.bodies.push_back(std::move(body));
  }
  file.sections.push_back(std::move(section));
  // The MAILx module's section (its dashed line even without a body, state-and-outputs.md §1.3):
  // per body, per node, X and V (mecaMAILx write_xxx_dof).
  grammar::DofSection mailx{{}, true};
  const DeformableBodies& d = scene.deformable;
  for (std::size_t m = 0; m < d.states.size(); ++m) {
    const int dimension = d.meshes.bodies[m].dimension;
    grammar::DofBody body;
    body.body_type = grammar::Word{"MAILx"};
    body.number = grammar::Integer{static_cast<std::int64_t>(m + 1)};
    body.model = grammar::Word{"MECAx"};
    const std::string node_type = dimension == 2 ? "NO2xx" : "NO3xx";
    for (std::size_t k = 0; k < d.meshes.bodies[m].nodes(); ++k) {
      grammar::DofNode node;
      node.node_type = grammar::Word{node_type};
      node.number = grammar::Integer{static_cast<std::int64_t>(k + 1)};
      for (int c = 0; c < dimension; ++c) {
        const auto i =
            static_cast<Eigen::Index>(k * static_cast<std::size_t>(dimension) + static_cast<std::size_t>(c));
        node.x.push_back(grammar::Real{d.states[m].x(i)});
        node.v.push_back(grammar::Real{d.states[m].v(i)});
      }
      body.nodes.push_back(std::move(node));
    }
    mailx.bodies.push_back(std::move(body));
  }
  file.sections.push_back(std::move(mailx));
  // With MAILx bodies a second dashed line follows (LMGC90's DOF files of 4cubes and of a MAILx-only
  // case end so; a rigid-only file has one).
  if (!d.empty()) file.sections.push_back(grammar::DofSection{{}, true});
  return file;
}

namespace {}  // namespace

grammar::VlocRlocFile vloc_rloc_file_2d(const Scene2D& scene, const RunState2D& state) {
  using grammar::Integer;
  using grammar::Real;
  using grammar::Word;
  grammar::VlocRlocFile file;
  file.step = Integer{state.step};
  file.time = Real{state.time};
  const double h = state.h;
  // Serial index of each contactor within the contactors of its type (LMGC90's module lists).
  std::vector<std::int64_t> serial(scene.contactors.size(), 0);
  std::map<std::string, std::int64_t> per_type;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k) serial[k] = ++per_type[scene.contactors[k].type];
  // Modules in the alphabetical order of LMGC90's writer; inside one, by candidate contactor
  // (PLPLx: in detection order).
  constexpr PairFamily2D kWriteOrder[] = {
      PairFamily2D::CLALp, PairFamily2D::CLJCx, PairFamily2D::DKALp, PairFamily2D::DKDKL, PairFamily2D::DKDKx,
      PairFamily2D::DKJCx, PairFamily2D::DKKDx, PairFamily2D::DKPLx, PairFamily2D::P2P2L, PairFamily2D::PLALp,
      PairFamily2D::PLJCx, PairFamily2D::PLPLx, PairFamily2D::PTPT2};
  // Mesh contactors (CLxxx, ALpxx) by their MAILx body, rank in it and serial among their type.
  const std::vector<MeshContactor>& mesh_tactors = scene.deformable.meshes.contactors;
  const auto mesh_body = [&](std::int32_t t) {
    return Integer{mesh_tactors[static_cast<std::size_t>(t)].mesh + 1};
  };
  const auto mesh_rank = [&](std::int32_t t) {
    return Integer{mesh_tactors[static_cast<std::size_t>(t)].rank};
  };
  for (PairFamily2D family : kWriteOrder) {
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < state.contacts.size(); ++k)
      if (state.contacts[k].family == family) members.push_back(k);
    if (members.empty()) continue;
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(pair_family_name(family));
    std::map<std::int32_t, std::int64_t> adjacency;  // running count per candidate contactor
    std::vector<std::int64_t> iadj(members.size());
    for (std::size_t m = 0; m < members.size(); ++m)
      iadj[m] = ++adjacency[state.contacts[members[m]].candidate];
    std::vector<std::size_t> order(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) order[m] = m;
    if (family != PairFamily2D::PLPLx)
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return state.contacts[members[a]].candidate < state.contacts[members[b]].candidate;
      });
    for (std::size_t m : order) {
      const Interaction2D& c = state.contacts[members[m]];
      // The rigid contactors of the pair (a mesh side reads mesh_tactors instead).
      static const Contactor2D kNone;
      const Contactor2D& cd =
          side_on_mesh(family, 0) ? kNone : scene.contactors[static_cast<std::size_t>(c.candidate)];
      const Contactor2D& an =
          side_on_mesh(family, 1) ? kNone : scene.contactors[static_cast<std::size_t>(c.antagonist)];
      const std::string& law = scene.laws[static_cast<std::size_t>(c.law)].nickname;
      grammar::VlocRlocInteraction out;
      out.type = Word{std::string(kind->type)};
      out.number = Integer{static_cast<std::int64_t>(m + 1)};
      out.title = std::string(kind->title);
      const std::string status(status_name(c.status));
      const Integer cd_body{cd.body + 1}, cd_rank{cd.rank}, an_body{an.body + 1}, an_rank{an.rank};
      switch (family) {
        case PairFamily2D::CLALp:
          // mailx-2d-contact.md §9: ALpxx rank in its body, the segment, the ALpxx's serial.
          out.words = {Word{"MAILx"}, Word{"CLxxx"}, Word{law}, Word{"MAILx"}, Word{"ALpxx"}, Word{status}};
          out.integers = {mesh_body(c.candidate),
                          mesh_rank(c.candidate),
                          mesh_body(c.antagonist),
                          mesh_rank(c.antagonist),
                          Integer{c.antagonist_segment},
                          Integer{mesh_tactors[static_cast<std::size_t>(c.antagonist)].serial}};
          break;
        case PairFamily2D::CLJCx:
          out.words = {Word{"MAILx"}, Word{"CLxxx"}, Word{law}, Word{"RBDY2"}, Word{an.type}, Word{status}};
          out.integers = {mesh_body(c.candidate), mesh_rank(c.candidate), an_body, an_rank,
                          Integer{serial[static_cast<std::size_t>(c.antagonist)]}};
          break;
        case PairFamily2D::DKALp:
          // mod_DKALp write_out_Vloc_Rloc: the ALpxx's rank in its body, the segment, the rank of the
          // contact among its disk's.
          out.words = {Word{"RBDY2"}, Word{"DISKx"}, Word{law}, Word{"MAILx"}, Word{"ALpxx"}, Word{status}};
          out.integers = {cd_body,
                          cd_rank,
                          mesh_body(c.antagonist),
                          mesh_rank(c.antagonist),
                          Integer{c.antagonist_segment},
                          Integer{iadj[m]}};
          break;
        case PairFamily2D::P2P2L:
          // mod_P2P2L write_out_Vloc_Rloc: each point's body and rank in it; the last column (titled
          // iadj) the antagonist's serial among the PT2DL.
          out.words = {Word{"MAILx"}, Word{"PT2DL"}, Word{law}, Word{"MAILx"}, Word{"PT2DL"}, Word{status}};
          out.integers = {mesh_body(c.candidate), mesh_rank(c.candidate), mesh_body(c.antagonist),
                          mesh_rank(c.antagonist),
                          Integer{mesh_tactors[static_cast<std::size_t>(c.antagonist)].serial}};
          break;
        case PairFamily2D::DKDKL:
          // mod_DKDKL write_out_Vloc_Rloc: the last column the DISKL's serial.
          out.words = {Word{"RBDY2"}, Word{"DISKx"}, Word{law}, Word{"MAILx"}, Word{"DISKL"}, Word{status}};
          out.integers = {cd_body, cd_rank, mesh_body(c.antagonist), mesh_rank(c.antagonist),
                          Integer{mesh_tactors[static_cast<std::size_t>(c.antagonist)].serial}};
          break;
        case PairFamily2D::PLALp:
          out.words = {Word{"RBDY2"}, Word{cd.type}, Word{"CDVER"}, Word{law},
                       Word{"MAILx"}, Word{"ALpxx"}, Word{status}};
          out.integers = {cd_body,
                          cd_rank,
                          Integer{c.candidate_vertex},
                          mesh_body(c.antagonist),
                          mesh_rank(c.antagonist),
                          Integer{c.antagonist_segment},
                          Integer{iadj[m]}};
          break;
        case PairFamily2D::PLJCx:
          out.words = {Word{"RBDY2"}, Word{cd.type}, Word{"CDVER"}, Word{law},
                       Word{"RBDY2"}, Word{an.type}, Word{status}};
          out.integers = {cd_body, cd_rank, Integer{c.candidate_vertex}, an_body, an_rank, Integer{iadj[m]}};
          break;
        case PairFamily2D::PLPLx:
          out.words = {Word{"RBDY2"}, Word{cd.type}, Word{"CDVER"}, Word{law},
                       Word{"RBDY2"}, Word{an.type}, Word{"ANSEG"}, Word{status}};
          out.integers = {cd_body,
                          cd_rank,
                          Integer{c.candidate_vertex},
                          an_body,
                          an_rank,
                          Integer{c.antagonist_segment},
                          Integer{serial[static_cast<std::size_t>(c.antagonist)]}};
          break;
        case PairFamily2D::DKPLx:
          out.words = {Word{"RBDY2"}, Word{"DISKx"}, Word{law},   Word{"RBDY2"},
                       Word{an.type}, Word{"CDVER"}, Word{status}};
          out.integers = {cd_body, cd_rank, an_body, an_rank, Integer{0}, Integer{iadj[m]}};
          break;
        default:
          out.words = {Word{"RBDY2"}, Word{cd.type}, Word{law}, Word{"RBDY2"}, Word{an.type}, Word{status}};
          out.integers = {cd_body, cd_rank, an_body, an_rank,
                          Integer{serial[static_cast<std::size_t>(c.antagonist)]}};
      }
      const double gap_end = c.gap_begin + h * c.u(1);
      // The written point of disk modules is the candidate's surface point (rigid-2d.md §3.4).
      const bool disk =
          family == PairFamily2D::DKDKx || family == PairFamily2D::DKJCx || family == PairFamily2D::DKKDx;
      const Eigen::Vector2d point = disk ? Eigen::Vector2d(c.point + 0.5 * c.gap_begin * c.normal) : c.point;
      for (const grammar::VectorLineKind& line : kind->vectors) {
        grammar::VlocRlocVector v;
        for (int k = 0; k < line.count; ++k) v.labels.emplace_back(line.labels[k]);
        const std::string first(line.labels[0]);
        if (first.rfind("rl", 0) == 0)
          v.values = {Real{c.r(0) / h}, Real{c.r(1) / h}, Real{0.0}};
        else if (first.rfind("vl", 0) == 0)
          v.values = {Real{c.u(0)}, Real{c.u(1)}, Real{0.0}};
        else if (first == "gapTT" || first == "gap =")
          v.values = {Real{gap_end}};
        else if (first == "n(1)=")
          v.values = {Real{c.normal.x()}, Real{c.normal.y()}, Real{0.0}};
        else
          v.values = {Real{point.x()}, Real{point.y()}, Real{0.0}};
        out.vectors.push_back(std::move(v));
      }
      const int internals = law_internal_count(scene.laws[static_cast<std::size_t>(c.law)].law);
      if (internals > 0) {
        std::vector<Real> values;
        // A law with internals keeps a law state per interaction (keeps_law_state_2d).
        const LawState2D none;
        const auto& internal = (state.law_states.empty() ? none : state.law_states[members[m]]).internal;
        for (int k = 0; k < internals; ++k) values.push_back(Real{internal[static_cast<std::size_t>(k)]});
        const std::size_t per_line = kind->internals == grammar::InternalLayout2D::per_line_6 ? 6
                                     : kind->internals == grammar::InternalLayout2D::per_line_5
                                         ? 5
                                         : values.size();
        if (kind->internals == grammar::InternalLayout2D::one_line_with_comment)
          if (const grammar::LawKind* kind =
                  grammar::find_law_kind(law_keyword(scene.laws[static_cast<std::size_t>(c.law)].law)))
            out.internal_comment = grammar::internal_variables_comment(kind->internals_2d);
        for (std::size_t k = 0; k < values.size(); k += per_line)
          out.internal_lines.emplace_back(
              values.begin() + static_cast<std::ptrdiff_t>(k),
              values.begin() + static_cast<std::ptrdiff_t>(std::min(values.size(), k + per_line)));
      }
      file.interactions.push_back(std::move(out));
    }
  }
  return file;
}

WarmStart2D warm_start_2d(const grammar::VlocRlocFile& file, const Scene2D& scene, double h) {
  // Contactor index by (body rank, contactor rank).
  std::map<std::pair<std::int64_t, std::int64_t>, std::int32_t> by_rank;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k)
    by_rank[{scene.contactors[k].body + 1, scene.contactors[k].rank}] = static_cast<std::int32_t>(k);
  // Mesh contactors by (MAILx body, rank in it).
  std::map<std::pair<std::int64_t, std::int64_t>, std::int32_t> by_mesh_rank;
  const std::vector<MeshContactor>& mesh_tactors = scene.deformable.meshes.contactors;
  for (std::size_t k = 0; k < mesh_tactors.size(); ++k)
    by_mesh_rank[{mesh_tactors[k].mesh + 1, mesh_tactors[k].rank}] = static_cast<std::int32_t>(k);
  std::vector<std::pair<Interaction2D, LawState2D>> previous;
  for (const auto& b : file.interactions) {
    PairFamily2D family;
    const std::string& t = b.type.value;
    if (t == "DKDKx")
      family = PairFamily2D::DKDKx;
    else if (t == "DKJCx")
      family = PairFamily2D::DKJCx;
    else if (t == "DKKDx")
      family = PairFamily2D::DKKDx;
    else if (t == "DKPLx")
      family = PairFamily2D::DKPLx;
    else if (t == "PLJCx")
      family = PairFamily2D::PLJCx;
    else if (t == "PLPLx")
      family = PairFamily2D::PLPLx;
    else if (t == "PTPT2")
      family = PairFamily2D::PTPT2;
    else if (t == "CLALp")
      family = PairFamily2D::CLALp;
    else if (t == "CLJCx")
      family = PairFamily2D::CLJCx;
    else if (t == "PLALp")
      family = PairFamily2D::PLALp;
    else if (t == "DKALp")
      family = PairFamily2D::DKALp;
    else if (t == "P2P2L")
      family = PairFamily2D::P2P2L;
    else if (t == "DKDKL")
      family = PairFamily2D::DKDKL;
    else
      continue;
    const bool vertex =
        family == PairFamily2D::PLJCx || family == PairFamily2D::PLPLx || family == PairFamily2D::PLALp;
    const auto& n = b.integers;
    if (n.size() < 5 || b.vectors.empty() || b.vectors[0].values.size() < 2) continue;
    const std::size_t an_at = vertex ? 3 : 2;
    const auto& cd_ranks = side_on_mesh(family, 0) ? by_mesh_rank : by_rank;
    const auto& an_ranks = side_on_mesh(family, 1) ? by_mesh_rank : by_rank;
    auto cd = cd_ranks.find({n[0].value, n[1].value});
    auto an = an_ranks.find({n[an_at].value, n[an_at + 1].value});
    if (cd == cd_ranks.end() || an == an_ranks.end()) continue;
    Interaction2D c;
    c.family = family;
    c.candidate = cd->second;
    c.antagonist = an->second;
    c.candidate_vertex = vertex ? static_cast<std::int32_t>(n[2].value) : 0;
    if (family == PairFamily2D::DKALp) c.antagonist_segment = static_cast<std::int32_t>(n[4].value);
    c.r = Eigen::Vector2d(b.vectors[0].values[0].value * h, b.vectors[0].values[1].value * h);
    if (!b.words.empty()) status_from_name(b.words.back().value, c.status);
    LawState2D law_state;
    std::size_t k = 0;
    for (const auto& line : b.internal_lines)
      for (const auto& v : line)
        if (k < law_state.internal.size()) law_state.internal[k++] = v.value;
    previous.emplace_back(c, law_state);
  }
  std::stable_sort(previous.begin(), previous.end(), [](const auto& x, const auto& y) {
    const Interaction2D &a = x.first, &b = y.first;
    return std::tie(a.family, a.candidate, a.antagonist, a.candidate_vertex) <
           std::tie(b.family, b.candidate, b.antagonist, b.candidate_vertex);
  });
  WarmStart2D warm;
  for (const auto& [c, law_state] : previous) {
    warm.interactions.push_back(c);
    warm.law_states.push_back(law_state);
  }
  return warm;
}

}  // namespace lmgc::solver
