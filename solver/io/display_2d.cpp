#include "solver/io/display_2d.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grammar/common/output_file.hpp"

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

bool DisplayWriter2D::write(const Scene2D& scene, const RunState2D& state, std::string& error) {
  const std::size_t k = times_.size() + 1;
  if (!grammar::write_file_whole(dir_ / fmt::format("bodies_{}.vtu", k), bodies_vtu_2d(scene), error))
    return false;
  if (!grammar::write_file_whole(dir_ / fmt::format("contacts_{}.vtu", k), contacts_vtu_2d(scene, state),
                                 error))
    return false;
  times_.push_back(state.time);
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (std::size_t i = 0; i < times_.size(); ++i) {
    pvd += fmt::format("    <DataSet timestep=\"{:.10g}\" group=\"\" part=\"0\" file=\"bodies_{}.vtu\"/>\n",
                       times_[i], i + 1);
    pvd += fmt::format("    <DataSet timestep=\"{:.10g}\" group=\"\" part=\"1\" file=\"contacts_{}.vtu\"/>\n",
                       times_[i], i + 1);
  }
  pvd += "  </Collection>\n</VTKFile>\n";
  return grammar::write_file_whole(dir_ / "lmgc90.pvd", pvd, error);
}

}  // namespace lmgc::solver
