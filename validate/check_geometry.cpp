// Physical sanity of BODIES.DAT: sizes, polygon orientation and simplicity, closed polyhedra,
// finite elements with positive Jacobian. docs/lmgc90-facts/datbox-inputs.md §1.4-1.5.
#include <fmt/format.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "validate/case_index.hpp"
#include "validate/checks.hpp"

namespace lmgc::validate {
namespace {

using grammar::Body;
using grammar::Contactor;
using grammar::Real;

struct Reporter {
  grammar::DiagnosticSink& sink;
  std::string file;
  void operator()(std::string_view code, grammar::SourceSpan span, std::string message,
                  std::string hint = {}) {
    sink.report(code, grammar::Location{file, span}, std::move(message), std::move(hint));
  }
};

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c),
               d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

void check_polygon(const Contactor& c, const std::string& owner, Reporter& report) {
  const std::size_t n = c.vertices.size();
  std::vector<Eigen::Vector2d> v;
  for (const auto& p : c.vertices) v.emplace_back(p[0].value, p[1].value);
  if (n < 3) {
    report("L3009", c.type.span,
           fmt::format("polygon of {} has {} vertices; at least 3 are needed", owner, n));
    return;
  }
  double area2 = 0.0;
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    area2 += cross(v[i], v[(i + 1) % n]);
    scale = std::max(scale, (v[i] - v[(i + 1) % n]).norm());
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) {
        report("L3009", c.vertices[j][0].span,
               fmt::format("polygon of {} is not simple: edges {} and {} cross", owner, i + 1, j + 1));
        return;
      }
    }
  if (std::fabs(area2) <= 1e-12 * scale * scale) {
    report("L3009", c.type.span, fmt::format("polygon of {} is degenerate (zero area)", owner));
  } else if (area2 < 0.0) {
    report(
        "L3009", c.type.span,
        fmt::format("polygon of {} is clockwise; LMGC90 requires counter-clockwise vertices (it stops on a "
                    "negative area)",
                    owner),
        "list the vertices in the reverse order");
  }
}

// LMGC90 orients the faces of a POLYR itself (set_orientation_surface_T3) and turns them all
// over when the volume comes out negative (mod_DiscreteGeometry.f90), so the order of a face's
// vertices does not matter; what it cannot repair is a surface that is not closed (an edge not
// shared by exactly two faces), a degenerate face or a face naming a missing vertex.
void check_polyhedron(const Contactor& c, const std::string& owner, Reporter& report) {
  const std::size_t nv = c.vertices.size();
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : c.vertices) v.emplace_back(p[0].value, p[1].value, p[2].value);
  std::map<std::pair<std::int64_t, std::int64_t>, int> edges;  // undirected: (smaller, larger)
  for (const auto& f : c.faces) {
    std::array<std::int64_t, 3> id{f[0].value, f[1].value, f[2].value};
    bool valid = true;
    for (auto k : id)
      if (k < 1 || k > static_cast<std::int64_t>(nv)) valid = false;
    if (!valid) {
      report("L3010", f[0].span, fmt::format("face of {} names a vertex outside 1..{}", owner, nv));
      return;
    }
    const Eigen::Vector3d& a = v[static_cast<std::size_t>(id[0] - 1)];
    const Eigen::Vector3d& b = v[static_cast<std::size_t>(id[1] - 1)];
    const Eigen::Vector3d& d = v[static_cast<std::size_t>(id[2] - 1)];
    if ((b - a).cross(d - a).norm() <= 1e-14 * std::max(1.0, (b - a).squaredNorm())) {
      report("L3010", f[0].span,
             fmt::format("face ({}, {}, {}) of {} has zero area", id[0], id[1], id[2], owner));
      return;
    }
    for (int k = 0; k < 3; ++k) {
      const std::int64_t p = id[static_cast<std::size_t>(k)], q = id[static_cast<std::size_t>((k + 1) % 3)];
      ++edges[{std::min(p, q), std::max(p, q)}];
    }
  }
  for (const auto& [edge, count] : edges) {
    if (count != 2) {
      report(
          "L3010", c.type.span,
          fmt::format("polyhedron of {} is not a closed surface: edge {}-{} belongs to {} face{} (2 needed)",
                      owner, edge.first, edge.second, count, count == 1 ? "" : "s"));
      return;
    }
  }
}

// Jacobian of linear elements at their nodes: the signed area (2D) or volume (3D).
void check_element(const Body& body, const grammar::Element& e, const std::string& owner, Reporter& report) {
  const std::string& type = e.type.value;
  auto node = [&](std::size_t k) -> const grammar::Node* {
    const std::int64_t id = e.nodes[k].value;
    if (id < 1 || id > static_cast<std::int64_t>(body.nodes.size())) return nullptr;
    return &body.nodes[static_cast<std::size_t>(id - 1)];
  };
  auto xy = [](const grammar::Node* n) {
    return Eigen::Vector2d(n->coordinates.size() > 0 ? n->coordinates[0].value : 0.0,
                           n->coordinates.size() > 1 ? n->coordinates[1].value : 0.0);
  };
  if (type == "T3xxx" || type == "Q4xxx") {
    const std::size_t m = type == "T3xxx" ? 3 : 4;
    if (e.nodes.size() < m) return;
    for (std::size_t k = 0; k < m; ++k) {
      const grammar::Node* a = node(k);
      const grammar::Node* b = node((k + 1) % m);
      const grammar::Node* c = node((k + m - 1) % m);
      if (!a || !b || !c) return;  // reported by the reference checks
      const double jacobian = cross(xy(b) - xy(a), xy(c) - xy(a));
      if (jacobian <= 0.0) {
        report("L3011", e.type.span,
               fmt::format("element {} {} of {} has a non-positive Jacobian at its node {} (nodes must turn "
                           "counter-clockwise)",
                           type, &e - body.elements.data() + 1, owner, e.nodes[k].value));
        return;
      }
    }
  } else if (type == "TE4xx") {
    if (e.nodes.size() < 4) return;
    std::array<Eigen::Vector3d, 4> p;
    for (std::size_t k = 0; k < 4; ++k) {
      const grammar::Node* n = node(k);
      if (!n || n->coordinates.size() < 3) return;
      p[k] = Eigen::Vector3d(n->coordinates[0].value, n->coordinates[1].value, n->coordinates[2].value);
    }
    if ((p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) <= 0.0)
      report("L3011", e.type.span,
             fmt::format("element TE4xx {} of {} has a non-positive Jacobian", &e - body.elements.data() + 1,
                         owner));
  }
}

}  // namespace

// log10 of the largest ρ s^(d+2) a body may have (its inertia, before the other factors).
constexpr double kInertiaLog10Limit = 290.0;

void check_geometry(const CaseFiles& files, grammar::DiagnosticSink& sink) {
  if (!files.bodies) return;
  Reporter report{sink, datbox_path(files, "BODIES.DAT")};
  std::size_t rank[3] = {0, 0, 0};
  for (const Body& body : files.bodies->bodies) {
    const std::string owner = body_name(body, ++rank[static_cast<int>(body.type)]);
    const int dimension = body.type == grammar::BodyType::rbdy3 ? 3 : 2;
    double density = 0.0;
    if (body.rigid_bulk && files.bulk_behav)
      grammar::bulk_density(*files.bulk_behav, body.rigid_bulk->behav.value, density);
    for (const Contactor& c : body.contactors) {
      const std::string& type = c.type.value;
      // Sizes: radius, half lengths and heights must be positive.
      const bool sized = type == "DISKx" || type == "DISKb" || type == "xKSID" || type == "SPHER" ||
                         type == "SPHEb" || type == "JONCx" || type == "CYLND" || type == "DNLYC" ||
                         type == "PLANx";
      if (sized) {
        const std::size_t count = type == "JONCx" || type == "CYLND" || type == "DNLYC" ? 2
                                  : type == "PLANx"                                     ? 3
                                                                                        : 1;
        for (std::size_t k = 0; k < count && k < c.values.size(); ++k) {
          if (!(c.values[k].value > 0.0))
            report("L3001", c.values[k].span,
                   fmt::format("{} size of contactor {} of {} is {}; it must be > 0", type,
                               &c - body.contactors.data() + 1, owner, c.values[k].value));
          // The body's moment of inertia grows as ρ s^(d+2): it must stay a double.
          else if (density > 0.0 &&
                   std::log10(density) + (dimension + 2) * std::log10(c.values[k].value) > kInertiaLog10Limit)
            report("L1003", c.values[k].span,
                   fmt::format(
                       "{} size {} of contactor {} of {} with density {} gives a mass and inertia beyond "
                       "double precision",
                       type, c.values[k].value, &c - body.contactors.data() + 1, owner, density));
        }
      }
      if (type == "POLYG") check_polygon(c, owner, report);
      if (type == "POLYR") check_polyhedron(c, owner, report);
    }
    if (body.rigid_bulk) {
      const auto& b = *body.rigid_bulk;
      if (b.avrd.value < 0.0)
        report("L3001", b.avrd.span,
               fmt::format("avrd of {} is {}; it must be >= 0 (0: computed)", owner, b.avrd.value));
      if (b.gyrd.value < 0.0)
        report("L3001", b.gyrd.span,
               fmt::format("gyrd of {} is {}; it must be >= 0 (0: computed)", owner, b.gyrd.value));
    }
    for (const auto& e : body.elements) check_element(body, e, owner, report);
    // A mesh's CLxxx and ALpxx segments need two distinct points (LMGC90 divides by their length).
    const auto node_position = [&](std::int64_t n) {
      std::array<double, 2> p{};
      if (n >= 1 && static_cast<std::size_t>(n) <= body.nodes.size())
        for (std::size_t k = 0; k < 2 && k < body.nodes[static_cast<std::size_t>(n - 1)].coordinates.size();
             ++k)
          p[k] = body.nodes[static_cast<std::size_t>(n - 1)].coordinates[k].value;
      return p;
    };
    for (const auto& c : body.contactors) {
      if (c.type.value != "CLxxx" && c.type.value != "ALpxx") continue;
      std::vector<const grammar::Integer*> chain;
      for (const auto& n : c.nodes) chain.push_back(&n);
      for (const auto& more : c.continuations)
        if (more.nodes.size() >= 2) chain.push_back(&more.nodes[1]);
      for (std::size_t k = 0; k + 1 < chain.size(); ++k)
        if (chain[k]->value == chain[k + 1]->value ||
            node_position(chain[k]->value) == node_position(chain[k + 1]->value))
          report("L3018", chain[k + 1]->span,
                 fmt::format("{} {} of {}: nodes {} and {} are one point", c.type.value,
                             &c - body.contactors.data() + 1, owner, chain[k]->value, chain[k + 1]->value));
      if (c.type.value == "CLxxx" && !c.values.empty() &&
          !(c.values[0].value >= 0.0 && c.values[0].value <= 1.0))
        report("L3018", c.values[0].span,
               fmt::format("CLxxx {} of {}: apab is {}; it must be in [0, 1]",
                           &c - body.contactors.data() + 1, owner, c.values[0].value));
    }
    // A PT2DL point lies on its edge; a DISKL's edge has two points and its arc a positive sagitta
    // (LMGC90 divides by |ab| and by bdyr: mod_DISKL get_radius_DISKL).
    for (const auto& c : body.contactors) {
      if (c.type.value != "PT2DL" && c.type.value != "DISKL") continue;
      const auto rank = &c - body.contactors.data() + 1;
      if (!c.values.empty() && !(c.values[0].value >= 0.0 && c.values[0].value <= 1.0))
        report("L3018", c.values[0].span,
               fmt::format("{} {} of {}: apab is {}; it must be in [0, 1]", c.type.value, rank, owner,
                           c.values[0].value));
      if (c.type.value != "DISKL") continue;
      if (c.nodes.size() >= 2 && (c.nodes[0].value == c.nodes[1].value ||
                                  node_position(c.nodes[0].value) == node_position(c.nodes[1].value)))
        report("L3018", c.nodes[1].span,
               fmt::format("DISKL {} of {}: nodes {} and {} are one point", rank, owner, c.nodes[0].value,
                           c.nodes[1].value));
      if (c.values.size() >= 2 && !(c.values[1].value > 0.0))
        report("L3018", c.values[1].span,
               fmt::format("DISKL {} of {}: bdyr (the arc's sagitta) is {}; it must be > 0", rank, owner,
                           c.values[1].value));
    }
    // Two elements on the same nodes: the mesh counts that matter twice (stiffness and mass).
    std::map<std::vector<std::int64_t>, std::size_t> seen;
    for (std::size_t k = 0; k < body.elements.size(); ++k) {
      std::vector<std::int64_t> nodes;
      for (const auto& n : body.elements[k].nodes) nodes.push_back(n.value);
      std::sort(nodes.begin(), nodes.end());
      const auto [it, fresh] = seen.emplace(nodes, k);
      if (!fresh)
        report("L3017", body.elements[k].type.span,
               fmt::format("element {} of {} has the nodes of element {}: the mesh counts them twice", k + 1,
                           owner, it->second + 1));
    }
  }
}

}  // namespace lmgc::validate
