// The MAILx reference cases (reference_cases/mailx_*; README.md in each gives the expected values,
// their source and tolerance): run by lmgc-run through their own command.py, they write LMGC90's
// DOF.LAST and GPV.LAST byte for byte (lmgc90_reference/, LMGC90 2025 running the same script), and
// the patch carries its uniform stress at every Gauss point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "grammar/gpv/parser.hpp"
#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// reference_cases/<name>'s DATBOX and command.py in scratch_dir(tag), to edit before a run.
fs::path copied_case(const std::string& name, const std::string& tag) {
  const fs::path dir = scratch_dir(tag);
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / entry, dir / entry,
             fs::copy_options::recursive);
  return dir;
}

fs::path run_case(const std::string& name) {
  return run_reference_case(name, "mailx_" + name);
}

void expect_lmgc90_files(const std::string& name, const fs::path& dir) {
  const fs::path reference = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / "lmgc90_reference";
  for (const char* file : {"DOF.LAST", "GPV.LAST"}) {
    const std::string ours = read_file(dir / "OUTBOX" / file);
    EXPECT_FALSE(ours.empty()) << file;
    EXPECT_TRUE(ours == read_file(reference / file)) << name << ": " << file << " differs from LMGC90's";
  }
}

TEST(MailxReferenceCases, PatchCarriesItsUniformStressAndWritesLmgc90sFiles) {
  const fs::path dir = run_case("mailx_patch_q4");
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  expect_lmgc90_files("mailx_patch_q4", dir);
  grammar::DiagnosticSink sink(10);
  const fs::path gpv_path = dir / "OUTBOX" / "GPV.LAST";
  const grammar::GpvFile gpv =
      grammar::parse_gpv(grammar::SourceText(gpv_path.string(), read_file(gpv_path)), sink);
  ASSERT_EQ(gpv.bodies.size(), 1u);
  ASSERT_EQ(gpv.bodies[0].elements.size(), 9u);
  const double expected[4] = {1.8e6, 2.2e6, 0.6e6, 1.0e6};
  int points = 0;
  double worst = 0.0;
  for (const auto& element : gpv.bodies[0].elements) {
    const auto& lines = element.models[0].lines;
    ASSERT_EQ(lines.size(), 8u);  // 4 points × (stress, strain)
    for (std::size_t p = 0; p < lines.size(); p += 2, ++points)
      for (int k = 0; k < 4; ++k) {
        const double value = lines[p][static_cast<std::size_t>(k)].value;
        EXPECT_NEAR(value, expected[k], 5e-6 * 2.2e6);
        worst = std::max(worst, std::abs(value - expected[k]) / 2.2e6);
      }
  }
  EXPECT_EQ(points, 36);
  std::printf("largest stress deviation from the uniform stress: %.2e of the largest component\n", worst);
}

// The rows of a POSTPRO file: time, then the values.
std::vector<std::vector<double>> rows_of(const fs::path& path) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(read_file(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::vector<double> row;
    double v;
    while (fields >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

TEST(MailxReferenceCases, DampedCantileverWritesLmgc90sFiles) {
  const fs::path dir = run_case("mailx_cantilever_t3");
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  expect_lmgc90_files("mailx_cantilever_t3", dir);
  // Dep and Fint EVOLUTION of the tip's and the clamp's node sets: LMGC90's lines within 2e-7 of the
  // row's largest value (the 8 digits written; a sum of nodal forces taken in another order moves
  // its last digit).
  const fs::path reference =
      fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "mailx_cantilever_t3" / "lmgc90_reference";
  double worst = 0.0;
  for (const char* file : {"Dep_0000001.DAT", "Dep_0000002.DAT", "Fint_0000001.DAT", "Fint_0000002.DAT"}) {
    const auto ours = rows_of(dir / "POSTPRO" / file), theirs = rows_of(reference / file);
    ASSERT_EQ(ours.size(), 200u) << file;
    ASSERT_EQ(ours.size(), theirs.size()) << file;
    for (std::size_t r = 0; r < ours.size(); ++r) {
      ASSERT_EQ(ours[r].size(), theirs[r].size()) << file;
      double scale = 0.0;
      for (double v : theirs[r]) scale = std::max(scale, std::abs(v));
      for (std::size_t c = 0; c < ours[r].size(); ++c) {
        EXPECT_LE(std::abs(ours[r][c] - theirs[r][c]), 2e-7 * scale)
            << file << " row " << r + 1 << " column " << c + 1;
        worst = std::max(worst, std::abs(ours[r][c] - theirs[r][c]) / scale);
      }
    }
  }
  std::printf(
      "POSTPRO Dep/Fint EVOLUTION: largest difference from LMGC90's %.2e of the row's largest value\n",
      worst);
}

}  // namespace
}  // namespace lmgc::test

namespace lmgc::test {
namespace {

// A case with contacts against LMGC90's files: DOF.LAST byte for byte (or within 1e-9 of its largest
// value), Vloc_Rloc.LAST interaction for interaction (the same words and integers, every value within
// the tolerance of the file's largest): the cases' README.md say why.
void expect_contact_files_as(const fs::path& dir, const fs::path& reference, const std::string& name,
                             const std::string& family, bool dof_bytes, double vloc_tolerance);

void expect_lmgc90_contact_files(const std::string& name, const std::string& family, bool dof_bytes = true,
                                 double vloc_tolerance = 1e-9) {
  const fs::path dir = run_case(name);
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path reference = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / "lmgc90_reference";
  expect_contact_files_as(dir, reference, name, family, dof_bytes, vloc_tolerance);
}

// The case restarted from LMGC90's last files (DOF.LAST, Vloc_Rloc.LAST as the INI files, a GPV.INI of
// their step) for 50 steps, against LMGC90's own restart (lmgc90_reference/restart/,
// scripts/make_mailx_reference_cases.py): the warm start reads the interactions and internals back.
void expect_lmgc90_restart_files(const std::string& name, const std::string& family) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name;
  const fs::path reference = source / "lmgc90_reference";
  const fs::path dir = scratch_dir(name + "_restart");
  fs::copy(source / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
  fs::copy_file(reference / "DOF.LAST", dir / "DATBOX" / "DOF.INI", fs::copy_options::overwrite_existing);
  fs::copy_file(reference / "Vloc_Rloc.LAST", dir / "DATBOX" / "Vloc_Rloc.INI",
                fs::copy_options::overwrite_existing);
  std::istringstream dof(read_file(reference / "DOF.LAST"));
  std::string header, line;
  for (int k = 0; k < 6 && std::getline(dof, line); ++k) header += line + "\n";
  header.replace(header.find("! DOF"), 5, "! GPV");
  std::ofstream(dir / "DATBOX" / "GPV.INI") << header;
  std::istringstream script(read_file(source / "command.py"));
  std::string text;
  while (std::getline(script, line))
    text += (line.rfind("nb_steps = ", 0) == 0 ? "nb_steps = 50" : line) + "\n";
  std::ofstream(dir / "command.py") << text;
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  expect_contact_files_as(dir, reference / "restart", name, family, true, 1e-9);
}

void expect_contact_files_as(const fs::path& dir, const fs::path& reference, const std::string& name,
                             const std::string& family, bool dof_bytes, double vloc_tolerance) {
  if (dof_bytes) {
    EXPECT_TRUE(read_file(dir / "OUTBOX" / "DOF.LAST") == read_file(reference / "DOF.LAST")) << name;
  } else {
    // Values within 1e-9 of the file's largest (the case's README says why).
    const grammar::DofFile ours = read_dof(dir / "OUTBOX" / "DOF.LAST");
    const grammar::DofFile theirs = read_dof(reference / "DOF.LAST");
    std::vector<double> a, b;
    for (const auto* file : {&ours, &theirs})
      for (const auto& section : file->sections)
        for (const auto& body : section.bodies)
          for (const auto& node : body.nodes)
            for (const auto* values : {&node.x, &node.v})
              for (const auto& v : *values) (file == &ours ? a : b).push_back(v.value);
    ASSERT_EQ(a.size(), b.size());
    double dof_scale = 0.0;
    for (double v : b) dof_scale = std::max(dof_scale, std::abs(v));
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-9 * dof_scale) << name;
  }
  const grammar::VlocRlocFile ours = read_vloc_rloc(dir / "OUTBOX" / "Vloc_Rloc.LAST");
  const grammar::VlocRlocFile theirs = read_vloc_rloc(reference / "Vloc_Rloc.LAST");
  ASSERT_EQ(ours.interactions.size(), theirs.interactions.size());
  ASSERT_FALSE(ours.interactions.empty());
  double scale = 0.0;
  for (const auto& i : theirs.interactions)
    for (const auto& v : i.vectors)
      for (const auto& x : v.values) scale = std::max(scale, std::abs(x.value));
  for (std::size_t k = 0; k < ours.interactions.size(); ++k) {
    const auto &a = ours.interactions[k], &b = theirs.interactions[k];
    EXPECT_EQ(a.type.value, family);
    EXPECT_EQ(a.words, b.words);
    EXPECT_EQ(a.integers, b.integers);
    ASSERT_EQ(a.vectors.size(), b.vectors.size());
    for (std::size_t v = 0; v < a.vectors.size(); ++v)
      for (std::size_t c = 0; c < a.vectors[v].values.size(); ++c)
        EXPECT_NEAR(a.vectors[v].values[c].value, b.vectors[v].values[c].value, vloc_tolerance * scale);
  }
}

// mailx_disk_on_block: a rigid disk rolling on an elastic block (DKALp), 300 steps.
TEST(MailxReferenceCases, DiskRollingOnABlockWritesLmgc90sFiles) {
  expect_lmgc90_contact_files("mailx_disk_on_block", "DKALp");
}

// mailx_block_on_wall: an elastic block landing and sliding on a JONCx (CLJCx, GAP_SGR_CLB), 200 steps.
TEST(MailxReferenceCases, BlockSlidingOnAWallWritesLmgc90sFiles) {
  expect_lmgc90_contact_files("mailx_block_on_wall", "CLJCx", false, 2e-7);
}

// mailx_glued_blocks: a block glued on another by COUPLED_DOF on CLALp pairs, sheared, 100 steps.
TEST(MailxReferenceCases, GluedBlocksWriteLmgc90sFiles) {
  expect_lmgc90_contact_files("mailx_glued_blocks", "CLALp");
}

// The cohesive laws of deformable pairs on two bonded blocks (CLALp) pressed, then pulled apart and
// sheared, 400 steps (README.md of each): DOF.LAST within 1e-9 of its largest value or byte for
// byte, Vloc_Rloc.LAST (statuses, internals: L, jumps, β, TPSini) interaction for interaction.
TEST(MailxReferenceCases, MacCzmBlocksDamageAsLmgc90s) {
  expect_lmgc90_contact_files("mailx_mac_czm_blocks", "CLALp", false);
}
TEST(MailxReferenceCases, MalCzmBlocksDamageAsLmgc90s) {
  expect_lmgc90_contact_files("mailx_mal_czm_blocks", "CLALp");
}
TEST(MailxReferenceCases, GapMohrDsClbBlocksBreakAsLmgc90s) {
  expect_lmgc90_contact_files("mailx_gap_mohr_blocks", "CLALp");
}
TEST(MailxReferenceCases, GapWetDsClbBlocksSeparateAsLmgc90s) {
  expect_lmgc90_contact_files("mailx_gap_wet_blocks", "CLALp", false);
}

// mailx_glued_points: two blocks glued node to node by COUPLED_DOF on P2P2L pairs of coinciding
// PT2DL points, 150 steps.
TEST(MailxReferenceCases, BlocksGluedNodeToNodeWriteLmgc90sFiles) {
  expect_lmgc90_contact_files("mailx_glued_points", "P2P2L");
}

// The same case in the layout LMGC90's pre writes ('+PT2DL' lines, each its own point) runs the same.
TEST(MailxReferenceCases, PlusPt2dlLinesAreEachTheirOwnPoint) {
  const fs::path dir = run_reference_case("mailx_glued_points", "mailx_glued_points_plain");
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path plus = copied_case("mailx_glued_points", "mailx_glued_points_plus");
  std::istringstream in(read_file(plus / "DATBOX" / "BODIES.DAT"));
  std::string bodies, line;
  bool first_of_body = true;
  int continued = 0;
  while (std::getline(in, line)) {
    if (line.rfind(" MAILx", 0) == 0) first_of_body = true;
    if (line.rfind(" PT2DL", 0) == 0) {
      if (!first_of_body) line[0] = '+', ++continued;
      first_of_body = false;
    }
    bodies += line + "\n";
  }
  EXPECT_EQ(continued, 4);
  std::ofstream(plus / "DATBOX" / "BODIES.DAT") << bodies;
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + plus.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(read_file(plus / "OUTBOX" / "DOF.LAST") == read_file(dir / "OUTBOX" / "DOF.LAST"));
  EXPECT_TRUE(read_file(plus / "OUTBOX" / "Vloc_Rloc.LAST") == read_file(dir / "OUTBOX" / "Vloc_Rloc.LAST"));
}

// Coinciding points of a P2P2L row are glued, which LMGC90 does only with COUPLED_DOF: another law is
// an error (L2018 at the row's law) before the run.
TEST(MailxReferenceCases, CoincidingPointsWithAnotherLawThanCoupledDofAreRefused) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path dir = copied_case("mailx_glued_points", "mailx_glued_points_iqs");
  std::string tact = read_file(dir / "DATBOX" / "TACT_BEHAV.DAT");
  const std::string glue = " glued  COUPLED_DOF";
  ASSERT_NE(tact.find(glue), std::string::npos);
  tact.replace(tact.find(glue), glue.size(), " glued  IQS_CLB                         fric= 0.3000000D+00");
  std::ofstream(dir / "DATBOX" / "TACT_BEHAV.DAT") << tact;
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "'");
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("error[L2018]"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("TACT_BEHAV.DAT:6:23"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("only with COUPLED_DOF"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "OUTBOX" / "DOF.LAST"));
}

TEST(MailxReferenceCases, MacCzmBlocksRestartFromLmgc90sFilesAsLmgc90Does) {
  expect_lmgc90_restart_files("mailx_mac_czm_blocks", "CLALp");
}
TEST(MailxReferenceCases, GluedPointsRestartFromLmgc90sFilesAsLmgc90Does) {
  expect_lmgc90_restart_files("mailx_glued_points", "P2P2L");
}
TEST(MailxReferenceCases, DiskOnDisklRestartsFromLmgc90sFilesAsLmgc90Does) {
  expect_lmgc90_restart_files("mailx_disk_on_diskl", "DKDKL");
}

// A DISKL whose arc has no sagitta has no disk (LMGC90 divides by bdyr): lmgc-check's L3018 at the value.
TEST(MailxReferenceCases, DisklWithoutSagittaIsADegenerateContactor) {
  const fs::path dir = copied_case("mailx_disk_on_diskl", "mailx_disk_on_diskl_flat");
  std::string bodies = read_file(dir / "DATBOX" / "BODIES.DAT");
  const std::string arc = "bdyr= 0.4000000D-01";
  ASSERT_NE(bodies.find(arc), std::string::npos);
  bodies.replace(bodies.find(arc), arc.size(), "bdyr= 0.0000000D+00");
  std::ofstream(dir / "DATBOX" / "BODIES.DAT") << bodies;
  const ToolRun run = run_tool_both_streams("lmgc-check", "'" + dir.string() + "'");
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("error[L3018]"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("bdyr (the arc's sagitta) is 0"), std::string::npos) << run.output;
}

// mailx_disk_on_diskl: a rigid disk landing and sliding on the DISKL arcs of an elastic block
// (DKDKL, mod_DISKL's velocity and reaction maps), 300 steps.
TEST(MailxReferenceCases, DiskOnTheArcsOfABlockWritesLmgc90sFiles) {
  expect_lmgc90_contact_files("mailx_disk_on_diskl", "DKDKL");
}

}  // namespace
}  // namespace lmgc::test
