#include "solver/fem/finite_strain_plasticity.hpp"

#include <cmath>

#include "solver/fem/element_matrices.hpp"
#include "solver/fem/quadrature.hpp"
#include "solver/fem/reference_element.hpp"

namespace lmgc::solver::fem {

namespace {

const double kRoot32 = std::sqrt(1.5), kRoot23 = std::sqrt(2.0 / 3.0);

// σ_y(p) and H (LMGC90's SEUDUB).
void yield_stress(const J2Parameters& m, double p, double& sigma, double& slope) {
  const auto& c = m.coefficients;
  switch (m.hardening) {
    case Hardening::swift: {
      const double e = c[1] + p;
      if (std::abs(c[2] - 1.0) < 1e-20) {
        sigma = c[0] * e;
        slope = c[0];
      } else {
        sigma = c[0] * std::pow(e, c[2]);
        slope = c[0] * c[2] * std::pow(e, c[2] - 1.0);
      }
      return;
    }
    case Hardening::hollomon:
      if (p < 1e-10) {
        sigma = slope = 0.0;
      } else {
        sigma = c[0] * std::pow(p, c[1]);
        slope = c[0] * c[1] * std::pow(p, c[1] - 1.0);
      }
      return;
    case Hardening::linear:
      sigma = c[0] + c[1] * p;
      slope = c[1];
      return;
  }
}

// A symmetric tensor with an out-of-plane component: (xx, yy, xy, zz).
using Sym = Eigen::Vector4d;

double norm(const Sym& s) {
  return std::sqrt(s(0) * s(0) + s(1) * s(1) + s(3) * s(3) + 2.0 * s(2) * s(2));
}

// G (xx, yy, xy, yx, zz) times the symmetric A times Gᵀ, in the (xx, yy, xy, zz) layout.
Sym push(const Eigen::Matrix<double, 5, 1>& g, const Sym& a) {
  Sym out;
  out(0) = a(0) * g(0) * g(0) + a(1) * g(2) * g(2) + 2.0 * (a(2) * g(2) * g(0));
  out(1) = a(0) * g(3) * g(3) + a(1) * g(1) * g(1) + 2.0 * (a(2) * g(1) * g(3));
  out(2) = a(0) * g(0) * g(3) + a(2) * g(0) * g(1) + a(2) * g(3) * g(2) + a(1) * g(2) * g(1);
  out(3) = a(3) * g(4) * g(4);
  return out;
}

struct TrialPoint {
  Sym deviator;              // dev τ (μ dev b̄, returned at a plastic point)
  Sym direction;             // n = dev τ_trial / ‖dev τ_trial‖
  double trial_norm = 0.0;   // ‖dev τ_trial‖
  double third_trace = 0.0;  // tr b̄_trial / 3
  bool plastic = false;
};

}  // namespace

J2Failure j2_element(const Eigen::Matrix<double, 4, 2>& x0, const Eigen::Matrix<double, 8, 1>& u,
                     const std::array<J2State, 4>& begin, double young, double poisson,
                     const J2Parameters& plasticity, bool axisymmetric, bool tangent, J2ElementResult& out,
                     int& failed_point) {
  const Hypothesis h = axisymmetric ? Hypothesis::axisymmetric : Hypothesis::plane_strain;
  const double mu = young / (2.0 * (1.0 + poisson));
  const double kappa = young / (3.0 * (1.0 - 2.0 * poisson));
  const QuadratureRule<2> rule = quadrature<2>(Rule::quad_2x2);
  std::array<TrialPoint, 4> trial;
  out.force.setZero();
  out.stiffness.setZero();

  // Loop 1, on the reference configuration: F, the trial state, the return mapping.
  double volume0 = 0.0, volume = 0.0, mean_third_trace = 0.0;
  for (int g = 0; g < 4; ++g) {
    const auto geometry = point_geometry<Q4>(x0, rule.points[static_cast<std::size_t>(g)],
                                             rule.weights[static_cast<std::size_t>(g)], h);
    if (!geometry) {
      failed_point = g;
      return J2Failure::inverted;
    }
    volume0 += geometry->weight;
    Eigen::Matrix<double, 5, 1> f;  // (xx, yy, xy, yx, zz)
    f << 1.0, 1.0, 0.0, 0.0, 1.0;
    for (int a = 0; a < 4; ++a) {
      const double ux = u(2 * a), uy = u(2 * a + 1);
      f(0) += ux * geometry->gradients(a, 0);
      f(1) += uy * geometry->gradients(a, 1);
      f(2) += ux * geometry->gradients(a, 1);
      f(3) += uy * geometry->gradients(a, 0);
      if (axisymmetric) f(4) += ux * geometry->values(a) / geometry->position.x();
    }
    const double j = (f(0) * f(1) - f(2) * f(3)) * f(4);
    if (!(j > 0.0)) {
      failed_point = g;
      return J2Failure::inverted;
    }
    const J2State& state = begin[static_cast<std::size_t>(g)];
    Sym b = push(f, Sym(state[0], state[1], state[2], state[3])) * std::pow(j, -2.0 / 3.0);
    TrialPoint& t = trial[static_cast<std::size_t>(g)];
    t.third_trace = (b(0) + b(1) + b(3)) / 3.0;
    b(0) -= t.third_trace;
    b(1) -= t.third_trace;
    b(3) -= t.third_trace;
    volume += j * geometry->weight;
    mean_third_trace += t.third_trace;
    t.deviator = mu * b;
    t.trial_norm = norm(t.deviator);
    double q = kRoot32 * t.trial_norm;
    t.direction = t.deviator / (t.trial_norm == 0.0 ? 1.0 : t.trial_norm);
    J2State& next = out.internal[static_cast<std::size_t>(g)];
    next = state;
    double sigma_y = 0.0, slope = 0.0;
    yield_stress(plasticity, state[4], sigma_y, slope);
    // LMGC90's loading test: from an elastic state the trial passes the yield stress; from a plastic
    // one it passes the last von Mises value.
    t.plastic = state[5] - sigma_y < 0.0 ? q - sigma_y > 0.0 : q - state[5] > 0.0;
    if (t.plastic) {
      const double mu_bar = mu * t.third_trace;
      const double trial_q = q == 0.0 ? 1.0 : q;
      double criterion = q, increment = 0.0;
      int iteration = 1;
      for (;;) {
        criterion -= sigma_y;
        if (!(std::abs(criterion / trial_q) > 1e-10)) break;
        if (++iteration == 50) {
          failed_point = g;
          return J2Failure::return_mapping;
        }
        const double derivative = -kRoot32 * 2.0 * mu_bar * (1.0 + slope / (3.0 * mu_bar));
        increment -= criterion / derivative;
        criterion = q - kRoot32 * 2.0 * mu_bar * increment;
        next[4] = state[4] + kRoot23 * increment;
        yield_stress(plasticity, next[4], sigma_y, slope);
      }
      t.deviator -= 2.0 * mu_bar * increment * t.direction;
      q = kRoot32 * norm(t.deviator);
    }
    next[5] = q;
  }
  const double theta = volume / volume0;
  const double pressure = kappa / 2.0 * (theta - 1.0 / theta);
  mean_third_trace /= 4.0;

  // Loop 2, on the current configuration x = x0 + u: the mean divergence, Cp⁻¹ at plastic points,
  // the Cauchy stress.
  Eigen::Matrix<double, 4, 2> x = x0;
  for (int a = 0; a < 4; ++a) x.row(a) += u.segment<2>(2 * a).transpose();
  Eigen::Matrix<double, 8, 1> divergence = Eigen::Matrix<double, 8, 1>::Zero();
  std::array<PointGeometry<Q4>, 4> current;
  for (int g = 0; g < 4; ++g) {
    const auto geometry = point_geometry<Q4>(x, rule.points[static_cast<std::size_t>(g)],
                                             rule.weights[static_cast<std::size_t>(g)], h);
    if (!geometry) {
      failed_point = g;
      return J2Failure::inverted;
    }
    current[static_cast<std::size_t>(g)] = *geometry;
    const double r = geometry->position.x();
    Eigen::Matrix<double, 5, 1> inverse;  // F⁻¹ = 1 − ∂u/∂x (xx, yy, xy, yx, zz)
    inverse << 1.0, 1.0, 0.0, 0.0, 1.0;
    for (int a = 0; a < 4; ++a) {
      const double ux = u(2 * a), uy = u(2 * a + 1);
      divergence(2 * a) += (geometry->gradients(a, 0) + (axisymmetric ? geometry->values(a) / r : 0.0)) *
                           geometry->weight / volume;
      divergence(2 * a + 1) += geometry->gradients(a, 1) * geometry->weight / volume;
      inverse(0) -= ux * geometry->gradients(a, 0);
      inverse(1) -= uy * geometry->gradients(a, 1);
      inverse(2) -= ux * geometry->gradients(a, 1);
      inverse(3) -= uy * geometry->gradients(a, 0);
      if (axisymmetric) inverse(4) -= ux * geometry->values(a) / r;
    }
    const double j_inverse = (inverse(0) * inverse(1) - inverse(2) * inverse(3)) * inverse(4);
    if (!(j_inverse > 0.0)) {
      failed_point = g;
      return J2Failure::inverted;
    }
    const TrialPoint& t = trial[static_cast<std::size_t>(g)];
    J2State& next = out.internal[static_cast<std::size_t>(g)];
    if (t.plastic) {
      // b_e = J^(2/3) (dev τ/μ + the element's mean tr b̄/3), Cp⁻¹ = F⁻¹ b_e F⁻ᵀ.
      Sym be = t.deviator / mu;
      be(0) += mean_third_trace;
      be(1) += mean_third_trace;
      be(3) += mean_third_trace;
      const Sym cp = push(inverse, be * std::pow(j_inverse, -2.0 / 3.0));
      for (int k = 0; k < 4; ++k) next[static_cast<std::size_t>(k)] = cp(k);
    }
    Eigen::Vector4d& sigma = out.stress[static_cast<std::size_t>(g)];
    sigma = t.deviator * j_inverse;
    sigma(0) += pressure;
    sigma(1) += pressure;
    sigma(3) += pressure;
  }

  // Loop 3: the consistent tangent, the volumetric and geometric stiffnesses, the internal force, in
  // fixed sizes: KS strain components (3 in plane strain, 4 with the hoop one).
  const double volumetric = kappa / 2.0 * (1.0 + 1.0 / (theta * theta)) * theta;
  const auto assemble = [&]<int KS>() {
    for (int g = 0; g < 4; ++g) {
      const PointGeometry<Q4>& geometry = current[static_cast<std::size_t>(g)];
      const Eigen::Vector4d& sigma = out.stress[static_cast<std::size_t>(g)];
      const double r = geometry.position.x(), dv = geometry.weight;
      Eigen::Matrix<double, KS, 8> b = Eigen::Matrix<double, KS, 8>::Zero();  // (xx, yy, xy[, θθ])
      Eigen::Matrix<double, KS + 1, 8> grad =
          Eigen::Matrix<double, KS + 1, 8>::Zero();  // ∂x vx, ∂x vy, ∂y vx, ∂y vy[, vx/r]
      for (int a = 0; a < 4; ++a) {
        const double dx = geometry.gradients(a, 0), dy = geometry.gradients(a, 1);
        b(0, 2 * a) = dx;
        b(1, 2 * a + 1) = dy;
        b(2, 2 * a) = dy;
        b(2, 2 * a + 1) = dx;
        grad(0, 2 * a) = dx;
        grad(1, 2 * a + 1) = dx;
        grad(2, 2 * a) = dy;
        grad(3, 2 * a + 1) = dy;
        if constexpr (KS == 4) {
          b(3, 2 * a) = geometry.values(a) / r;
          grad(4, 2 * a) = geometry.values(a) / r;
        }
      }
      out.force.noalias() += b.transpose() * sigma.template head<KS>() * dv;
      if (!tangent) continue;
      const TrialPoint& t = trial[static_cast<std::size_t>(g)];
      const double mu_bar = mu * t.third_trace, two_mu_bar = 2.0 * mu_bar;
      const double c1 = 2.0 / 3.0 * t.trial_norm;
      const Sym& n = t.direction;
      // c̄ = 2μ̄ I_dev − ⅔‖dev τ_trial‖(n⊗1 + 1⊗n), Voigt with engineering shear (xx, yy, xy, θθ).
      Eigen::Matrix4d c = Eigen::Matrix4d::Zero();
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) {
          if (i == 2 || k == 2) continue;
          c(i, k) = (i == k ? 2.0 / 3.0 : -1.0 / 3.0) * two_mu_bar - c1 * (n(i) + n(k));
        }
      c(0, 2) = c(2, 0) = -c1 * n(2);
      c(1, 2) = c(2, 1) = -c1 * n(2);
      c(3, 2) = c(2, 3) = -c1 * n(2);
      c(2, 2) = two_mu_bar / 2.0;
      if (t.plastic) {
        const J2State& next = out.internal[static_cast<std::size_t>(g)];
        const double increment = (next[4] - begin[static_cast<std::size_t>(g)][4]) * kRoot32;
        double sigma_y = 0.0, slope = 0.0;
        yield_stress(plasticity, next[4], sigma_y, slope);
        const double beta0 = 1.0 + slope / (3.0 * mu_bar);
        const double beta1 = two_mu_bar * increment / t.trial_norm;
        const double beta2 = (1.0 - 1.0 / beta0) * c1 * increment / mu_bar;
        const double beta3 = (1.0 / beta0 - beta1 + beta2) * 2.0 * mu_bar;
        const double beta4 = (1.0 / beta0 - beta1) * t.trial_norm * 2.0;
        Sym d;  // dev(n²)
        d(0) = n(0) * n(0) + n(2) * n(2);
        d(1) = n(1) * n(1) + n(2) * n(2);
        d(2) = n(2) * n(0) + n(1) * n(2);
        d(3) = n(3) * n(3);
        const double third = (d(0) + d(1) + d(3)) / 3.0;
        d(0) -= third;
        d(1) -= third;
        d(3) -= third;
        Eigen::Matrix4d plastic;
        for (int i = 0; i < 4; ++i)
          for (int k = 0; k < 4; ++k)
            plastic(i, k) =
                -c(i, k) * beta1 - beta3 * n(i) * n(k) - beta4 * (n(i) * d(k) + d(i) * n(k)) / 2.0;
        c += plastic;
      }
      // The pressure's part: p(1⊗1 − 2I).
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
          c(i, k) += i == 2 || k == 2 ? (i == k ? -pressure : 0.0) : (i == k ? -pressure : pressure);
      Eigen::Matrix<double, 5, 5> s = Eigen::Matrix<double, 5, 5>::Zero();
      s(0, 0) = sigma(0);
      s(0, 2) = sigma(2);
      s(1, 1) = sigma(0);
      s(1, 3) = sigma(2);
      s(2, 0) = sigma(2);
      s(2, 2) = sigma(1);
      s(3, 1) = sigma(2);
      s(3, 3) = sigma(1);
      s(4, 4) = sigma(3);
      const Eigen::Matrix<double, KS, KS> ck = c.template topLeftCorner<KS, KS>();
      const Eigen::Matrix<double, KS + 1, KS + 1> sk = s.template topLeftCorner<KS + 1, KS + 1>();
      // Coefficient-based products: 8 × 8 results of a depth of 3 to 5 are below a blocked product's gain.
      const Eigen::Matrix<double, KS, 8> cb = (ck * dv).lazyProduct(b);
      const Eigen::Matrix<double, KS + 1, 8> sg = (sk * dv).lazyProduct(grad);
      out.stiffness.noalias() += b.transpose().lazyProduct(cb);
      out.stiffness.noalias() += (dv * volumetric) * divergence * divergence.transpose();
      out.stiffness.noalias() += grad.transpose().lazyProduct(sg);
    }
  };
  if (axisymmetric)
    assemble.template operator()<4>();
  else
    assemble.template operator()<3>();
  return J2Failure::none;
}

}  // namespace lmgc::solver::fem
