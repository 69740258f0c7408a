#include "solver/fem/linear_body.hpp"

#include <algorithm>

namespace lmgc::solver::fem {

namespace {
using Triplets = std::vector<Eigen::Triplet<double>>;

template <class E>
bool add_element(const MeshBody& body, const MeshElement& element, Triplets& k, Triplets& m) {
  constexpr int D = E::kDimension, N = E::kNodes;
  NodeCoordinates<E> x;
  for (int a = 0; a < N; ++a)
    for (int c = 0; c < D; ++c)
      x(a, c) =
          body.coordinates[static_cast<std::size_t>(element.nodes[static_cast<std::size_t>(a)] * D + c)];
  const Material& material = body.materials[static_cast<std::size_t>(element.material)];
  const ElementEntry& entry = element_entry(element.kind);
  ElementMatrix<E> ke, me;
  if (!stiffness<E>(x, elasticity_matrix(body.hypothesis, material.young, material.poisson), body.hypothesis,
                    quadrature<D>(entry.stiffness_rule), ke) ||
      !consistent_mass<E>(x, material.density, body.hypothesis, quadrature<D>(entry.mass_rule), me))
    return false;
  if (body.lumped_mass) {
    // LMGC90 lumps each element's mass (compute_elementary_mass_iso, mailx-2d.md §3).
    ElementMatrix<E> diagonal = ElementMatrix<E>::Zero();
    if (entry.lumping == MassLumping::row_sum) {
      for (int i = 0; i < N * D; ++i) diagonal(i, i) = me.row(i).sum();
    } else {
      const double element_mass =
          material.density * *volume<E>(x, body.hypothesis, quadrature<D>(entry.mass_rule));
      const double scale = D * element_mass / me.diagonal().sum();
      for (int i = 0; i < N * D; ++i) diagonal(i, i) = scale * me(i, i);
    }
    me = diagonal;
  }
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b)
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          const int row = element.nodes[static_cast<std::size_t>(a)] * D + i;
          const int col = element.nodes[static_cast<std::size_t>(b)] * D + j;
          k.emplace_back(row, col, ke(a * D + i, b * D + j));
          if (me(a * D + i, b * D + j) != 0.0) m.emplace_back(row, col, me(a * D + i, b * D + j));
        }
  return true;
}
}  // namespace

bool assemble(const MeshBody& body, LinearBodyMatrices& matrices, std::string& error,
              std::size_t* failed_element) {
  Triplets k, m;
  for (std::size_t e = 0; e < body.elements.size(); ++e) {
    const MeshElement& element = body.elements[e];
    const bool ok = with_element(element.kind, [&](auto shape) {
      using E = decltype(shape);
      return add_element<E>(body, element, k, m);
    });
    if (!ok) {
      if (failed_element) *failed_element = e;
      error = "element " + std::to_string(e + 1) + " (" + std::string(element_entry(element.kind).name) +
              ") has a Gauss point where its Jacobian is not positive: inverted or degenerate";
      return false;
    }
  }
  const auto n = static_cast<Eigen::Index>(body.dofs());
  matrices.stiffness.resize(n, n);
  matrices.stiffness.setFromTriplets(k.begin(), k.end());
  matrices.mass.resize(n, n);
  matrices.mass.setFromTriplets(m.begin(), m.end());
  return true;
}

bool LinearThetaScheme::prepare(const LinearBodyMatrices& matrices, double h, double theta,
                                double rayleigh_alpha, double rayleigh_beta,
                                std::span<const std::int32_t> driven_dofs) {
  return prepare(
      matrices.mass, matrices.stiffness, h, theta,
      Eigen::SparseMatrix<double>(rayleigh_alpha * matrices.mass + rayleigh_beta * matrices.stiffness),
      driven_dofs);
}

bool LinearThetaScheme::prepare(const Eigen::SparseMatrix<double>& mass,
                                const Eigen::SparseMatrix<double>& stiffness, double h, double theta,
                                const Eigen::SparseMatrix<double>& damping,
                                std::span<const std::int32_t> driven_dofs) {
  h_ = h;
  theta_ = theta;
  stiffness_ = stiffness;
  mass_ = mass;
  damping_ = damping.size() ? damping : Eigen::SparseMatrix<double>(mass_.rows(), mass_.cols());
  iteration_ = mass_ + theta * h * damping_ + (theta * h) * (theta * h) * stiffness_;
  const auto n = static_cast<std::int32_t>(iteration_.rows());
  free_of_.assign(static_cast<std::size_t>(n), 0);
  for (std::int32_t d : driven_dofs) free_of_[static_cast<std::size_t>(d)] = -1;
  free_dofs_.clear();
  for (std::int32_t i = 0; i < n; ++i)
    if (free_of_[static_cast<std::size_t>(i)] >= 0) {
      free_of_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(free_dofs_.size());
      free_dofs_.push_back(i);
    }
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index col = 0; col < iteration_.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(iteration_, col); it; ++it) {
      const std::int32_t r = free_of_[static_cast<std::size_t>(it.row())],
                         c = free_of_[static_cast<std::size_t>(it.col())];
      if (r >= 0 && c >= 0) t.emplace_back(r, c, it.value());
    }
  const auto f = static_cast<Eigen::Index>(free_dofs_.size());
  iteration_free_.resize(f, f);
  iteration_free_.setFromTriplets(t.begin(), t.end());
  // The same sparsity as the last factorisation (a Newton iteration's tangent): the ordering and
  // symbolic analysis are kept and only the numbers factorised, unless a copy of the scene shares it.
  const auto* outer = iteration_free_.outerIndexPtr();
  const auto* inner = iteration_free_.innerIndexPtr();
  const bool same_pattern = factor_ && factor_.use_count() == 1 &&
                            pattern_outer_.size() == static_cast<std::size_t>(f + 1) &&
                            pattern_inner_.size() == static_cast<std::size_t>(iteration_free_.nonZeros()) &&
                            std::equal(pattern_outer_.begin(), pattern_outer_.end(), outer) &&
                            std::equal(pattern_inner_.begin(), pattern_inner_.end(), inner);
  if (same_pattern) {
    auto& factor = const_cast<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>&>(*factor_);
    factor.factorize(iteration_free_);
    return factor.info() == Eigen::Success && (factor.vectorD().array() > 0.0).all();
  }
  pattern_outer_.assign(outer, outer + f + 1);
  pattern_inner_.assign(inner, inner + iteration_free_.nonZeros());
  auto factor = std::make_shared<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(iteration_free_);
  factor_ = factor;
  return factor->info() == Eigen::Success && (factor->vectorD().array() > 0.0).all();
}

Eigen::VectorXd LinearThetaScheme::solve_free(const Eigen::VectorXd& rhs) const {
  Eigen::VectorXd reduced(static_cast<Eigen::Index>(free_dofs_.size()));
  for (std::size_t k = 0; k < free_dofs_.size(); ++k)
    reduced(static_cast<Eigen::Index>(k)) = rhs(free_dofs_[k]);
  const Eigen::VectorXd solved = factor_->solve(reduced);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(rhs.size());
  for (std::size_t k = 0; k < free_dofs_.size(); ++k)
    out(free_dofs_[k]) = solved(static_cast<Eigen::Index>(k));
  return out;
}

void LinearThetaScheme::free_velocity(const Eigen::VectorXd& x_begin, const Eigen::VectorXd& v_begin,
                                      const Eigen::VectorXd& f_ext, std::span<const DrivenVelocity> driven,
                                      Eigen::VectorXd& v_free) const {
  // Residual at V = V_begin: −h K (X_begin + θ h V_begin) − h C V_begin + h F_ext.
  Eigen::VectorXd rhs =
      -h_ * (stiffness_ * (x_begin + theta_ * h_ * v_begin)) - h_ * (damping_ * v_begin) + h_ * f_ext;
  // The driven dofs' increments act on the free ones through K̂: ΔV_d = v_d − V_begin,d.
  Eigen::VectorXd imposed = Eigen::VectorXd::Zero(v_begin.size());
  for (const DrivenVelocity& d : driven) imposed(d.dof) = d.value - v_begin(d.dof);
  if (!driven.empty()) rhs -= iteration_ * imposed;
  v_free = v_begin + solve_free(rhs) + imposed;
}

Eigen::VectorXd LinearThetaScheme::response(const Eigen::VectorXd& impulse) const {
  return solve_free(impulse);
}

Eigen::VectorXd LinearThetaScheme::displacement(const Eigen::VectorXd& x_begin,
                                                const Eigen::VectorXd& v_begin,
                                                const Eigen::VectorXd& v) const {
  return x_begin + h_ * ((1.0 - theta_) * v_begin + theta_ * v);
}

}  // namespace lmgc::solver::fem
