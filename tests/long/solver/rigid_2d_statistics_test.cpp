// The granular RIGID_2D examples, run for as many steps as LMGC90's reference run made, agree with
// LMGC90 statistically: at the last step the number of interactions and of active ones (mean
// coordination = 2 × active ÷ bodies) within 5 %, and the kinetic energy averaged over the
// DOF.OUT.n snapshots both runs wrote (a single instant of a granular flow is chaotic) within
// 5 % (or 1e-9 J for a packing at rest). Label `long`: minutes of runs, not part of CI's suite.
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

// Kinetic energy of the bodies of a DOF file, with the scene's masses and inertias [J].
double kinetic_energy(const fs::path& dof_path, const solver::Scene2D& scene) {
  grammar::DiagnosticSink sink;
  const auto dof = grammar::parse_dof(grammar::SourceText(dof_path.string(), read_file(dof_path)), sink);
  double energy = 0.0;
  std::size_t i = 0;
  for (const auto& section : dof.sections)
    for (const auto& body : section.bodies) {
      if (i >= scene.bodies.size() || body.nodes.empty() || body.nodes[0].v.size() < 3) continue;
      const auto& v = body.nodes[0].v;
      energy += 0.5 * scene.bodies.mass[i] * (v[0].value * v[0].value + v[1].value * v[1].value) +
                0.5 * scene.bodies.inertia[i] * v[2].value * v[2].value;
      ++i;
    }
  return energy;
}

struct LastStepStatistics {
  double interactions = 0, active = 0, kinetic_energy = 0;
};

LastStepStatistics statistics(const fs::path& outbox, const solver::Scene2D& scene) {
  LastStepStatistics s;
  grammar::DiagnosticSink sink;
  // LMGC90's large reference files are stored gzip-compressed.
  const fs::path vloc_path =
      fs::exists(outbox / "Vloc_Rloc.LAST") ? outbox / "Vloc_Rloc.LAST" : outbox / "Vloc_Rloc.LAST.gz";
  const auto vloc =
      grammar::parse_vloc_rloc(grammar::SourceText("Vloc_Rloc.LAST", read_maybe_gzip(vloc_path)), sink);
  for (const auto& interaction : vloc.interactions) {
    ++s.interactions;
    if (!interaction.vectors.empty() && interaction.vectors[0].values.size() >= 2 &&
        interaction.vectors[0].values[1].value != 0.0)
      ++s.active;
  }
  s.kinetic_energy = kinetic_energy(outbox / "DOF.LAST", scene);
  return s;
}

TEST(Rigid2DStatistics, GranularExamplesAgreeWithLmgc90Within5PercentAtTheirLastStep) {
  LMGC_REQUIRE_SHARED();
  for (const char* name :
       {"1024DK_BoxJC", "200DK_BoxJC_MD", "500PL_PerioBoxJC", "siloDK_hoperJC", "BridgePL_GroundJC"}) {
    SCOPED_TRACE(name);
    const fs::path example = examples_dir() / "RIGID_2D" / name;
    const ExampleRun r = run_example(example, reference_steps_run(example), "long_");
    ASSERT_EQ(r.run.exit_code, 0);
    grammar::DiagnosticSink sink;
    const auto files = case_folder::load_case(r.case_dir, sink);
    ASSERT_TRUE(files.has_value());
    solver::Scene2D scene;
    solver::RunOutputs2D outputs;
    ASSERT_TRUE(solver::prepare_run_2d(*files, scene, outputs, sink));
    const LastStepStatistics ours = statistics(r.case_dir / "OUTBOX", scene);
    const LastStepStatistics lmgc = statistics(example / "reference_lmgc90" / "OUTBOX", scene);
    const double bodies = static_cast<double>(scene.bodies.size());
    std::printf("%-20s interactions %6.0f / %6.0f   coordination %.3f / %.3f   kinetic energy %.4e / %.4e\n",
                name, ours.interactions, lmgc.interactions, 2 * ours.active / bodies,
                2 * lmgc.active / bodies, ours.kinetic_energy, lmgc.kinetic_energy);
    EXPECT_NEAR(ours.interactions, lmgc.interactions, 0.05 * lmgc.interactions);
    EXPECT_NEAR(ours.active, lmgc.active, 0.05 * lmgc.active);
    double ours_mean = ours.kinetic_energy, lmgc_mean = lmgc.kinetic_energy;
    int snapshots = 1;
    for (int n = 1;; ++n) {
      const fs::path a = r.case_dir / "OUTBOX" / ("DOF.OUT." + std::to_string(n));
      if (!fs::exists(a)) break;
      const fs::path b = example / "reference_lmgc90" / "OUTBOX" / a.filename();
      if (!fs::exists(b)) continue;
      ours_mean += kinetic_energy(a, scene);
      lmgc_mean += kinetic_energy(b, scene);
      ++snapshots;
    }
    ours_mean /= snapshots;
    lmgc_mean /= snapshots;
    std::printf("%-20s mean kinetic energy over %d snapshots %.4e / %.4e\n", name, snapshots, ours_mean,
                lmgc_mean);
    EXPECT_NEAR(ours_mean, lmgc_mean, std::max(0.05 * lmgc_mean, 1e-9));
  }
}

}  // namespace
}  // namespace lmgc::test
