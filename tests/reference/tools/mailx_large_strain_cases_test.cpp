// The large-strain reference cases (reference_cases/mailx_neo_hookean_stretch, mailx_adaptive_stretch,
// mailx_rotated_at_rest; README.md in each gives the expected values, their source and tolerance):
// run by lmgc-run through their own command.py (LMGC90's Newton loop), against the closed form of
// plane-strain uniaxial stress, frame invariance, and what LMGC90 2025 wrote running the same script
// (lmgc90_reference/): the same steps and time steps, DOF.LAST and GPV.LAST.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "grammar/gpv/parser.hpp"
#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

fs::path run_case(const std::string& name) {
  return run_reference_case(name, "mailx_" + name);
}

// The largest difference between our file and LMGC90's, over `scale`; -1 when the counts differ.
double difference_to_lmgc90(const std::string& name, const fs::path& dir, const char* file, double scale) {
  const fs::path reference = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / "lmgc90_reference";
  const std::vector<double> ours = fortran_numbers(read_file(dir / "OUTBOX" / file)),
                            theirs = fortran_numbers(read_file(reference / file));
  if (ours.empty() || ours.size() != theirs.size()) return -1.0;
  double d = 0.0;
  for (std::size_t k = 0; k < ours.size(); ++k) d = std::max(d, std::abs(ours[k] - theirs[k]));
  return d / scale;
}

std::string steps_log(const std::string& name, const fs::path& dir) {
  const std::string ours = read_file(dir / "steps.txt");
  EXPECT_EQ(ours, read_file(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / "lmgc90_reference" /
                            "steps.txt"))
      << name << ": the steps (number, h, iterations, ComputeTimeStep's state) differ from LMGC90's";
  return ours;
}

grammar::GpvFile gauss_point_values(const fs::path& dir) {
  grammar::DiagnosticSink sink(10);
  const fs::path path = dir / "OUTBOX" / "GPV.LAST";
  return grammar::parse_gpv(grammar::SourceText(path.string(), read_file(path)), sink);
}

// Plane-strain uniaxial stress at λ2 = 1.5 (μ = E/2(1 + ν), λ = E/3(1 − 2ν) − 2μ/3, E = 1e6 Pa, ν = 0.3):
// P11 = μλ1 + (λ ln J − μ)/λ1 = 0 gives λ1; then P22 = μλ2 + (λ ln J − μ)/λ2, P33 = λ ln J, W.
struct UniaxialStretch {
  double lambda1, p22, p33, energy;
};
UniaxialStretch uniaxial_stretch() {
  const double young = 1e6, poisson = 0.3, l2 = 1.5;
  const double mu = young / (2 * (1 + poisson)), lambda = young / (3 * (1 - 2 * poisson)) - 2 * mu / 3;
  const auto p11 = [&](double l1) { return mu * l1 + (lambda * std::log(l1 * l2) - mu) / l1; };
  double a = 0.5, b = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b);
    (p11(a) * p11(m) <= 0.0 ? b : a) = m;
  }
  const double l1 = 0.5 * (a + b), log_j = std::log(l1 * l2);
  return {l1, mu * l2 + (lambda * log_j - mu) / l2, lambda * log_j,
          0.5 * lambda * log_j * log_j - mu * log_j + 0.5 * mu * (l1 * l1 + l2 * l2 - 2)};
}

TEST(MailxLargeStrainCases, NeoHookeanStretchFollowsTheClosedFormAndLmgc90) {
  const std::string name = "mailx_neo_hookean_stretch";
  const fs::path dir = run_case(name);
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const UniaxialStretch expected = uniaxial_stretch();
  const grammar::GpvFile gpv = gauss_point_values(dir);
  ASSERT_EQ(gpv.bodies.size(), 1u);
  ASSERT_EQ(gpv.bodies[0].elements.size(), 4u);
  double worst = 0.0;
  for (const grammar::GpvElement& e : gpv.bodies[0].elements) {
    const auto& lines = e.models.at(0).lines;
    ASSERT_EQ(lines.size(), 12u);  // 4 points × (P, F, W)
    for (std::size_t p = 0; p < 4; ++p) {
      const auto& stress = lines[3 * p];
      const auto& gradient = lines[3 * p + 1];
      worst = std::max({worst, std::abs(stress[0].value) / expected.p22,
                        std::abs(stress[3].value - expected.p22) / expected.p22,
                        std::abs(stress[4].value - expected.p33) / expected.p22,
                        std::abs(gradient[0].value - expected.lambda1),
                        std::abs(lines[3 * p + 2][0].value - expected.energy) / expected.energy});
    }
  }
  // The 7 printed digits and the quasi-static run's inertia (ρ = 1 kg/m², h = 0.05 s, θ = 1).
  EXPECT_LT(worst, 1e-6);
  std::printf("largest relative difference to the closed form: %.1e\n", worst);
  steps_log(name, dir);
  EXPECT_EQ(read_file(dir / "OUTBOX" / "DOF.LAST"), read_file(fs::path(LMGC_SOURCE_DIR) / "reference_cases" /
                                                              name / "lmgc90_reference" / "DOF.LAST"));
  const double gpv_difference = difference_to_lmgc90(name, dir, "GPV.LAST", expected.p22);
  EXPECT_GE(gpv_difference, 0.0);
  EXPECT_LT(gpv_difference, 1e-9);
}

TEST(MailxLargeStrainCases, AdaptiveTimeStepCutsAndRecoversAsLmgc90s) {
  const std::string name = "mailx_adaptive_stretch";
  const fs::path dir = run_case(name);
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const std::string log = steps_log(name, dir);
  // The first step fails at h = 0.25 and is redone at 0.25/√2; two good steps grow it back to 0.25.
  EXPECT_NE(log.find("2.500000e-01 5 1"), std::string::npos) << log;
  EXPECT_NE(log.find("1.767767e-01 4 0"), std::string::npos) << log;
  EXPECT_EQ(read_file(dir / "OUTBOX" / "DOF.LAST"), read_file(fs::path(LMGC_SOURCE_DIR) / "reference_cases" /
                                                              name / "lmgc90_reference" / "DOF.LAST"));
  const double gpv_difference = difference_to_lmgc90(name, dir, "GPV.LAST", uniaxial_stretch().p22);
  EXPECT_GE(gpv_difference, 0.0);
  EXPECT_LT(gpv_difference, 1e-9);
}

TEST(MailxLargeStrainCases, RigidlyRotatedBodyAtRestHasNoStress) {
  const std::string name = "mailx_rotated_at_rest";
  const fs::path dir = run_case(name);
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const grammar::GpvFile gpv = gauss_point_values(dir);
  ASSERT_EQ(gpv.bodies.size(), 1u);
  double stress = 0.0, rotation = 0.0;
  for (const grammar::GpvElement& e : gpv.bodies[0].elements)
    for (std::size_t p = 0; p < 4; ++p) {
      const auto& lines = e.models.at(0).lines;
      for (const auto& v : lines[3 * p]) stress = std::max(stress, std::abs(v.value));
      // F is the rotation by 90°: (0, −1, 1, 0, 1).
      const double f[5] = {0.0, -1.0, 1.0, 0.0, 1.0};
      for (int k = 0; k < 5; ++k) rotation = std::max(rotation, std::abs(lines[3 * p + 1][k].value - f[k]));
    }
  // Round-off of E = 1e6 Pa (1e-15 relative per operation, a few hundred of them).
  EXPECT_LT(stress, 1e-8);
  EXPECT_LT(rotation, 1e-13);
  std::printf("largest stress %.1e Pa, F − R %.1e\n", stress, rotation);
  steps_log(name, dir);
  // LMGC90's state is at round-off too: displacements within 1e-14 of the body's size.
  const double dof_difference = difference_to_lmgc90(name, dir, "DOF.LAST", 1.0);
  EXPECT_GE(dof_difference, 0.0);
  EXPECT_LT(dof_difference, 1e-12);
}

}  // namespace
}  // namespace lmgc::test

namespace lmgc::test {
namespace {

// The stretch case with its command.py edited by `edits` ((what, by what) pairs) and its DRV_DOF.DAT
// top velocity replaced by `top_velocity`.
fs::path edited_stretch(const std::string& tag, std::vector<std::pair<std::string, std::string>> edits,
                        const std::string& top_velocity = "") {
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "mailx_neo_hookean_stretch";
  const fs::path dir = scratch_dir("mailx_stretch_" + tag);
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(source / entry, dir / entry, fs::copy_options::recursive);
  std::string script = read_file(dir / "command.py");
  for (const auto& [what, by] : edits) {
    const auto at = script.find(what);
    EXPECT_NE(at, std::string::npos) << what;
    if (at != std::string::npos) script.replace(at, what.size(), by);
  }
  std::ofstream(dir / "command.py") << script;
  if (!top_velocity.empty()) {
    std::string driven = read_file(dir / "DATBOX" / "DRV_DOF.DAT");
    for (std::size_t at; (at = driven.find(" 0.5000000D+00")) != std::string::npos;)
      driven.replace(at, 14, top_velocity);
    std::ofstream(dir / "DATBOX" / "DRV_DOF.DAT") << driven;
  }
  return dir;
}

// A Newton loop that cannot converge at the smallest time step ends lmgc-run with exit code 7, the
// message naming the step, and DOF.LAST and GPV.LAST of the last converged step.
TEST(MailxLargeStrainCases, NewtonLoopThatCannotConvergeEndsWithItsExitCodeAndLastGoodFiles) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  // Converges for 3 steps, then an impossible tolerance from step 4.
  const fs::path dir = edited_stretch(
      "diverging",
      {{"chipy.NewtonRaphson_Initialize(1e-10)",
        "chipy.NewtonRaphson_Initialize(1e-10 if chipy.TimeEvolution_GetStep() < 4 else 1e-300)"}});
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "'");
  EXPECT_EQ(run.exit_code, 7) << run.output;
  EXPECT_NE(run.output.find("step 4"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("did not converge"), std::string::npos) << run.output;
  const std::string dof = read_file(dir / "OUTBOX" / "DOF.LAST");
  EXPECT_NE(dof.find("time= 0.1500000D+00"), std::string::npos) << dof.substr(0, 200);  // step 3's
  EXPECT_NE(read_file(dir / "OUTBOX" / "GPV.LAST").find("time= 0.1500000D+00"), std::string::npos);
}

// The top driven down through the bottom in one step inverts the elements: the run names the element
// and its Gauss point; the adaptive step cuts h until the step converges (the minimum allows it).
TEST(MailxLargeStrainCases, InvertedElementIsNamedAndTheStepIsRedoneSmaller) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path dir = edited_stretch(
      "inverted",
      {{"chipy.NewtonRaphson_SetMinTimeStep(0.05)", "chipy.NewtonRaphson_SetMinTimeStep(1e-4)"},
       {"chipy.NewtonRaphson_SetFinalTime(1.0)", "chipy.NewtonRaphson_SetFinalTime(0.02)"}},
      "-0.3000000D+02");
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("is inverted (det F <= 0)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("MAILx body 1, element "), std::string::npos) << run.output;
  const std::string log = read_file(dir / "steps.txt");
  EXPECT_NE(log.find(" 1\n"), std::string::npos) << log;  // a step redone
  EXPECT_NE(log.find(" 2\n"), std::string::npos) << log;  // and the run ends at its final time
  // Without a Newton loop (one pass per step) the run stops at once, naming them.
  const fs::path plain =
      edited_stretch("inverted_plain",
                     {{"  chipy.NewtonRaphson_Initialize(1e-10)\n", ""},
                      {"if k > 1:", "if False:"},
                      {"istate = chipy.NewtonRaphson_ComputeTimeStep()", "istate = 0; is_converged = 0"}},
                     "-0.3000000D+02");
  const ToolRun stopped = run_tool_both_streams("lmgc-run", "'" + plain.string() + "'");
  EXPECT_NE(stopped.exit_code, 0);
  EXPECT_NE(stopped.output.find("is inverted (det F <= 0)"), std::string::npos) << stopped.output;
}

}  // namespace
}  // namespace lmgc::test

namespace lmgc::test {
namespace {

// reference_cases/mailx_j2_traction_{linear,swift}: LMGC90's own J2 plasticity on Q4P0x stretched by
// 20 % in plane strain. Every Gauss point of GPV.LAST is on or inside its yield surface: q = σ_y(p) to
// 1.5e-7 where it yielded in the last step (half a unit of q's 7th printed digit, 6.8e-8, plus p's
// through σ_y', up to 4.7e-8; the return mapping stops at 1e-10), q < σ_y(p) elsewhere; the body has yielded
// (p > 1 %); steps, DOF.LAST and GPV.LAST as LMGC90 2025 wrote them.
void expect_on_the_yield_surface(const std::string& name, double (*yield)(double)) {
  const fs::path dir = run_case(name);
  if (dir.empty()) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const grammar::GpvFile gpv = gauss_point_values(dir);
  ASSERT_EQ(gpv.bodies.size(), 1u);
  int on_surface = 0;
  double largest_p = 0.0;
  for (const grammar::GpvElement& e : gpv.bodies[0].elements) {
    const auto& lines = e.models.at(0).lines;
    ASSERT_EQ(lines.size(), 12u);  // 4 points × (σ, zero strain, 6 internal variables)
    for (std::size_t g = 0; g < 4; ++g) {
      const auto& internal = lines[3 * g + 2];
      ASSERT_EQ(internal.size(), 6u);
      const double p = internal[4].value, q = internal[5].value, sigma_y = yield(p);
      largest_p = std::max(largest_p, p);
      EXPECT_LE(q, sigma_y * (1.0 + 1.5e-7)) << name << " point " << g;
      if (q >= sigma_y * (1.0 - 1.5e-7)) ++on_surface;
    }
  }
  EXPECT_GT(largest_p, 0.01);
  EXPECT_GT(on_surface, 0);
  std::printf("%s: %d of 16 points on the yield surface, largest p %.4f\n", name.c_str(), on_surface,
              largest_p);
  steps_log(name, dir);
  const fs::path reference = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / name / "lmgc90_reference";
  for (const char* file : {"DOF.LAST", "GPV.LAST"})
    EXPECT_EQ(read_file(dir / "OUTBOX" / file), read_file(reference / file)) << name << ": " << file;
}

TEST(MailxLargeStrainCases, J2TractionWithLinearHardeningStaysOnItsYieldSurface) {
  expect_on_the_yield_surface("mailx_j2_traction_linear", [](double p) { return 2e3 + 1e4 * p; });
}

TEST(MailxLargeStrainCases, J2TractionWithSwiftHardeningStaysOnItsYieldSurface) {
  expect_on_the_yield_surface("mailx_j2_traction_swift",
                              [](double p) { return 1e4 * std::pow(0.01 + p, 0.2); });
}

}  // namespace
}  // namespace lmgc::test
