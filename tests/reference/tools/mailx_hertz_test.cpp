// reference_cases/mailx_hertz_cylinder (its README.md gives the expected values, their source and
// the tolerance): an elastic half-cylinder pressed on a rigid plane, run by lmgc-run through its own
// command.py; the contact half-width and the peak pressure against Hertz's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

TEST(MailxHertz, ContactHalfWidthAndPeakPressureFollowHertz) {
  if (!fs::exists(tool_path("lmgc-run"))) GTEST_SKIP() << "this build has no Python module (lmgc-run)";
  const fs::path source = fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "mailx_hertz_cylinder";
  const fs::path dir = scratch_dir("mailx_hertz_cylinder");
  for (const char* entry : {"DATBOX", "command.py"})
    fs::copy(source / entry, dir / entry, fs::copy_options::recursive);
  const ToolRun run = run_tool_both_streams("lmgc-run", "'" + dir.string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;

  const double R = 0.1, E = 1e8, nu = 0.3, P = 86300.0;
  const double e_star = E / (1.0 - nu * nu);
  const double a = std::sqrt(4.0 * P * R / (M_PI * e_star)), p0 = 2.0 * P / (M_PI * a);

  // (x, normal force) of every contact point, by x.
  std::vector<std::pair<double, double>> points;
  for (const grammar::VlocRlocInteraction& i :
       read_vloc_rloc(dir / "OUTBOX" / "Vloc_Rloc.LAST").interactions) {
    double x = 0.0, force = 0.0;
    for (const grammar::VlocRlocVector& v : i.vectors)
      for (std::size_t k = 0; k < v.labels.size() && k < v.values.size(); ++k) {
        if (v.labels[k] == "rln/H") force = v.values[k].value;
        if (v.labels[k] == "coo1=") x = v.values[k].value;
      }
    points.emplace_back(x, force);
  }
  ASSERT_EQ(points.size(), 62u);
  std::sort(points.begin(), points.end());
  double total = 0.0;
  for (const auto& [x, f] : points) total += f;
  EXPECT_NEAR(total, P, 1e-6 * P);  // quasi-static: the plane carries the load

  // Pressure: force over the point's share of the rim; least squares of p² = A + B x².
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0, peak = 0;
  int loaded = 0;
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    if (points[k].second <= 0.0) continue;
    const double p = points[k].second / (0.5 * (points[k + 1].first - points[k - 1].first));
    const double x2 = points[k].first * points[k].first;
    s0 += 1, s1 += x2, s2 += x2 * x2, t0 += p * p, t1 += p * p * x2;
    peak = std::max(peak, p);
    ++loaded;
  }
  const double B = (s0 * t1 - s1 * t0) / (s0 * s2 - s1 * s1), A = (t0 - B * s1) / s0;
  const double a_fit = std::sqrt(-A / B), p0_fit = std::sqrt(A);
  std::printf(
      "Hertz a = %.4e m, p0 = %.4e Pa; measured a = %.4e m (%+.2f %%), p0 = %.4e Pa (%+.2f %%), %d points\n",
      a, p0, a_fit, 100.0 * (a_fit / a - 1.0), p0_fit, 100.0 * (p0_fit / p0 - 1.0), loaded);
  EXPECT_NEAR(a_fit, a, 0.05 * a);
  EXPECT_NEAR(p0_fit, p0, 0.05 * p0);
  EXPECT_GT(loaded, 20);
}

}  // namespace
}  // namespace lmgc::test
