#include "solver/io/display_3d.hpp"

#include <fmt/format.h>

#include "grammar/common/output_file.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr int kVtkVertex = 1;
constexpr int kVtkTriangle = 5;
constexpr int kVtkHexahedron = 12;

// The drawn points of every contactor at the end of the step, and which contactor owns each.
struct BodyPoints {
  std::vector<Vector3d> points;
  std::vector<std::size_t> owner;    // (points) contactor index
  std::vector<std::size_t> offsets;  // (cells) end of each cell's points
  std::vector<int> types;            // (cells) VTK cell type
};

BodyPoints body_points(const Scene3D& scene) {
  const RigidBodies3D& b = scene.bodies;
  BodyPoints out;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k) {
    const Contactor3D& c = scene.contactors[k];
    const auto i = static_cast<std::size_t>(c.body);
    const Vector3d centre = b.reference[i] + b.displacement[i].head<3>() + b.frame[i] * c.shift;
    if (c.shape == ContactorShape3D::sphere || c.shape == ContactorShape3D::point) {
      out.points.push_back(centre);  // a vertex (radius 0 for PT3Dx)
      out.owner.push_back(k);
      out.types.push_back(kVtkVertex);
    } else if (c.shape == ContactorShape3D::polyhedron) {
      // One triangle cell per face (its own three points: the connectivity is sequential).
      const Polyhedron& shape = scene.polyhedra[static_cast<std::size_t>(c.polyhedron)];
      for (const auto& face : shape.faces) {
        for (std::int32_t v : face) {
          out.points.push_back(centre + b.frame[i] * shape.vertices[static_cast<std::size_t>(v)]);
          out.owner.push_back(k);
        }
        out.types.push_back(kVtkTriangle);
        out.offsets.push_back(out.points.size());
      }
      continue;
    } else {
      // Box of half-axes (axe1, axe2, axe3) along the plane's world axes (a cylinder: its bounding
      // box (r, r, H) along its axes); VTK_HEXAHEDRON order: the face at -axe3 counter-clockwise
      // about +axe3, then the face at +axe3.
      const Matrix3d axes = b.frame[i] * c.local_frame;
      const Vector3d half = c.shape == ContactorShape3D::cylinder || c.shape == ContactorShape3D::tube
                                ? Vector3d(c.radius, c.radius, c.half_axes.z())
                                : Vector3d(c.half_axes);
      constexpr int kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
      for (const auto& s : kCorner) {
        const Vector3d local(s[0] * half(0), s[1] * half(1), s[2] * half(2));
        out.points.push_back(centre + axes * local);
        out.owner.push_back(k);
      }
      out.types.push_back(kVtkHexahedron);
    }
    out.offsets.push_back(out.points.size());
  }
  return out;
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

void header(std::string& out, std::size_t points, std::size_t cells) {
  out +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n";
  out += fmt::format("  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", points,
                     cells);
}

}  // namespace

std::string bodies_vtu_3d(const Scene3D& scene) {
  const BodyPoints g = body_points(scene);
  const std::size_t points = g.points.size();
  const std::size_t cells = g.types.size();
  std::string out;
  header(out, points, cells);
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, points, [&](std::size_t i, int c) { return g.points[i](c); });
  out += "      </Points>\n      <Cells>\n";
  data_array(out, "Int64", "connectivity", 1, points,
             [](std::size_t i, int) { return static_cast<long long>(i); });
  data_array(out, "Int64", "offsets", 1, cells,
             [&](std::size_t i, int) { return static_cast<long long>(g.offsets[i]); });
  data_array(out, "UInt8", "types", 1, cells, [&](std::size_t i, int) { return g.types[i]; });
  // Point data (every point carries its contactor's and body's fields) so that a Glyph filter
  // scaled by `radius` draws the spheres; the corners of a PLANx box have radius 0.
  out += "      </Cells>\n      <PointData Scalars=\"radius\">\n";
  const RigidBodies3D& b = scene.bodies;
  const auto contactor = [&](std::size_t p) -> const Contactor3D& { return scene.contactors[g.owner[p]]; };
  const auto body = [&](std::size_t p) { return static_cast<std::size_t>(contactor(p).body); };
  data_array(out, "Float64", "radius", 1, points, [&](std::size_t i, int) {
    return contactor(i).shape == ContactorShape3D::sphere ? contactor(i).radius : 0.0;
  });
  data_array(out, "Int32", "Ids", 1, points,
             [&](std::size_t i, int) { return static_cast<int>(body(i)) + 1; });
  data_array(out, "Float64", "Disp", 3, points,
             [&](std::size_t i, int c) { return b.displacement[body(i)](c); });
  data_array(out, "Float64", "Velocy", 3, points,
             [&](std::size_t i, int c) { return b.velocity[body(i)](c); });
  // Angular velocity in global axes: frame * ω (ω in the body's principal axes).
  data_array(out, "Float64", "Spin", 3, points,
             [&](std::size_t i, int c) { return (b.frame[body(i)] * b.velocity[body(i)].tail<3>())(c); });
  data_array(out, "Int32", "Visible", 1, points,
             [&](std::size_t i, int) { return static_cast<int>(b.visible[body(i)]); });
  out += "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string contacts_vtu_3d([[maybe_unused]] const Scene3D& scene, const RunState3D& state) {
  const auto& contacts = state.contacts;
  const std::size_t n = contacts.size();
  const double h = state.h;
  std::string out;
  header(out, n, n);
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, n, [&](std::size_t i, int c) { return contacts[i].point(c); });
  out += "      </Points>\n      <Cells>\n";
  data_array(out, "Int64", "connectivity", 1, n,
             [](std::size_t i, int) { return static_cast<long long>(i); });
  data_array(out, "Int64", "offsets", 1, n, [](std::size_t i, int) { return static_cast<long long>(i + 1); });
  data_array(out, "UInt8", "types", 1, n, [](std::size_t, int) { return kVtkVertex; });
  out += "      </Cells>\n      <PointData Vectors=\"R\">\n";
  // Frame rows are (t, n, s) in global axes.
  data_array(out, "Float64", "N", 3, n, [&](std::size_t i, int c) { return contacts[i].frame(1, c); });
  data_array(out, "Float64", "T", 3, n, [&](std::size_t i, int c) { return contacts[i].frame(0, c); });
  data_array(out, "Float64", "S", 3, n, [&](std::size_t i, int c) { return contacts[i].frame(2, c); });
  // Global reaction force frameᵀ r / h.
  data_array(out, "Float64", "R", 3, n,
             [&](std::size_t i, int c) { return (contacts[i].frame.transpose() * contacts[i].r)(c) / h; });
  data_array(out, "Float64", "rln", 1, n, [&](std::size_t i, int) { return contacts[i].r(1) / h; });
  data_array(out, "Float64", "rlt", 1, n, [&](std::size_t i, int) { return contacts[i].r(0) / h; });
  data_array(out, "Float64", "rls", 1, n, [&](std::size_t i, int) { return contacts[i].r(2) / h; });
  data_array(out, "Float64", "gap", 1, n,
             [&](std::size_t i, int) { return contacts[i].gap_begin + h * contacts[i].u(1); });
  data_array(out, "Int32", "status", 1, n,
             [&](std::size_t i, int) { return static_cast<int>(contacts[i].status); });
  data_array(out, "Int32", "cdbdy", 1, n, [&](std::size_t i, int) { return contacts[i].candidate_body + 1; });
  data_array(out, "Int32", "anbdy", 1, n,
             [&](std::size_t i, int) { return contacts[i].antagonist_body + 1; });
  out += "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

bool DisplayWriter3D::write(const Scene3D& scene, const RunState3D& state, std::string& error) {
  const std::size_t k = times_.size() + 1;
  if (!grammar::write_file_whole(dir_ / fmt::format("bodies_{}.vtu", k), bodies_vtu_3d(scene), error))
    return false;
  if (!grammar::write_file_whole(dir_ / fmt::format("contacts_{}.vtu", k), contacts_vtu_3d(scene, state),
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
