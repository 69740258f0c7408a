// The MAILx bodies of LMGC90's example mecaMAILx_RIGID_2D/4cubes as linear elastic meshes
// (solver/model/mesh_bodies.hpp): their elements, materials and lumped masses as the case gives them
// (each body's mass is ρ times its area, the area from the nodes' coordinates), a stiffness whose
// kernel is the three rigid modes; and a model lmgc does not run yet is refused at its line.
#include "solver/model/mesh_bodies.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <filesystem>
#include <fstream>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;

fs::path four_cubes() {
  return test::examples_dir() / "mecaMAILx_RIGID_2D" / "4cubes";
}

TEST(MeshBodies, FourCubesMeshesHaveTheirMassAndOnlyRigidModesInTheirKernel) {
  LMGC_REQUIRE_SHARED();
  grammar::DiagnosticSink sink(100);
  const auto files = case_folder::load_case(four_cubes(), sink);
  ASSERT_TRUE(files);
  MeshBodies meshes;
  ASSERT_TRUE(build_mesh_bodies(*files, fem::Hypothesis::plane_strain, meshes, sink));
  EXPECT_EQ(sink.error_count(), 0u);
  ASSERT_EQ(meshes.bodies.size(), 3u);
  const fem::MeshBody& body = meshes.bodies[0];
  EXPECT_EQ(body.nodes(), 9u);
  EXPECT_EQ(body.elements.size(), 8u);
  EXPECT_TRUE(body.lumped_mass);
  EXPECT_TRUE(meshes.matlib[0]);
  ASSERT_EQ(body.materials.size(), 1u);
  EXPECT_EQ(body.materials[0].young, 0.16e11);
  EXPECT_EQ(body.materials[0].poisson, 0.3);
  EXPECT_EQ(body.materials[0].density, 2300.0);
  for (const fem::MeshBody& mesh : meshes.bodies) {
    fem::LinearBodyMatrices m;
    std::string error;
    ASSERT_TRUE(fem::assemble(mesh, m, error)) << error;
    double area = 0.0;
    for (const fem::MeshElement& e : mesh.elements) {
      const auto p = [&](int k) {
        const auto n = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)]);
        return Eigen::Vector2d(mesh.coordinates[2 * n], mesh.coordinates[2 * n + 1]);
      };
      const Eigen::Vector2d a = p(1) - p(0), b = p(2) - p(0);
      area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    // Lumped mass: diagonal, each component carries the body's mass.
    const Eigen::VectorXd diagonal = Eigen::MatrixXd(m.mass).diagonal();
    EXPECT_NEAR((Eigen::MatrixXd(m.mass) - Eigen::MatrixXd(diagonal.asDiagonal())).norm(), 0.0, 0.0);
    double x_mass = 0.0;
    for (Eigen::Index i = 0; i < diagonal.size(); i += 2) x_mass += diagonal(i);
    EXPECT_NEAR(x_mass, 2300.0 * area, 1e-9 * 2300.0 * area);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen{Eigen::MatrixXd(m.stiffness)};
    const double largest = eigen.eigenvalues().maxCoeff();
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(eigen.eigenvalues()(i)), 1e-9 * largest);
    EXPECT_GT(eigen.eigenvalues()(3), 1e-6 * largest);
  }
}

// 4cubes' MAILx model with its kinematics, form and material replaced by `edits` (pairs of
// (what, by what)), read into meshes.
bool build_edited_four_cubes(const std::string& name, std::vector<std::pair<std::string, std::string>> edits,
                             MeshBodies& meshes, grammar::DiagnosticSink& sink) {
  const fs::path dir = test::scratch_dir(name);
  fs::copy(four_cubes() / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
  std::string models = test::read_file(dir / "DATBOX" / "MODELS.DAT");
  for (const auto& [what, by] : edits) {
    const auto at = models.find(what);
    EXPECT_NE(at, std::string::npos) << what;
    if (at != std::string::npos) models.replace(at, what.size(), by);
  }
  std::ofstream(dir / "DATBOX" / "MODELS.DAT") << models;
  const auto files = case_folder::load_case(dir, sink);
  EXPECT_TRUE(files);
  return files && build_mesh_bodies(*files, fem::Hypothesis::plane_strain, meshes, sink);
}

TEST(MeshBodies, AModelLmgcDoesNotRunIsRefusedAtItsLine) {
  LMGC_REQUIRE_SHARED();
  grammar::DiagnosticSink sink(100);
  MeshBodies meshes;
  // Large strain in the updated Lagrangian form: not run yet, refused at the form_ line.
  EXPECT_FALSE(build_edited_four_cubes("mesh_bodies_updated_lagrangian",
                                       {{"kine_  small", "kine_  large"}, {"form_  xxxxx", "form_  UpdtL"}},
                                       meshes, sink));
  ASSERT_FALSE(sink.items().empty());
  const grammar::Diagnostic& d = sink.items().back();
  EXPECT_EQ(d.code, "L4003");
  EXPECT_NE(d.message.find("UpdtL"), std::string::npos) << d.message;
  EXPECT_EQ(d.where.span.line, 26u);  // MODELS.DAT's form_ line
}

TEST(MeshBodies, LargeStrainWithTheNeoHookeanMaterialIsTotalLagrangian) {
  LMGC_REQUIRE_SHARED();
  grammar::DiagnosticSink sink(100);
  MeshBodies meshes;
  ASSERT_TRUE(build_edited_four_cubes(
      "mesh_bodies_neo_hookean",
      {{"kine_  small", "kine_  large"}, {"form_  xxxxx", "form_  TotaL"}, {"mater  elas_", "mater  neoh_"}},
      meshes, sink));
  ASSERT_EQ(meshes.bodies.size(), 3u);
  for (const fem::MeshBody& body : meshes.bodies) {
    EXPECT_EQ(body.kinematics, fem::Kinematics::total_lagrangian);
    for (const fem::MeshElement& e : body.elements)
      EXPECT_EQ(body.materials[static_cast<std::size_t>(e.material)].law, fem::MaterialLaw::neo_hookean);
  }
  // Another material in large strain: refused at its mater line.
  grammar::DiagnosticSink other(100);
  EXPECT_FALSE(build_edited_four_cubes("mesh_bodies_large_elastic",
                                       {{"kine_  small", "kine_  large"}, {"form_  xxxxx", "form_  TotaL"}},
                                       meshes, other));
  ASSERT_FALSE(other.items().empty());
  EXPECT_EQ(other.items().back().code, "L4003");
  EXPECT_EQ(other.items().back().where.span.line, 28u);
}

}  // namespace
}  // namespace lmgc::solver

namespace lmgc::solver {
namespace {

// 4cubes' contactors as LMGC90 numbers them (mailx-2d-contact.md §1): every $tacty line its own
// contactor, ranked in its body whatever its type, serials per type over the case; an ALpxx with
// '+ALpxx' lines is one polyline; a continuation that does not start where the polyline ended is
// refused at its line.
TEST(MeshBodies, ContactorsAreRankedAsLmgc90RanksThemAndPolylinesContinue) {
  LMGC_REQUIRE_SHARED();
  grammar::DiagnosticSink sink(100);
  const auto files = case_folder::load_case(four_cubes(), sink);
  ASSERT_TRUE(files);
  MeshBodies meshes;
  ASSERT_TRUE(build_mesh_bodies(*files, fem::Hypothesis::plane_strain, meshes, sink));
  // Body 1: 6 ALpxx and 4 CLxxx; bodies 2 and 3: 4 CLxxx, 4 ALpxx, 4 CLxxx.
  ASSERT_EQ(meshes.contactors.size(), 34u);
  const MeshContactor& first = meshes.contactors[0];
  EXPECT_EQ(first.type, "ALpxx");
  EXPECT_EQ(first.rank, 1);
  EXPECT_EQ(first.nodes, (std::vector<std::int32_t>{2, 1}));  // noda= 3 nodb= 2, 0-based
  const MeshContactor& body2_al = meshes.contactors[14];      // body 2's 5th line: its first ALpxx
  EXPECT_EQ(body2_al.mesh, 1);
  EXPECT_EQ(body2_al.rank, 5);
  EXPECT_EQ(body2_al.serial, 7);  // after body 1's six
  EXPECT_EQ(meshes.contactors[6].type, "CLxxx");
  EXPECT_DOUBLE_EQ(meshes.contactors[6].apab, 0.2);

  // Body 1's first two ALpxx lines as one polyline: 3 → 2, then '+ALpxx' 2 → 9 and 9 → 8.
  const fs::path dir = test::scratch_dir("mesh_bodies_polyline");
  fs::copy(four_cubes() / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
  std::string bodies = test::read_file(dir / "DATBOX" / "BODIES.DAT");
  const std::string line = " ALpxx      6  color  REDxx  noda=    4  nodb=    3\n";
  const auto at = bodies.find(line);
  ASSERT_NE(at, std::string::npos);
  const std::string plus =
      "+ALpxx      6  color  REDxx  noda=    2  nodb=    9\n+ALpxx      6  color  REDxx  noda=    9  nodb=   "
      " 8\n";
  bodies.replace(at, line.size(), plus);
  std::ofstream(dir / "DATBOX" / "BODIES.DAT") << bodies;
  grammar::DiagnosticSink polyline_sink(100);
  const auto polyline_files = case_folder::load_case(dir, polyline_sink);
  ASSERT_TRUE(polyline_files);
  ASSERT_TRUE(build_mesh_bodies(*polyline_files, fem::Hypothesis::plane_strain, meshes, polyline_sink));
  EXPECT_EQ(meshes.contactors[0].nodes, (std::vector<std::int32_t>{2, 1, 8, 7}));
  EXPECT_EQ(meshes.contactors[0].segments(), 3u);
  EXPECT_EQ(meshes.contactors[1].rank, 2);  // the continuation lines are not contactors

  bodies.replace(bodies.find("noda=    9  nodb=    8"), 22, "noda=    7  nodb=    8");
  std::ofstream(dir / "DATBOX" / "BODIES.DAT") << bodies;
  grammar::DiagnosticSink broken_sink(100);
  const auto broken = case_folder::load_case(dir, broken_sink);
  ASSERT_TRUE(broken);
  EXPECT_FALSE(build_mesh_bodies(*broken, fem::Hypothesis::plane_strain, meshes, broken_sink));
  ASSERT_FALSE(broken_sink.items().empty());
  EXPECT_EQ(broken_sink.items().back().code, "L4003");
}

}  // namespace
}  // namespace lmgc::solver
