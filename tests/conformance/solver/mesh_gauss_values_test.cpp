// LMGC90's Gauss-point values of mecaMAILx_RIGID_2D/4cubes (reference_lmgc90/OUTBOX/GPV.LAST, MatLib's
// layout: σ (xx, xy, yy, zz), ε (xx, γxy, yy, zz), energy) recomputed from its DOF.LAST displacements
// by lmgc's elements (solver/io/mesh_gauss_values.hpp): the same layout, and the same values within
// what DOF.LAST's seven digits allow. The displacements carry the bodies' rigid motion, so an
// absolute error of half a unit of their 7th digit (δX ≤ 5e-8 |X|max) on nodes a distance ℓ apart
// gives strains within δX/ℓ; the stresses within E times that. Measured: 648 values, the largest
// relative difference 2.2e-4 (on the smallest strains, where the 7th digit of X weighs most).
#include "solver/io/mesh_gauss_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "grammar/dof/parser.hpp"
#include "grammar/gpv/parser.hpp"
#include "solver/model/mesh_bodies.hpp"
#include "tests/support/lmgc90_reference_runs.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::solver {
namespace {

TEST(MeshGaussValues, FourCubesGpvLastFollowsFromItsDofLast) {
  LMGC_REQUIRE_SHARED();
  const auto example = test::examples_dir() / "mecaMAILx_RIGID_2D" / "4cubes";
  grammar::DiagnosticSink sink(100);
  const auto files = case_folder::load_case(example, sink);
  ASSERT_TRUE(files);
  MeshBodies meshes;
  ASSERT_TRUE(build_mesh_bodies(*files, fem::Hypothesis::plane_strain, meshes, sink));
  const grammar::DofFile dof = test::read_dof(example / "reference_lmgc90" / "OUTBOX" / "DOF.LAST");
  const auto path = example / "reference_lmgc90" / "OUTBOX" / "GPV.LAST";
  const grammar::GpvFile gpv =
      grammar::parse_gpv(grammar::SourceText(path.string(), test::read_file(path)), sink);
  ASSERT_EQ(gpv.bodies.size(), meshes.bodies.size());
  std::vector<const grammar::DofBody*> mailx;
  for (const auto& section : dof.sections)
    for (const auto& body : section.bodies)
      if (body.body_type.value == "MAILx") mailx.push_back(&body);
  ASSERT_EQ(mailx.size(), meshes.bodies.size());
  int compared = 0;
  double worst_stress = 0.0, worst_strain = 0.0;
  for (std::size_t b = 0; b < meshes.bodies.size(); ++b) {
    const fem::MeshBody& mesh = meshes.bodies[b];
    Eigen::VectorXd x(static_cast<Eigen::Index>(mesh.dofs()));
    double largest = 0.0;
    for (std::size_t n = 0; n < mesh.nodes(); ++n)
      for (int c = 0; c < 2; ++c) {
        x(static_cast<Eigen::Index>(2 * n + c)) = mailx[b]->nodes[n].x[static_cast<std::size_t>(c)].value;
        largest = std::max(largest, std::abs(x(static_cast<Eigen::Index>(2 * n + c))));
      }
    const double strain_bound = 5e-8 * largest / 0.5 * 4.0;  // nodes ≥ 0.5 apart; 4 nodal errors per strain
    const double stress_bound = 0.16e11 * 2.0 * strain_bound;
    const grammar::GpvBody ours = gauss_point_values(mesh, meshes.matlib[b], x, static_cast<int>(b + 1));
    const grammar::GpvBody& theirs = gpv.bodies[b];
    ASSERT_EQ(ours.elements.size(), theirs.elements.size());
    for (std::size_t e = 0; e < ours.elements.size(); ++e) {
      EXPECT_EQ(ours.elements[e].type.value, theirs.elements[e].type.value);
      const auto& a = ours.elements[e].models[0].lines;
      const auto& c = theirs.elements[e].models[0].lines;
      ASSERT_EQ(a.size(), c.size());  // 3 points × (stress, strain, energy)
      for (std::size_t l = 0; l < a.size(); ++l) {
        ASSERT_EQ(a[l].size(), c[l].size());
        const double bound = l % 3 == 0 ? stress_bound : l % 3 == 1 ? strain_bound : stress_bound * 1e-5;
        for (std::size_t k = 0; k < a[l].size(); ++k) {
          EXPECT_NEAR(a[l][k].value, c[l][k].value, bound + 5e-8 * std::abs(c[l][k].value))
              << "body " << b + 1 << " element " << e + 1 << " line " << l << " value " << k;
          ++compared;
          const double relative =
              std::abs(a[l][k].value - c[l][k].value) / std::max(std::abs(c[l][k].value), 1e-300);
          if (l % 3 == 0) worst_stress = std::max(worst_stress, relative);
          if (l % 3 == 1 && std::abs(c[l][k].value) > 0) worst_strain = std::max(worst_strain, relative);
        }
      }
    }
  }
  EXPECT_GT(compared, 100);
  std::printf("%d values compared; largest relative difference: stress %.2e, strain %.2e\n", compared,
              worst_stress, worst_strain);
}

}  // namespace
}  // namespace lmgc::solver
