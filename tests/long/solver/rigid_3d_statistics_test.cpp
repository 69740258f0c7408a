// 945_SP_Box_PL, run for the 160 steps LMGC90's reference run made, agrees with LMGC90
// statistically: at the last step the numbers of interactions and of active ones within 5 %, and
// the kinetic energy averaged over the DOF.OUT.n snapshots both runs kept within 5 % (a single
// instant of a granular flow is chaotic). Label `long`: about a minute, not part of CI's suite.
#include <gtest/gtest.h>

#include <cmath>

#include "grammar/dof/parser.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "solver/driver/case_input.hpp"
#include "tests/support/gzip.hpp"
#include "tests/support/lmgc90_reference_runs.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

fs::path plain_or_gzip(const fs::path& path) {
  return fs::exists(path) ? path : fs::path(path.string() + ".gz");
}

// ½ m |v|² + ½ Σ I_i ω_i² of the bodies of a DOF file, with the scene's masses and inertias [J].
double kinetic_energy(const fs::path& dof_path, const solver::Scene3D& scene) {
  grammar::DiagnosticSink sink;
  const auto dof =
      grammar::parse_dof(grammar::SourceText(dof_path.string(), read_maybe_gzip(dof_path)), sink);
  double energy = 0.0;
  std::size_t i = 0;
  for (const auto& section : dof.sections)
    for (const auto& body : section.bodies) {
      if (i >= scene.bodies.size() || body.nodes.empty() || body.nodes[0].v.size() < 6) continue;
      const auto& v = body.nodes[0].v;
      for (int d = 0; d < 3; ++d) {
        energy += 0.5 * scene.bodies.mass[i] * v[static_cast<std::size_t>(d)].value *
                  v[static_cast<std::size_t>(d)].value;
        energy += 0.5 * scene.bodies.inertia[i](d) * v[static_cast<std::size_t>(d + 3)].value *
                  v[static_cast<std::size_t>(d + 3)].value;
      }
      ++i;
    }
  return energy;
}

struct LastStep {
  double interactions = 0, active = 0;
};

LastStep last_step(const fs::path& outbox) {
  LastStep s;
  grammar::DiagnosticSink sink;
  const auto vloc = grammar::parse_vloc_rloc(
      grammar::SourceText("Vloc_Rloc.LAST", read_maybe_gzip(plain_or_gzip(outbox / "Vloc_Rloc.LAST"))), sink);
  for (const auto& interaction : vloc.interactions) {
    ++s.interactions;
    // 3D reaction line: rls/H rlt/H rln/H.
    if (!interaction.vectors.empty() && interaction.vectors[0].values.size() >= 3 &&
        interaction.vectors[0].values[2].value != 0.0)
      ++s.active;
  }
  return s;
}

TEST(Rigid3DStatistics, SpheresInABoxAgreeWithLmgc90Within5PercentAtTheLastStep) {
  LMGC_REQUIRE_SHARED();
  const fs::path example = examples_dir() / "RIGID_3D" / "945_SP_Box_PL";
  const ExampleRun r = run_example(example, reference_steps_run(example), "long_");
  ASSERT_EQ(r.run.exit_code, 0);
  grammar::DiagnosticSink sink;
  const auto files = case_folder::load_case(r.case_dir, sink);
  ASSERT_TRUE(files.has_value());
  solver::Scene3D scene;
  solver::RunOutputs3D outputs;
  ASSERT_TRUE(solver::prepare_run_3d(*files, scene, outputs, sink));
  const fs::path ours_outbox = r.case_dir / "OUTBOX", lmgc_outbox = example / "reference_lmgc90" / "OUTBOX";
  const LastStep ours = last_step(ours_outbox), lmgc = last_step(lmgc_outbox);
  std::printf("945_SP_Box_PL interactions %.0f / %.0f, active %.0f / %.0f\n", ours.interactions,
              lmgc.interactions, ours.active, lmgc.active);
  EXPECT_NEAR(ours.interactions, lmgc.interactions, 0.05 * lmgc.interactions);
  EXPECT_NEAR(ours.active, lmgc.active, 0.05 * lmgc.active);
  double ours_mean = 0.0, lmgc_mean = 0.0;
  int snapshots = 0;
  for (int n = 1;; ++n) {
    const fs::path a = ours_outbox / ("DOF.OUT." + std::to_string(n));
    if (!fs::exists(a)) break;
    const fs::path b = plain_or_gzip(lmgc_outbox / a.filename());
    if (!fs::exists(b)) continue;
    ours_mean += kinetic_energy(a, scene);
    lmgc_mean += kinetic_energy(b, scene);
    ++snapshots;
  }
  ASSERT_GE(snapshots, 3);
  ours_mean /= snapshots;
  lmgc_mean /= snapshots;
  std::printf("945_SP_Box_PL mean kinetic energy over %d snapshots %.4e / %.4e\n", snapshots, ours_mean,
              lmgc_mean);
  EXPECT_NEAR(ours_mean, lmgc_mean, 0.05 * lmgc_mean);
}

}  // namespace
}  // namespace lmgc::test
