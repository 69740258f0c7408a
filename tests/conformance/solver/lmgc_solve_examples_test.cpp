// lmgc-solve on LMGC90's RIGID_2D examples, with the parameters of each example's command.py as
// reference_lmgc90/RUN.md records them: every example runs (a documented step cut keeps CI
// short), and the deterministic ones agree with LMGC90's own DOF.OUT.n files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "grammar/dof/parser.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// Steps run per example in CI: the first 200 (or the script's count when smaller), and 20 for
// 500PL_PerioBoxJC, whose steps cost ~5000 NLGS sweeps over 2000 contacts each (a CI run also
// repeats this under the sanitizers). Full runs are timed in bench/.
long step_cut(const fs::path& example) { return example.filename() == "500PL_PerioBoxJC" ? 20 : 200; }

// The literal assignments of command.py, as RUN.md lists them ("`dt = 0.0005`, `nb_steps = ...`").
std::map<std::string, std::string> script_parameters(const fs::path& case_dir) {
  std::map<std::string, std::string> parameters;
  const std::string run_md = read_file(case_dir / "reference_lmgc90" / "RUN.md");
  const auto line_start = run_md.find("script parameters");
  if (line_start == std::string::npos) return parameters;
  const std::string line = run_md.substr(line_start, run_md.find('\n', line_start) - line_start);
  const std::regex assignment("`(\\w+) = ([^`]+)`");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), assignment); it != std::sregex_iterator(); ++it) {
    std::string value = (*it)[2];
    value.erase(std::remove(value.begin(), value.end(), '\''), value.end());
    while (!value.empty() && value.back() == ' ') value.pop_back();
    parameters[(*it)[1]] = value;
  }
  return parameters;
}

struct ExampleRun {
  fs::path case_dir;  // scratch copy
  ToolRun run;
  long steps = 0;
};

// Copies the example's DATBOX to a scratch folder and runs lmgc-solve with its script's
// parameters (COMMAND.DAT is removed: LMGC90's reference run used command.py).
ExampleRun run_example(const fs::path& example, long step_cut) {
  ExampleRun result;
  const auto p = script_parameters(example);
  result.case_dir = scratch_dir("solve_" + example.filename().string());
  fs::copy(example / "DATBOX", result.case_dir / "DATBOX", fs::copy_options::recursive);
  fs::remove(result.case_dir / "DATBOX" / "COMMAND.DAT");
  result.steps = std::min(step_cut, std::stol(p.at("nb_steps")));
  std::string args = "'" + result.case_dir.string() + "' --quiet --steps " + std::to_string(result.steps);
  const std::pair<const char*, const char*> flags[] = {
      {"dt", "--dt"},         {"theta", "--theta"},   {"tol", "--tol"},
      {"relax", "--relax"},   {"gs_it1", "--gs-it1"}, {"gs_it2", "--gs-it2"},
      {"freq_write", "--write-every"}, {"lx", "--xperiod"}};
  for (const auto& [name, flag] : flags)
    if (p.count(name)) args += std::string(" ") + flag + " " + p.at(name);
  if (p.count("norm")) args += " --norm '" + p.at("norm") + "'";
  if (p.count("solver_type")) args += " --solver " + p.at("solver_type");
  // BouncingBallsDK's script calls RBDY2_SetYminBoundary(-0.).
  if (example.filename() == "BouncingBallsDK") args += " --ymin-boundary 0";
  result.run = run_tool("lmgc-solve", args);
  return result;
}

std::vector<fs::path> rigid_2d_examples() {
  std::vector<fs::path> cases;
  for (const auto& c : example_cases())
    if (c.parent_path().filename() == "RIGID_2D" && fs::exists(c / "reference_lmgc90" / "RUN.md")) cases.push_back(c);
  return cases;
}

grammar::DofFile read_dof(const fs::path& path) {
  grammar::DiagnosticSink sink;
  return grammar::parse_dof(grammar::SourceText(path.string(), read_file(path)), sink);
}

// Largest |X_ours - X_lmgc| over every body, relative to the largest |X_lmgc|.
double relative_position_difference(const grammar::DofFile& ours, const grammar::DofFile& lmgc) {
  std::vector<double> a, b;
  for (const auto* file : {&ours, &lmgc})
    for (const auto& section : file->sections)
      for (const auto& body : section.bodies)
        for (const auto& node : body.nodes)
          for (const auto& x : node.x) (file == &ours ? a : b).push_back(x.value);
  if (a.size() != b.size() || b.empty()) return INFINITY;
  double difference = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    difference = std::max(difference, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(b[k]));
  }
  return difference / std::max(scale, 1e-300);
}

TEST(LmgcSolveExamples, EveryRigid2DExampleRunsItsFirstStepsWithItsScriptParameters) {
  LMGC_REQUIRE_SHARED();
  const auto examples = rigid_2d_examples();
  ASSERT_GE(examples.size(), 7u);
  for (const auto& example : examples) {
    SCOPED_TRACE(case_name(example));
    const ExampleRun r = run_example(example, step_cut(example));
    ASSERT_EQ(r.run.exit_code, 0);
    EXPECT_TRUE(fs::is_regular_file(r.case_dir / "OUTBOX" / "DOF.LAST"));
    EXPECT_TRUE(fs::is_regular_file(r.case_dir / "OUTBOX" / "BODIES.OUT"));
    // One report line per step, each with a finite achieved residual.
    const std::string report = read_file(r.case_dir / "OUTBOX" / "run_report.csv");
    EXPECT_EQ(std::count(report.begin(), report.end(), '\n'), r.steps + 1);
    EXPECT_EQ(report.find("nan"), std::string::npos);
    EXPECT_EQ(report.find("inf"), std::string::npos);
    const grammar::DofFile last = read_dof(r.case_dir / "OUTBOX" / "DOF.LAST");
    EXPECT_EQ(last.step.value, r.steps);
  }
}

// The two deterministic examples (few bodies, converged solves) follow LMGC90's trajectory to
// 1e-8 relative over their first 200 steps, on every DOF.OUT.n LMGC90 kept for that span.
TEST(LmgcSolveExamples, BouncingBallsAndClusterFollowLmgc90To1e8OverTheFirst200Steps) {
  LMGC_REQUIRE_SHARED();
  for (const char* name : {"BouncingBallsDK", "clusterDKPL_GroundJC"}) {
    SCOPED_TRACE(name);
    const fs::path example = examples_dir() / "RIGID_2D" / name;
    const ExampleRun r = run_example(example, 200);
    ASSERT_EQ(r.run.exit_code, 0);
    int compared = 0;
    for (int n = 1;; ++n) {
      const fs::path ours = r.case_dir / "OUTBOX" / ("DOF.OUT." + std::to_string(n));
      if (!fs::exists(ours)) break;
      const fs::path lmgc = example / "reference_lmgc90" / "OUTBOX" / ours.filename();
      if (!fs::exists(lmgc)) continue;
      const grammar::DofFile a = read_dof(ours), b = read_dof(lmgc);
      EXPECT_EQ(a.step.value, b.step.value);
      EXPECT_LE(relative_position_difference(a, b), 1e-8) << ours.filename();
      ++compared;
    }
    EXPECT_GE(compared, 1);
  }
}

}  // namespace
}  // namespace lmgc::test
