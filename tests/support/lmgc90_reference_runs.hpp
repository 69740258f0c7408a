#pragma once
// Running lmgc-solve on an LMGC90 example the way LMGC90's reference run was made: the literal
// parameters of its command.py as reference_lmgc90/RUN.md records them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "grammar/dof/parser.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {

// The numbers of a file LMGC90 writes (mantissa with a D or E exponent), in order.
inline std::vector<double> fortran_numbers(const std::string& text) {
  static const std::regex number(R"([-+]?\d*\.\d+[DE][-+]\d+)");
  std::vector<double> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
    std::string t = it->str();
    for (char& ch : t)
      if (ch == 'D') ch = 'E';
    out.push_back(std::stod(t));
  }
  return out;
}

// reference_cases/<name> (its DATBOX and command.py) run by lmgc-run in scratch_dir(tag): the run's
// folder, or an empty path when the build has no lmgc-run. The run must exit 0.
inline std::filesystem::path run_reference_case(const std::string& name, const std::string& tag) {
  namespace fs = std::filesystem;
  if (!fs::exists(tool_path("lmgc-run"))) return {};
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name;
  const fs::path dir = scratch_dir(tag);
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(source / entry, dir / entry, fs::copy_options::recursive);
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return dir;
}

// The literal assignments of command.py, as RUN.md lists them ("`dt = 0.0005`, `nb_steps = ...`").
inline std::map<std::string, std::string> script_parameters(const std::filesystem::path& case_dir) {
  std::map<std::string, std::string> parameters;
  const std::string run_md = read_file(case_dir / "reference_lmgc90" / "RUN.md");
  const auto line_start = run_md.find("script parameters");
  if (line_start == std::string::npos) return parameters;
  const std::string line = run_md.substr(line_start, run_md.find('\n', line_start) - line_start);
  const std::regex assignment("`(\\w+) = ([^`]+)`");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), assignment); it != std::sregex_iterator();
       ++it) {
    std::string value = (*it)[2];
    value.erase(std::remove(value.begin(), value.end(), '\''), value.end());
    while (!value.empty() && value.back() == ' ') value.pop_back();
    parameters[(*it)[1]] = value;
  }
  return parameters;
}

// The number of steps LMGC90's reference run made (RUN.md "| steps run | 930 (...) |").
inline long reference_steps_run(const std::filesystem::path& case_dir) {
  const std::string run_md = read_file(case_dir / "reference_lmgc90" / "RUN.md");
  std::smatch m;
  if (!std::regex_search(run_md, m, std::regex("\\| steps run \\| (\\d+)"))) return 0;
  return std::stol(m[1]);
}

struct ExampleRun {
  std::filesystem::path case_dir;  // scratch copy
  ToolRun run;
  long steps = 0;
};

// Copies the example's DATBOX to a scratch folder and runs lmgc-solve for `steps` steps with its
// script's parameters (COMMAND.DAT is removed: LMGC90's reference run used command.py).
// `tag` keeps the scratch folders of tests that run the same example apart (ctest runs tests in
// parallel).
// A RIGID_3D example (its BODIES.DAT holds RBDY3 bodies).
inline bool dimension3(const std::filesystem::path& example) {
  return read_file(example / "DATBOX" / "BODIES.DAT").find("RBDY3") != std::string::npos;
}

// `extra` is appended to the command line (flags override the script's).
inline ExampleRun run_example(const std::filesystem::path& example, long steps, const std::string& tag = "",
                              const std::string& extra = "") {
  namespace fs = std::filesystem;
  ExampleRun result;
  const auto p = script_parameters(example);
  result.case_dir = scratch_dir("solve_" + tag + example.filename().string());
  fs::copy(example / "DATBOX", result.case_dir / "DATBOX", fs::copy_options::recursive);
  fs::remove(result.case_dir / "DATBOX" / "COMMAND.DAT");
  result.steps = p.count("nb_steps") ? std::min(steps, std::stol(p.at("nb_steps"))) : steps;
  std::string args = "'" + result.case_dir.string() + "' --quiet --steps " + std::to_string(result.steps);
  const std::pair<const char*, const char*> flags[] = {{"dt", "--dt"},
                                                       {"theta", "--theta"},
                                                       {"tol", "--tol"},
                                                       {"relax", "--relax"},
                                                       {"gs_it1", "--gs-it1"},
                                                       {"gs_it2", "--gs-it2"},
                                                       {"freq_write", "--write-every"},
                                                       {"lx", "--xperiod"}};
  for (const auto& [name, flag] : flags)
    if (p.count(name)) args += std::string(" ") + flag + " " + p.at(name);
  if (p.count("norm")) args += " --norm '" + p.at("norm") + "'";
  if (p.count("solver_type")) args += " --solver " + p.at("solver_type");
  // RBDY3 scripts may switch to the Cayley frame update, and set periodic sides and a source point
  // with script variables or literals as arguments.
  {
    std::istringstream script(read_file(example / "command.py"));
    std::string line;
    const auto call_arguments = [&](const std::string& call) {
      std::vector<std::string> values;
      const std::size_t open = line.find('('), close = line.rfind(')');
      if (line.rfind(call, 0) != 0 || open == std::string::npos || close == std::string::npos) return values;
      std::istringstream list(line.substr(open + 1, close - open - 1));
      for (std::string item; std::getline(list, item, ',');) {
        item.erase(0, item.find_first_not_of(' '));
        item.erase(item.find_last_not_of(' ') + 1);
        values.push_back(p.count(item) ? p.at(item) : item);
      }
      return values;
    };
    while (std::getline(script, line)) {
      if (line.rfind("chipy.RBDY3_NewRotationScheme()", 0) == 0) args += " --new-rotation-scheme";
      if (line.rfind("chipy.nlgs_3D_DiagonalResolution()", 0) == 0) args += " --diagonal-resolution";
      // At the top level or under the scripts' `if "--norand" not in sys.argv:` (LMGC90's reference
      // runs ran the scripts unchanged, so scrambled).
      const std::size_t indent = line.find_first_not_of(' ');
      if (indent != std::string::npos &&
          (line.compare(indent, 32, "chipy.nlgs_SetWithQuickScramble(") == 0 ||
           line.compare(indent, 35, "chipy.nlgs_3D_SetWithQuickScramble(") == 0))
        args += " --quick-scramble";
      if (const auto v = call_arguments("chipy.SetPeriodicCondition("); v.size() == 2 && dimension3(example))
        args += " --xperiod " + v[0] + " --yperiod " + v[1];
      if (const auto v = call_arguments("chipy.RBDY3_SetSourcePointWithIni("); v.size() == 5)
        args += " --source-point " + v[0] + "," + v[1] + "," + v[2] + "," + v[3] + "," + v[4];
    }
  }
  // BouncingBallsDK's script calls RBDY2_SetYminBoundary(-0.).
  if (example.filename() == "BouncingBallsDK") args += " --ymin-boundary 0";
  if (!extra.empty()) args += " " + extra;
  result.run = run_tool("lmgc-solve", args);
  return result;
}

// A DOF or Vloc_Rloc file of a run or of LMGC90's reference, parsed.
inline grammar::DofFile read_dof(const std::filesystem::path& path) {
  grammar::DiagnosticSink sink;
  return grammar::parse_dof(grammar::SourceText(path.string(), read_file(path)), sink);
}

inline grammar::VlocRlocFile read_vloc_rloc(const std::filesystem::path& path) {
  grammar::DiagnosticSink sink;
  return grammar::parse_vloc_rloc(grammar::SourceText(path.string(), read_file(path)), sink);
}

// The X values of every body node of a DOF file, the first `dofs` of each node.
inline std::vector<double> node_displacements(const grammar::DofFile& file,
                                              std::size_t dofs = std::numeric_limits<std::size_t>::max()) {
  std::vector<double> x;
  for (const auto& section : file.sections)
    for (const auto& body : section.bodies)
      for (const auto& node : body.nodes)
        for (std::size_t d = 0; d < dofs && d < node.x.size(); ++d) x.push_back(node.x[d].value);
  return x;
}

// Largest |X_ours - X_lmgc| over the first `dofs` of every node (infinite when the files do not hold
// the same bodies), and the largest |X_lmgc|.
struct PositionDifference {
  double largest = INFINITY;
  double scale = 0.0;
};
inline PositionDifference position_difference(const grammar::DofFile& ours, const grammar::DofFile& lmgc,
                                              std::size_t dofs = std::numeric_limits<std::size_t>::max()) {
  const std::vector<double> a = node_displacements(ours, dofs), b = node_displacements(lmgc, dofs);
  PositionDifference out;
  if (a.size() != b.size() || b.empty()) return out;
  out.largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    out.largest = std::max(out.largest, std::abs(a[k] - b[k]));
    out.scale = std::max(out.scale, std::abs(b[k]));
  }
  return out;
}

// Largest |X_ours - X_lmgc| over every body, relative to the largest |X_lmgc| (infinite when the
// files do not hold the same bodies).
inline double relative_position_difference(const grammar::DofFile& ours, const grammar::DofFile& lmgc) {
  const PositionDifference d = position_difference(ours, lmgc);
  return d.largest / std::max(d.scale, 1e-300);
}

inline std::vector<std::filesystem::path> rigid_examples(const std::string& family) {
  std::vector<std::filesystem::path> cases;
  for (const auto& c : example_cases())
    if (c.parent_path().filename() == family && std::filesystem::exists(c / "reference_lmgc90" / "RUN.md"))
      cases.push_back(c);
  return cases;
}

inline std::vector<std::filesystem::path> rigid_2d_examples() {
  return rigid_examples("RIGID_2D");
}

}  // namespace lmgc::test
