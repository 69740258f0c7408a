#include "solver/io/display_2d.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grammar/common/output_file.hpp"
#include "solver/io/mesh_gauss_values.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr int kArcSegments = 24;  // segments of a disk outline or of a JONCx rounded end

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// Outline of a contactor in the world frame at the end of the step.
std::vector<Vector2d> outline(const Scene2D& scene, const Contactor2D& c) {
  const RigidBodies2D& b = scene.bodies;
  const auto i = static_cast<std::size_t>(c.body);
  const Vector3d q = b.reference[i] + b.displacement[i];
  const Eigen::Matrix2d R = rotation(q.z());
  const Vector2d centre = q.head<2>() + R * c.shift;
  std::vector<Vector2d> points;
  switch (c.shape) {
    case ContactorShape2D::disk:
    case ContactorShape2D::hollow_disk:
      for (int k = 0; k < kArcSegments; ++k) {
        const double a = 2.0 * M_PI * k / kArcSegments;
        points.push_back(centre + c.radius * Vector2d(std::cos(a), std::sin(a)));
      }
      break;
    case ContactorShape2D::joncx:
      for (int end = 0; end < 2; ++end)
        for (int k = 0; k <= kArcSegments / 2; ++k) {
          const double a = -M_PI / 2 + M_PI * end + M_PI * k / (kArcSegments / 2);
          const Vector2d local((end == 0 ? c.half_length : -c.half_length) + c.half_width * std::cos(a),
                               c.half_width * std::sin(a));
          points.push_back(centre + R * local);
        }
      break;
    case ContactorShape2D::polygon:
      for (std::int32_t k = 0; k < c.vertex_count; ++k)
        points.push_back(centre + R * scene.vertices[static_cast<std::size_t>(c.first_vertex + k)]);
      break;
    case ContactorShape2D::point:
      points.push_back(centre);
      break;
  }
  return points;
}

template <class F>
void data_array(std::string& out, const char* type, const char* name, int components, std::size_t n,
                F value) {
  out +=
      fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                  type, name, components);
  for (std::size_t i = 0; i < n; ++i) {
    out += "         ";
    for (int c = 0; c < components; ++c) out += fmt::format(" {}", value(i, c));
    out += '\n';
  }
  out += "        </DataArray>\n";
}

}  // namespace

std::string bodies_vtu_2d(const Scene2D& scene) {
  std::vector<std::vector<Vector2d>> cells;
  for (const Contactor2D& c : scene.contactors) cells.push_back(outline(scene, c));
  std::size_t points = 0;
  for (const auto& cell : cells) points += cell.size();
  std::string out;
  out +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n";
  out += fmt::format("  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", points,
                     cells.size());
  out += "      <Points>\n";
  std::vector<Vector2d> all;
  all.reserve(points);
  for (const auto& cell : cells) all.insert(all.end(), cell.begin(), cell.end());
  data_array(out, "Float64", "Points", 3, all.size(),
             [&](std::size_t i, int c) { return c < 2 ? all[i](c) : 0.0; });
  out += "      </Points>\n      <Cells>\n";
  std::size_t offset = 0;
  std::vector<std::size_t> offsets;
  for (const auto& cell : cells) offsets.push_back(offset += cell.size());
  data_array(out, "Int64", "connectivity", 1, points,
             [](std::size_t i, int) { return static_cast<long long>(i); });
  data_array(out, "Int64", "offsets", 1, cells.size(),
             [&](std::size_t i, int) { return static_cast<long long>(offsets[i]); });
  // VTK_POLYGON = 7, VTK_VERTEX = 1.
  data_array(out, "UInt8", "types", 1, cells.size(),
             [&](std::size_t i, int) { return cells[i].size() > 1 ? 7 : 1; });
  out += "      </Cells>\n      <CellData>\n";
  const RigidBodies2D& b = scene.bodies;
  auto body = [&](std::size_t cell) { return static_cast<std::size_t>(scene.contactors[cell].body); };
  data_array(out, "Int32", "Ids", 1, cells.size(),
             [&](std::size_t i, int) { return static_cast<int>(body(i)) + 1; });
  data_array(out, "Float64", "Disp", 3, cells.size(),
             [&](std::size_t i, int c) { return b.displacement[body(i)](c); });
  data_array(out, "Float64", "Velocy", 3, cells.size(),
             [&](std::size_t i, int c) { return b.velocity[body(i)](c); });
  data_array(out, "Int32", "Visible", 1, cells.size(),
             [&](std::size_t i, int) { return static_cast<int>(b.visible[body(i)]); });
  out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string contacts_vtu_2d(const Scene2D& scene, const RunState2D& state) {
  const auto& contacts = state.contacts;
  const std::size_t n = contacts.size();
  const double h = state.h;
  std::string out;
  out +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n";
  out += fmt::format("  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n);
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, n,
             [&](std::size_t i, int c) { return c < 2 ? contacts[i].point(c) : 0.0; });
  out += "      </Points>\n      <Cells>\n";
  data_array(out, "Int64", "connectivity", 1, n,
             [](std::size_t i, int) { return static_cast<long long>(i); });
  data_array(out, "Int64", "offsets", 1, n, [](std::size_t i, int) { return static_cast<long long>(i + 1); });
  data_array(out, "UInt8", "types", 1, n, [](std::size_t, int) { return 1; });
  out += "      </Cells>\n      <PointData>\n";
  data_array(out, "Float64", "N", 3, n,
             [&](std::size_t i, int c) { return c < 2 ? contacts[i].normal(c) : 0.0; });
  data_array(out, "Float64", "T", 3, n,
             [&](std::size_t i, int c) { return c < 2 ? contacts[i].tangent()(c) : 0.0; });
  // Global reaction force r_t t + r_n n divided by h.
  data_array(out, "Float64", "R", 3, n, [&](std::size_t i, int c) {
    const Interaction2D& k = contacts[i];
    return c < 2 ? (k.r(0) * k.tangent()(c) + k.r(1) * k.normal(c)) / h : 0.0;
  });
  data_array(out, "Float64", "rln", 1, n, [&](std::size_t i, int) { return contacts[i].r(1) / h; });
  data_array(out, "Float64", "rlt", 1, n, [&](std::size_t i, int) { return contacts[i].r(0) / h; });
  data_array(out, "Float64", "gap", 1, n,
             [&](std::size_t i, int) { return contacts[i].gap_begin + h * contacts[i].u(1); });
  data_array(out, "Int32", "status", 1, n,
             [&](std::size_t i, int) { return static_cast<int>(contacts[i].status); });
  data_array(out, "Int32", "cdbdy", 1, n, [&](std::size_t i, int) { return contacts[i].candidate_body + 1; });
  data_array(out, "Int32", "anbdy", 1, n,
             [&](std::size_t i, int) { return contacts[i].antagonist_body + 1; });
  out += "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  (void)scene;
  return out;
}

std::string meshes_vtu_2d(const Scene2D& scene) {
  const DeformableBodies& d = scene.deformable;
  struct NodeRef {
    std::size_t body, node;
  };
  std::vector<NodeRef> nodes;
  std::vector<std::size_t> first_node;  // per body, its first point
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    first_node.push_back(nodes.size());
    for (std::size_t k = 0; k < d.meshes.bodies[b].nodes(); ++k) nodes.push_back({b, k});
  }
  // Nodal tensors: the mean of the element means around each node (LMGC90 fits them by least
  // squares, mailx-2d.md §5: the same on a uniform field).
  std::vector<Eigen::Matrix3d> strain(nodes.size(), Eigen::Matrix3d::Zero()),
      stress(nodes.size(), Eigen::Matrix3d::Zero());
  std::vector<int> around(nodes.size(), 0);
  std::vector<std::pair<std::size_t, std::size_t>> cells;  // (body, element)
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    const fem::MeshBody& mesh = d.meshes.bodies[b];
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      cells.emplace_back(b, e);
      Eigen::Vector4d eps, sig;
      element_mean_strain_stress(mesh, d.states[b].x, e, eps, sig);
      Eigen::Matrix3d te, ts;
      te << eps(0), 0.5 * eps(2), 0, 0.5 * eps(2), eps(1), 0, 0, 0, eps(3);
      ts << sig(0), sig(2), 0, sig(2), sig(1), 0, 0, 0, sig(3);
      const int count = fem::element_entry(mesh.elements[e].kind).nodes;
      for (int k = 0; k < count; ++k) {
        const std::size_t p =
            first_node[b] + static_cast<std::size_t>(mesh.elements[e].nodes[static_cast<std::size_t>(k)]);
        strain[p] += te;
        stress[p] += ts;
        ++around[p];
      }
    }
  }
  for (std::size_t p = 0; p < nodes.size(); ++p)
    if (around[p] > 0) {
      strain[p] /= around[p];
      stress[p] /= around[p];
    }
  const auto x = [&](std::size_t p, int c) {
    const auto& [b, k] = nodes[p];
    return d.states[b].x(static_cast<Eigen::Index>(2 * k + static_cast<std::size_t>(c)));
  };
  std::string out;
  out +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n";
  out += fmt::format("  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                     nodes.size(), cells.size());
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, nodes.size(), [&](std::size_t p, int c) {
    const auto& [b, k] = nodes[p];
    return c < 2 ? d.meshes.bodies[b].coordinates[2 * k + static_cast<std::size_t>(c)] + x(p, c) : 0.0;
  });
  out += "      </Points>\n      <Cells>\n";
  std::vector<long long> connectivity, offsets;
  std::vector<int> types;
  for (const auto& [b, e] : cells) {
    const fem::MeshElement& element = d.meshes.bodies[b].elements[e];
    const int count = fem::element_entry(element.kind).nodes;
    for (int k = 0; k < count; ++k)
      connectivity.push_back(static_cast<long long>(first_node[b]) +
                             element.nodes[static_cast<std::size_t>(k)]);
    offsets.push_back(static_cast<long long>(connectivity.size()));
    // VTK_TRIANGLE 5, VTK_QUAD 9, VTK_QUADRATIC_TRIANGLE 22, VTK_QUADRATIC_QUAD 23 (LMGC90's node orders).
    types.push_back(element.kind == fem::ElementKind::T3                                             ? 5
                    : element.kind == fem::ElementKind::Q4 || element.kind == fem::ElementKind::Q4P0 ? 9
                    : element.kind == fem::ElementKind::T6                                           ? 22
                                                                                                     : 23);
  }
  data_array(out, "Int64", "connectivity", 1, connectivity.size(),
             [&](std::size_t i, int) { return connectivity[i]; });
  data_array(out, "Int64", "offsets", 1, offsets.size(), [&](std::size_t i, int) { return offsets[i]; });
  data_array(out, "UInt8", "types", 1, types.size(), [&](std::size_t i, int) { return types[i]; });
  out += "      </Cells>\n      <PointData>\n";
  data_array(out, "Int32", "Ids", 1, nodes.size(),
             [&](std::size_t p, int) { return static_cast<int>(nodes[p].body) + 1; });
  data_array(out, "Int32", "Node Id", 1, nodes.size(),
             [&](std::size_t p, int) { return static_cast<int>(nodes[p].node) + 1; });
  data_array(out, "Float64", "Disp", 3, nodes.size(),
             [&](std::size_t p, int c) { return c < 2 ? x(p, c) : 0.0; });
  data_array(out, "Float64", "Velocy", 3, nodes.size(), [&](std::size_t p, int c) {
    const auto& [b, k] = nodes[p];
    return c < 2 ? d.states[b].v(static_cast<Eigen::Index>(2 * k + static_cast<std::size_t>(c))) : 0.0;
  });
  data_array(out, "Float64", "E", 9, nodes.size(),
             [&](std::size_t p, int c) { return strain[p](c / 3, c % 3); });
  data_array(out, "Float64", "S", 9, nodes.size(),
             [&](std::size_t p, int c) { return stress[p](c / 3, c % 3); });
  data_array(out, "Float64", "Svm", 1, nodes.size(), [&](std::size_t p, int) {
    const Eigen::Matrix3d dev = stress[p] - stress[p].trace() / 3.0 * Eigen::Matrix3d::Identity();
    return std::sqrt(1.5 * (dev.array() * dev.array()).sum());
  });
  data_array(out, "Float64", "Fext", 3, nodes.size(), [&](std::size_t p, int c) {
    const auto& [b, k] = nodes[p];
    return c < 2 ? d.states[b].f_ext(static_cast<Eigen::Index>(2 * k + static_cast<std::size_t>(c))) : 0.0;
  });
  out += "      </PointData>\n      <CellData>\n";
  data_array(out, "Int32", "Element Id", 1, cells.size(),
             [&](std::size_t i, int) { return static_cast<int>(cells[i].second) + 1; });
  out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

bool DisplayWriter2D::write(const Scene2D& scene, const RunState2D& state, std::string& error) {
  const std::size_t k = times_.size() + 1;
  if (!grammar::write_file_whole(dir_ / fmt::format("bodies_{}.vtu", k), bodies_vtu_2d(scene), error))
    return false;
  if (!grammar::write_file_whole(dir_ / fmt::format("contacts_{}.vtu", k), contacts_vtu_2d(scene, state),
                                 error))
    return false;
  const bool meshes = !scene.deformable.empty();
  if (meshes &&
      !grammar::write_file_whole(dir_ / fmt::format("meshes_{}.vtu", k), meshes_vtu_2d(scene), error))
    return false;
  times_.push_back(state.time);
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (std::size_t i = 0; i < times_.size(); ++i) {
    pvd += fmt::format("    <DataSet timestep=\"{:.10g}\" group=\"\" part=\"0\" file=\"bodies_{}.vtu\"/>\n",
                       times_[i], i + 1);
    pvd += fmt::format("    <DataSet timestep=\"{:.10g}\" group=\"\" part=\"1\" file=\"contacts_{}.vtu\"/>\n",
                       times_[i], i + 1);
    if (meshes)
      pvd += fmt::format("    <DataSet timestep=\"{:.10g}\" group=\"\" part=\"2\" file=\"meshes_{}.vtu\"/>\n",
                         times_[i], i + 1);
  }
  pvd += "  </Collection>\n</VTKFile>\n";
  return grammar::write_file_whole(dir_ / "lmgc90.pvd", pvd, error);
}

}  // namespace lmgc::solver
