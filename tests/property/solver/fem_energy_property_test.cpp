// The θ-scheme of a linear elastic mesh body (solver/fem/linear_body.hpp), free, undamped, without
// contact or external force: with θ = ½ (the implicit midpoint rule) the discrete energy
// ½VᵀMV + ½XᵀKX is conserved to round-off; with θ > ½ it never grows and decreases.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "tests/support/fem_meshes.hpp"

namespace lmgc::solver::fem {
namespace {

double energy(const LinearBodyMatrices& m, const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
  return 0.5 * v.dot(m.mass * v) + 0.5 * x.dot(m.stiffness * x);
}

struct Run {
  std::vector<double> energies;
};

Run run(ElementKind kind, double theta, bool lumped) {
  const int nx = *rc::gen::inRange(1, 4), ny = *rc::gen::inRange(1, 3);
  const Material steel{2e11 * (1.0 + *rc::gen::inRange(0, 10) / 10.0), 0.3, 7800.0};
  MeshBody body = test::rectangle(kind, nx, ny, 1.0, 0.5, steel, Hypothesis::plane_strain);
  body.lumped_mass = lumped;
  LinearBodyMatrices m;
  std::string error;
  RC_ASSERT(assemble(body, m, error));
  LinearThetaScheme scheme;
  const double h = 1e-6 * (1 + *rc::gen::inRange(0, 50));
  RC_ASSERT(scheme.prepare(m, h, theta, 0.0, 0.0, {}));
  const auto n = static_cast<Eigen::Index>(body.dofs());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), v(n);
  // A velocity field that always deforms the body (never a rigid motion alone).
  for (Eigen::Index i = 0; i < n; ++i)
    v(i) = *rc::gen::inRange(-100, 101) / 100.0 + 0.01 * static_cast<double>(i % 7);
  Run r;
  r.energies.push_back(energy(m, x, v));
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (int step = 0; step < 50; ++step) {
    Eigen::VectorXd v_free;
    scheme.free_velocity(x, v, zero, {}, v_free);
    x = scheme.displacement(x, v, v_free);
    v = v_free;
    r.energies.push_back(energy(m, x, v));
  }
  return r;
}

RC_GTEST_PROP(FemEnergy, ThetaOneHalfConservesTheDiscreteEnergyToRoundOff, ()) {
  const ElementKind kind =
      *rc::gen::element(ElementKind::T3, ElementKind::Q4, ElementKind::T6, ElementKind::Q8);
  const Run r = run(kind, 0.5, *rc::gen::arbitrary<bool>());
  for (double e : r.energies) RC_ASSERT(std::abs(e - r.energies.front()) <= 1e-11 * r.energies.front());
}

RC_GTEST_PROP(FemEnergy, ThetaAboveOneHalfNeverCreatesEnergy, ()) {
  const ElementKind kind =
      *rc::gen::element(ElementKind::T3, ElementKind::Q4, ElementKind::T6, ElementKind::Q8);
  const double theta = 0.5 + *rc::gen::inRange(1, 51) / 100.0;
  const Run r = run(kind, theta, *rc::gen::arbitrary<bool>());
  for (std::size_t k = 1; k < r.energies.size(); ++k)
    RC_ASSERT(r.energies[k] <= r.energies[k - 1] * (1.0 + 1e-12));
  RC_ASSERT(r.energies.back() < r.energies.front());
}

}  // namespace
}  // namespace lmgc::solver::fem
