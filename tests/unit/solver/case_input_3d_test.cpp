// From a rigid 3D DATBOX folder to a Scene3D (solver/driver/case_input): PT3Dx bodies linked by
// PTPT3 rows, and the laws that need those links refused elsewhere with a located diagnostic.
#include <gtest/gtest.h>

#include <fstream>

#include "solver/driver/case_input.hpp"
#include "tests/support/run_tool.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;

fs::path case_copy(const std::string& reference_case, const std::string& name) {
  const fs::path dir = test::scratch_dir(name);
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / reference_case / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  return dir;
}

// Loads the case folder and prepares its 3D run; false when either step refuses it.
bool prepare_case(const fs::path& dir, Scene3D& scene, grammar::DiagnosticSink& sink) {
  const auto files = case_folder::load_case(dir, sink);
  RunOutputs3D outputs;
  return files.has_value() && prepare_run_3d(*files, scene, outputs, sink);
}

TEST(CaseInput3D, PointBodiesOfTheWireCaseAreLinkedByTheirReferenceDistance) {
  const fs::path dir = case_copy("wire_hanging_mass_3d", "case_input_3d_wire");
  grammar::DiagnosticSink sink;
  Scene3D scene;
  ASSERT_TRUE(prepare_case(dir, scene, sink));
  ASSERT_EQ(scene.contactors.size(), 4u);
  for (const Contactor3D& c : scene.contactors) EXPECT_EQ(c.shape, ContactorShape3D::point);
  // Each mass to the anchor above it (1 m); not to the other anchor (1.41 m > alert 1.1 m).
  ASSERT_EQ(scene.point_links.size(), 2u);
  EXPECT_EQ(scene.point_links[0].candidate, 0);
  EXPECT_EQ(scene.point_links[0].antagonist, 2);
  EXPECT_EQ(scene.point_links[1].candidate, 1);
  EXPECT_EQ(scene.point_links[1].antagonist, 3);
  EXPECT_DOUBLE_EQ(scene.point_links[0].reference_length, 1.0);
  EXPECT_TRUE(std::holds_alternative<ElasticWire>(scene.laws.front().law));
}

// LMGC90 stops on a wire or rod whose reference length is not set (only PTPT3 sets it): the
// scene is refused with L2018 at the visibility row that asks for it.
TEST(CaseInput3D, AWireOnAPairOtherThanPtpt3IsRefusedAtItsVisibilityRow) {
  const fs::path dir = case_copy("sphere_bounce_rst_3d", "case_input_3d_wire_on_plane");
  const fs::path tact = dir / "DATBOX" / "TACT_BEHAV.DAT";
  std::ofstream(tact, std::ios::binary)
      << "$behav  lawty\n"
         " rst08  ELASTIC_WIRE                    F/st= 0.2000000D+04  prst= 0.0000000D+00\n"
         "\n"
         "$seety\n"
         " cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
         " RBDY3  SPHER  BLEUx  rst08  RBDY3  PLANx  VERTx       0.1000000D-01\n";
  grammar::DiagnosticSink sink;
  Scene3D scene;
  EXPECT_FALSE(prepare_case(dir, scene, sink));
  bool found = false;
  for (const grammar::Diagnostic& d : sink.items())
    if (d.code == "L2018") {
      found = true;
      EXPECT_EQ(d.where.span.line, 6u);
      EXPECT_NE(d.message.find("PTPT3"), std::string::npos) << d.message;
    }
  EXPECT_TRUE(found);
  // lmgc-solve: exit 1, nothing written.
  EXPECT_EQ(test::run_tool("lmgc-solve", "'" + dir.string() + "' --quiet").exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
}

}  // namespace
}  // namespace lmgc::solver
