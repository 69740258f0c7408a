// LMGC90's example mecaMAILx_RIGID_2D/4cubes (three T3 meshes stacked on a rigid square on a driven
// JONCx: CLALp, PLALp and PLJCx contacts, GAP_SGR_CLB and IQS_CLB) run to its end through its own
// command.py by lmgc-run, against what LMGC90 2025 wrote (../shared/.../reference_lmgc90/).
//
// Tolerance: 1e-6 of the largest value of each file (the figure for a deterministic case).
// LMGC90 prints 7 significant digits, so a value as large as the file's scale is known to 5e-8 of it;
// the NLGS stops at tol = 1.666e-4 with the same iteration counts in both codes (checked below), so
// what remains is the round-off of two different summation orders through 500 steps. Measured:
// DOF 7.7e-10, GPV 1.1e-7, Vloc_Rloc 2.3e-7 of their scales.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// Interactions per module ("$icdan  CLALp ...").
std::map<std::string, int> interaction_counts(const std::string& text) {
  std::map<std::string, int> counts;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("$icdan", 0) == 0) ++counts[line.substr(8, 5)];
  return counts;
}

// The integer columns of a POSTPRO file (SOLVER_INFORMATIONS: iterations and contacts).
std::vector<std::string> columns(const std::string& text, std::initializer_list<int> which) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    std::string w;
    while (fields >> w) f.push_back(w);
    std::string row;
    for (int k : which)
      row += (static_cast<std::size_t>(k) < f.size() ? f[static_cast<std::size_t>(k)] : "") + " ";
    out.push_back(row);
  }
  return out;
}

TEST(MailxContactExample, FourCubesRunsToItsEndAndAgreesWithLmgc90) {
  LMGC_REQUIRE_SHARED();
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = examples_dir() / "mecaMAILx_RIGID_2D" / "4cubes";
  const fs::path reference = source / "reference_lmgc90";
  const fs::path dir = scratch_dir("mailx_4cubes");
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(source / entry, dir / entry, fs::copy_options::recursive);
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;

  int compared = 0;
  std::map<std::string, double> worst;
  for (const auto& entry : fs::directory_iterator(reference / "OUTBOX")) {
    const std::string name = entry.path().filename().string();
    const std::string kind = name.substr(0, name.find('.'));
    if (name.find(".OUT.") == std::string::npos || (kind != "DOF" && kind != "GPV" && kind != "Vloc_Rloc"))
      continue;
    const std::string theirs_text = read_file(entry.path()), ours_text = read_file(dir / "OUTBOX" / name);
    const std::vector<double> theirs = fortran_numbers(theirs_text), ours = fortran_numbers(ours_text);
    ASSERT_EQ(ours.size(), theirs.size()) << name;
    double scale = 0.0, difference = 0.0;
    for (double v : theirs) scale = std::max(scale, std::abs(v));
    for (std::size_t k = 0; k < ours.size(); ++k)
      difference = std::max(difference, std::abs(ours[k] - theirs[k]));
    EXPECT_LE(difference, 1e-6 * scale) << name;
    worst[kind] = std::max(worst[kind], difference / scale);
    if (kind == "Vloc_Rloc") {
      EXPECT_EQ(interaction_counts(ours_text), interaction_counts(theirs_text)) << name;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 150);  // every numbered file LMGC90 wrote (50 each)
  for (const auto& [kind, w] : worst)
    std::printf("%s: largest difference %.2e of the file's scale\n", kind.c_str(), w);

  // The NLGS: iterations and contacts of every step; the contact natures of every step.
  const std::string solver_ours = read_file(dir / "POSTPRO" / "SOLVER_INFORMATIONS.DAT");
  const std::string solver_theirs = read_file(reference / "POSTPRO" / "SOLVER_INFORMATIONS.DAT");
  EXPECT_EQ(columns(solver_ours, {1, 5}), columns(solver_theirs, {1, 5}));
  EXPECT_EQ(columns(solver_ours, {1}).size(), 500u);
  for (const char* file : {"DRY_CONTACT_NATURE.DAT", "WET_CONTACT_NATURE.DAT"})
    EXPECT_EQ(read_file(dir / "POSTPRO" / file), read_file(reference / "POSTPRO" / file)) << file;
  // VIOLATION EVOLUTION: penetrations at round-off in both codes (≤ 1e-8 m on 1 m cubes).
  const std::vector<double> violation_ours =
      fortran_numbers(read_file(dir / "POSTPRO" / "VIOLATION_EVOLUTION.DAT"));
  const std::vector<double> violation_theirs =
      fortran_numbers(read_file(reference / "POSTPRO" / "VIOLATION_EVOLUTION.DAT"));
  ASSERT_EQ(violation_ours.size(), violation_theirs.size());
  for (std::size_t k = 0; k < violation_ours.size(); ++k)
    EXPECT_NEAR(violation_ours[k], violation_theirs[k], 1e-8);
}

}  // namespace
}  // namespace lmgc::test

namespace lmgc::test {
namespace {

// A restart from LMGC90's last files of 4cubes (its DOF.LAST, GPV.LAST and Vloc_Rloc.LAST as
// DOF.INI, GPV.INI in MatLib's layout, and Vloc_Rloc.INI with CLALp, PLALp and PLJCx records): the
// run goes on from step 500 and its first step starts from the stored reactions, so it converges at
// the first check (50 sweeps), its contacts still stuck where LMGC90 left them.
TEST(MailxContactExample, FourCubesRestartsFromLmgc90sLastFiles) {
  LMGC_REQUIRE_SHARED();
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = examples_dir() / "mecaMAILx_RIGID_2D" / "4cubes";
  const fs::path last = source / "reference_lmgc90" / "OUTBOX";
  const fs::path dir = scratch_dir("mailx_4cubes_restart");
  fs::copy(source / "DATBOX", dir / "DATBOX", fs::copy_options::recursive);
  for (const char* name : {"DOF", "GPV", "Vloc_Rloc"})
    fs::copy_file(last / (std::string(name) + ".LAST"), dir / "DATBOX" / (std::string(name) + ".INI"),
                  fs::copy_options::overwrite_existing);
  std::string script = read_file(source / "command.py");
  const std::string steps = "nb_steps = 500";
  ASSERT_NE(script.find(steps), std::string::npos);
  script.replace(script.find(steps), steps.size(), "nb_steps = 10");
  std::ofstream(dir / "command.py") << script;
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string first = read_file(dir / "OUTBOX" / "Vloc_Rloc.OUT.1");
  EXPECT_NE(first.find("$steps      510"), std::string::npos);
  EXPECT_EQ(interaction_counts(first), interaction_counts(read_file(last / "Vloc_Rloc.LAST")));
  const std::vector<std::string> iterations =
      columns(read_file(dir / "POSTPRO" / "SOLVER_INFORMATIONS.DAT"), {1});
  ASSERT_EQ(iterations.size(), 10u);
  EXPECT_EQ(iterations.front(), "50 ");
}

}  // namespace
}  // namespace lmgc::test
