// LMGC90's example mecaMAILx_2D/1Q4-traction (one Q4xxx, large strain in the total Lagrangian form,
// MatLib's neo-Hookean material, stretched by driven velocities through 10000 steps of LMGC90's
// Newton loop and adaptive time step) run to its end through its own command.py by lmgc-run, against
// what LMGC90 2025 (built with MatLib) wrote (../shared/.../reference_lmgc90/).
//
// Tolerance: 1e-6 of the largest value of each file (the issue's figure for a deterministic case
// without contact). Both codes run the same formulas in another order: measured DOF 0 (every printed
// digit equal), GPV 1.2e-16, Dep and Fint EVOLUTION 1.0e-12 and 1.6e-10 of their scales (the residue columns
// are round-off in both codes).
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <sstream>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

std::vector<double> numbers(const std::string& text) {
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

std::string gunzip(const fs::path& path) {
  std::string text;
  FILE* pipe = popen(("gzip -dc '" + path.string() + "'").c_str(), "r");
  if (!pipe) return text;
  char buffer[65536];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
  pclose(pipe);
  return text;
}

// The largest difference over the file's largest value; -1 when the counts differ.
double relative_difference(const std::string& ours_text, const std::string& theirs_text) {
  const std::vector<double> ours = numbers(ours_text), theirs = numbers(theirs_text);
  if (ours.size() != theirs.size()) return -1.0;
  double scale = 0.0, difference = 0.0;
  for (double v : theirs) scale = std::max(scale, std::abs(v));
  for (std::size_t k = 0; k < ours.size(); ++k)
    difference = std::max(difference, std::abs(ours[k] - theirs[k]));
  return scale > 0.0 ? difference / scale : difference;
}

TEST(MailxLargeStrainExample, OneQ4TractionRunsToItsEndAndAgreesWithLmgc90) {
  LMGC_REQUIRE_SHARED();
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = examples_dir() / "mecaMAILx_2D" / "1Q4-traction";
  const fs::path reference = source / "reference_lmgc90";
  const fs::path dir = scratch_dir("mailx_1q4_traction");
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(source / entry, dir / entry, fs::copy_options::recursive);
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;

  int compared = 0;
  std::map<std::string, double> worst;
  for (const auto& entry : fs::directory_iterator(reference / "OUTBOX")) {
    const std::string name = entry.path().filename().string();
    const std::string kind = name.substr(0, name.find('.'));
    if (name.find(".OUT.") == std::string::npos) continue;
    ASSERT_TRUE(fs::exists(dir / "OUTBOX" / name)) << name;
    const double d = relative_difference(read_file(dir / "OUTBOX" / name), read_file(entry.path()));
    EXPECT_GE(d, 0.0) << name << ": not the same count of values";
    EXPECT_LE(d, 1e-6) << name;
    worst[kind] = std::max(worst[kind], d);
    ++compared;
  }
  EXPECT_EQ(compared, 300);  // every numbered DOF, GPV and Vloc_Rloc file LMGC90 wrote (100 each)
  // POSTPRO: Dep EVOLUTION and Fint EVOLUTION of the two node sets, every step.
  for (const char* name : {"Dep_0000001.DAT", "Dep_0000002.DAT", "Fint_0000001.DAT", "Fint_0000002.DAT"}) {
    const fs::path plain = reference / "POSTPRO" / name,
                   zipped = reference / "POSTPRO" / (std::string(name) + ".gz");
    const std::string theirs = fs::exists(plain) ? read_file(plain) : gunzip(zipped);
    ASSERT_FALSE(theirs.empty()) << name;
    const std::string ours = read_file(dir / "POSTPRO" / name);
    EXPECT_EQ(std::count(ours.begin(), ours.end(), '\n'), 10000) << name;
    const double d = relative_difference(ours, theirs);
    EXPECT_GE(d, 0.0) << name;
    EXPECT_LE(d, 1e-6) << name;
    worst[std::string(name).substr(0, 3)] = std::max(worst[std::string(name).substr(0, 3)], d);
  }
  for (const auto& [kind, w] : worst)
    std::printf("%s: largest difference %.2e of the file's scale\n", kind.c_str(), w);
}

}  // namespace
}  // namespace lmgc::test
