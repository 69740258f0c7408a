// ParaView output of a rigid 3D run (solver/io/display_3d): a sphere resting on a PLANx box, run
// two steps with step_3d and written after each by DisplayWriter3D into a scratch folder; the
// .vtu files are parsed as XML, their piece sizes and data arrays checked against the scene and
// the run state, and the .pvd collection checked to list both steps.
#include "solver/io/display_3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "solver/integrator/step_3d.hpp"
#include "solver/model/scene_builder_3d.hpp"
#include "tests/support/nlgs_options.hpp"
#include "tests/support/run_tool.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;
using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kH = 1e-3;
constexpr double kG = 9.81;
constexpr double kRadius = 0.1;
constexpr double kDensity = 1000.0;

// ---- A minimal XML reader: elements, attributes, text; enough to check well-formedness. ----
struct XmlNode {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlNode> children;

  const XmlNode* child(const std::string& n) const {
    for (const XmlNode& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
  std::string attribute(const std::string& a) const {
    const auto it = attributes.find(a);
    return it == attributes.end() ? std::string() : it->second;
  }
};

class XmlReader {
 public:
  explicit XmlReader(const std::string& s) : s_(s) {}

  bool document(XmlNode& root, std::string& why) {
    skip_space();
    if (s_.compare(p_, 5, "<?xml") == 0) {
      const auto end = s_.find("?>", p_);
      if (end == std::string::npos) return fail(why, "unterminated XML declaration");
      p_ = end + 2;
    }
    skip_space();
    if (!element(root, why)) return false;
    skip_space();
    if (p_ != s_.size()) return fail(why, "content after the root element");
    return true;
  }

 private:
  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.';
  }
  void skip_space() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  bool fail(std::string& why, const std::string& what) {
    why = what + " at offset " + std::to_string(p_);
    return false;
  }
  std::string name() {
    const std::size_t start = p_;
    while (p_ < s_.size() && name_char(s_[p_])) ++p_;
    return s_.substr(start, p_ - start);
  }
  bool element(XmlNode& node, std::string& why) {
    if (p_ >= s_.size() || s_[p_] != '<') return fail(why, "expected '<'");
    ++p_;
    node.name = name();
    if (node.name.empty()) return fail(why, "empty element name");
    for (;;) {
      skip_space();
      if (p_ >= s_.size()) return fail(why, "unterminated start tag");
      if (s_.compare(p_, 2, "/>") == 0) {
        p_ += 2;
        return true;
      }
      if (s_[p_] == '>') {
        ++p_;
        break;
      }
      const std::string a = name();
      if (a.empty()) return fail(why, "bad attribute name");
      skip_space();
      if (p_ >= s_.size() || s_[p_] != '=') return fail(why, "expected '='");
      ++p_;
      skip_space();
      if (p_ >= s_.size() || (s_[p_] != '"' && s_[p_] != '\'')) return fail(why, "unquoted attribute");
      const char quote = s_[p_++];
      const auto end = s_.find(quote, p_);
      if (end == std::string::npos) return fail(why, "unterminated attribute value");
      const std::string value = s_.substr(p_, end - p_);
      if (value.find('<') != std::string::npos) return fail(why, "'<' in an attribute value");
      if (!node.attributes.emplace(a, value).second) return fail(why, "duplicate attribute " + a);
      p_ = end + 1;
    }
    for (;;) {
      if (p_ >= s_.size()) return fail(why, "unterminated element " + node.name);
      if (s_.compare(p_, 2, "</") == 0) {
        p_ += 2;
        if (name() != node.name) return fail(why, "mismatched end tag of " + node.name);
        skip_space();
        if (p_ >= s_.size() || s_[p_] != '>') return fail(why, "bad end tag");
        ++p_;
        return true;
      }
      if (s_[p_] == '<') {
        node.children.emplace_back();
        if (!element(node.children.back(), why)) return false;
      } else {
        const auto end = s_.find('<', p_);
        if (end == std::string::npos) return fail(why, "unterminated text");
        const std::string text = s_.substr(p_, end - p_);
        if (text.find_first_of("&>") != std::string::npos) return fail(why, "unescaped '&' or '>'");
        node.text += text;
        p_ = end;
      }
    }
  }

  const std::string& s_;
  std::size_t p_ = 0;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

XmlNode parse(const fs::path& path) {
  XmlNode root;
  std::string why;
  EXPECT_TRUE(XmlReader(read_text(path)).document(root, why)) << path << ": " << why;
  return root;
}

std::vector<double> numbers(const XmlNode& array) {
  std::vector<double> out;
  std::istringstream in(array.text);
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    out.push_back(std::strtod(word.c_str(), &end));
    EXPECT_EQ(*end, '\0') << "not a number: " << word;
  }
  return out;
}

// A parsed UnstructuredGrid piece: its sizes and every data array by name (per section).
struct Piece {
  std::size_t points = 0, cells = 0;
  std::map<std::string, std::map<std::string, std::vector<double>>> arrays;  // section -> name -> values
  std::map<std::string, std::map<std::string, int>> components;
};

Piece read_piece(const fs::path& path) {
  Piece piece;
  const XmlNode root = parse(path);
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attribute("type"), "UnstructuredGrid");
  const XmlNode* grid = root.child("UnstructuredGrid");
  if (!grid) {
    ADD_FAILURE() << path << ": no UnstructuredGrid";
    return piece;
  }
  const XmlNode* p = grid->child("Piece");
  if (!p) {
    ADD_FAILURE() << path << ": no Piece";
    return piece;
  }
  piece.points = std::stoul(p->attribute("NumberOfPoints"));
  piece.cells = std::stoul(p->attribute("NumberOfCells"));
  for (const XmlNode& section : p->children)
    for (const XmlNode& array : section.children) {
      EXPECT_EQ(array.name, "DataArray");
      EXPECT_EQ(array.attribute("format"), "ascii");
      const std::string name = array.attribute("Name");
      piece.arrays[section.name][name] = numbers(array);
      piece.components[section.name][name] = std::stoi(array.attribute("NumberOfComponents"));
    }
  // Every array holds one tuple per point (Points, PointData) or per cell (offsets, types,
  // CellData); connectivity as many entries as the last offset.
  for (const auto& [section, arrays] : piece.arrays)
    for (const auto& [name, values] : arrays) {
      const auto tuples = static_cast<std::size_t>(piece.components[section][name]);
      std::size_t expected = 0;
      if (section == "Points" || section == "PointData") {
        expected = tuples * piece.points;
      } else if (section == "Cells" && name == "connectivity") {
        const auto& offsets = arrays.at("offsets");
        expected = offsets.empty() ? 0 : static_cast<std::size_t>(offsets.back());
      } else {
        expected = tuples * piece.cells;
      }
      EXPECT_EQ(values.size(), expected) << path << " " << section << "/" << name;
    }
  return piece;
}

Vector3d tuple3(const std::vector<double>& values, std::size_t i) {
  return Vector3d(values.at(3 * i), values.at(3 * i + 1), values.at(3 * i + 2));
}

// ---- The scene: body 1 a ground PLANx (top face z = 0), body 2 a sphere resting on it. ----
Scene3D build_scene() {
  SceneBuilder3D b;
  b.add_fixed_plane(Vector3d(0.0, 0.0, -0.05), Matrix3d::Identity(), Vector3d(1.0, 0.5, 0.05));
  b.add_sphere(Vector3d(0.2, 0.0, kRadius), kRadius, kDensity);
  b.add_law("iqsc0", IqsClb{0.3});
  b.see("SPHER", "BLEUx", "iqsc0", "PLANx", "VERTx", 0.01);
  return b.build();
}

struct Written {
  fs::path dir;
  Scene3D scene;
  RunState3D state;
};

Written run_and_write(const std::string& name) {
  Written w{lmgc::test::scratch_dir(name) / "DISPLAY", build_scene(), {}};
  w.state.h = kH;
  DisplayWriter3D display(w.dir);
  for (int k = 0; k < 2; ++k) {
    EXPECT_TRUE(step_3d(w.scene, w.state, test::converged_nlgs_options(10)).converged);
    std::string error;
    EXPECT_TRUE(display.write(w.scene, w.state, error)) << error;
    EXPECT_EQ(display.count(), static_cast<std::size_t>(k + 1));
  }
  return w;
}

TEST(Display3D, WritesBodiesContactsAndCollectionFilesPerStep) {
  const Written w = run_and_write("display_3d_files");
  for (const char* f : {"bodies_1.vtu", "contacts_1.vtu", "bodies_2.vtu", "contacts_2.vtu", "lmgc90.pvd"})
    EXPECT_TRUE(fs::is_regular_file(w.dir / f)) << f;
  // Written whole: no temporary file left behind.
  for (const auto& entry : fs::directory_iterator(w.dir))
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
}

TEST(Display3D, CollectionListsBothStepsWithTheirTimes) {
  const Written w = run_and_write("display_3d_pvd");
  const XmlNode root = parse(w.dir / "lmgc90.pvd");
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attribute("type"), "Collection");
  const XmlNode* collection = root.child("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->children.size(), 4u);
  const char* files[] = {"bodies_1.vtu", "contacts_1.vtu", "bodies_2.vtu", "contacts_2.vtu"};
  const double times[] = {kH, kH, 2 * kH, 2 * kH};
  for (std::size_t i = 0; i < 4; ++i) {
    const XmlNode& d = collection->children[i];
    EXPECT_EQ(d.name, "DataSet");
    EXPECT_EQ(d.attribute("file"), files[i]);
    EXPECT_EQ(d.attribute("part"), i % 2 == 0 ? "0" : "1");
    EXPECT_NEAR(std::stod(d.attribute("timestep")), times[i], 1e-15);
    EXPECT_TRUE(fs::is_regular_file(w.dir / d.attribute("file")));
  }
}

TEST(Display3D, BodiesFileHasASphereVertexAndAPlaneHexahedron) {
  const Written w = run_and_write("display_3d_bodies");
  const Piece piece = read_piece(w.dir / "bodies_2.vtu");
  // Contactor 0: the PLANx box (8 corners), contactor 1: the sphere (one vertex).
  EXPECT_EQ(piece.points, 9u);
  EXPECT_EQ(piece.cells, 2u);
  const auto& cells = piece.arrays.at("Cells");
  EXPECT_EQ(cells.at("types"), (std::vector<double>{12, 1}));
  EXPECT_EQ(cells.at("offsets"), (std::vector<double>{8, 9}));
  const auto& points = piece.arrays.at("Points").at("Points");
  const auto& data = piece.arrays.at("PointData");

  // The box corners: centre (0, 0, -0.05), half-axes (1, 0.5, 0.05), positive hexahedron volume.
  Vector3d low = tuple3(points, 0), high = low;
  for (std::size_t i = 0; i < 8; ++i) {
    low = low.cwiseMin(tuple3(points, i));
    high = high.cwiseMax(tuple3(points, i));
    EXPECT_EQ(data.at("radius").at(i), 0.0);
    EXPECT_EQ(data.at("Ids").at(i), 1.0);
  }
  EXPECT_LT((low - Vector3d(-1.0, -0.5, -0.1)).norm(), 1e-12);
  EXPECT_LT((high - Vector3d(1.0, 0.5, 0.0)).norm(), 1e-12);
  const Vector3d p0 = tuple3(points, 0);
  EXPECT_GT((tuple3(points, 1) - p0).cross(tuple3(points, 3) - p0).dot(tuple3(points, 4) - p0), 0.0);

  // The sphere: at reference + displacement, with its radius, body id and velocities.
  const RigidBodies3D& b = w.scene.bodies;
  const Vector3d centre = b.reference[1] + b.displacement[1].head<3>();
  EXPECT_LT((tuple3(points, 8) - centre).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(data.at("radius").at(8), kRadius);
  EXPECT_EQ(data.at("Ids").at(8), 2.0);
  EXPECT_LT((tuple3(data.at("Velocy"), 8) - b.velocity[1].head<3>()).norm(), 1e-12);
  EXPECT_LT((tuple3(data.at("Spin"), 8) - b.frame[1] * b.velocity[1].tail<3>()).norm(), 1e-12);
  EXPECT_LT((tuple3(data.at("Disp"), 8) - b.displacement[1].head<3>()).norm(), 1e-12);
}

TEST(Display3D, ContactsFileHasOneVertexPerInteraction) {
  const Written w = run_and_write("display_3d_contacts");
  ASSERT_EQ(w.state.contacts.size(), 1u);
  const Piece piece = read_piece(w.dir / "contacts_2.vtu");
  EXPECT_EQ(piece.points, 1u);
  EXPECT_EQ(piece.cells, 1u);
  EXPECT_EQ(piece.arrays.at("Cells").at("types"), (std::vector<double>{1}));
  const Interaction3D& c = w.state.contacts[0];
  const auto& data = piece.arrays.at("PointData");
  EXPECT_LT((tuple3(piece.arrays.at("Points").at("Points"), 0) - c.point).norm(), 1e-12);
  // The normal (frame row n) points up from the ground; the reaction carries the sphere's weight.
  const Vector3d normal = tuple3(data.at("N"), 0);
  EXPECT_LT((normal - c.frame.row(1).transpose()).norm(), 1e-12);
  EXPECT_NEAR(normal.z(), 1.0, 1e-12);
  const Vector3d reaction = tuple3(data.at("R"), 0);
  EXPECT_LT((reaction - c.frame.transpose() * c.r / kH).norm(), 1e-9);
  const double weight = kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) * kG;
  EXPECT_NEAR(reaction.z(), weight, 1e-6 * weight);
  EXPECT_NEAR(data.at("rln").at(0), c.r(1) / kH, 1e-9);
  EXPECT_NEAR(data.at("gap").at(0), c.gap_begin + kH * c.u(1), 1e-15);
  EXPECT_EQ(data.at("status").at(0), static_cast<double>(static_cast<int>(c.status)));
  EXPECT_EQ(data.at("cdbdy").at(0), 2.0);
  EXPECT_EQ(data.at("anbdy").at(0), 1.0);
}

// World placement: a PLANx box's axes are the body frame times the contactor's local frame; an
// SPHEb sphere sits at centre + frame * shift.
TEST(Display3D, PlacesTurnedPlanesAndClusterSpheresInWorldAxes) {
  SceneBuilder3D builder;
  const Matrix3d local = Eigen::AngleAxisd(0.35, Vector3d::UnitX()).toRotationMatrix();
  const Matrix3d turn = Eigen::AngleAxisd(0.5, Vector3d::UnitZ()).toRotationMatrix();
  const Vector3d half(0.8, 0.4, 0.1);
  builder.add_fixed_plane(Vector3d(0.1, 0.2, -0.3), local, half);
  builder.set_frame(0, turn);
  builder.add_sphere_cluster(Vector3d(0.5, 0.0, 0.5), {Vector3d(-0.05, 0.0, 0.0), Vector3d(0.05, 0.02, 0.0)},
                             0.05, kDensity);
  const Scene3D scene = builder.build();
  const fs::path dir = lmgc::test::scratch_dir("display_3d_placement");
  std::string error;
  DisplayWriter3D display(dir);
  RunState3D state;
  ASSERT_TRUE(display.write(scene, state, error)) << error;
  const Piece piece = read_piece(dir / "bodies_1.vtu");
  ASSERT_EQ(piece.points, 10u);
  ASSERT_EQ(piece.cells, 3u);
  const auto& points = piece.arrays.at("Points").at("Points");
  const RigidBodies3D& b = scene.bodies;
  const Matrix3d axes = turn * local;
  const Vector3d centre = b.reference[0];
  constexpr int kCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (std::size_t i = 0; i < 8; ++i) {
    const Vector3d s(kCorner[i][0] * half(0), kCorner[i][1] * half(1), kCorner[i][2] * half(2));
    EXPECT_LT((tuple3(points, i) - (centre + axes * s)).norm(), 1e-12) << "corner " << i;
  }
  for (std::size_t k = 1; k < 3; ++k) {
    const Contactor3D& c = scene.contactors[k];
    const auto body = static_cast<std::size_t>(c.body);
    EXPECT_LT((tuple3(points, 7 + k) - (b.reference[body] + b.frame[body] * c.shift)).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(piece.arrays.at("PointData").at("radius").at(7 + k), 0.05);
  }
  // The cluster's sphere centres are the given offsets from the cluster centre, in world axes.
  EXPECT_NEAR((tuple3(points, 9) - tuple3(points, 8)).norm(), std::hypot(0.1, 0.02), 1e-12);
}

TEST(Display3D, EmptyContactListGivesAnEmptyWellFormedPiece) {
  Scene3D scene = build_scene();
  RunState3D state;
  state.h = kH;
  const fs::path dir = lmgc::test::scratch_dir("display_3d_empty");
  std::string error;
  DisplayWriter3D display(dir);
  ASSERT_TRUE(display.write(scene, state, error)) << error;
  const Piece piece = read_piece(dir / "contacts_1.vtu");
  EXPECT_EQ(piece.points, 0u);
  EXPECT_EQ(piece.cells, 0u);
}

}  // namespace
}  // namespace lmgc::solver
