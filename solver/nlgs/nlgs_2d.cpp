#include "solver/nlgs/nlgs_2d.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "solver/laws/law_local_problem_2d.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

// H rows of one body for an interaction: t_row = (t, ℓ×t), n_row = (n, ℓ×n).
struct BodyRows {
  Vector3d t, n;
};
BodyRows rows(const Interaction2D& c, const Vector2d& lever) {
  return {Vector3d(c.tangent.x(), c.tangent.y(), lever(0)), Vector3d(c.normal.x(), c.normal.y(), lever(1))};
}

// Relative velocity (t, n) of the candidate w.r.t. the antagonist for body velocities.
Vector2d relative_velocity(const Interaction2D& c, const std::vector<Vector3d>& v) {
  const BodyRows cd = rows(c, c.lever_candidate), an = rows(c, c.lever_antagonist);
  const Vector3d& vc = v[static_cast<std::size_t>(c.candidate_body)];
  const Vector3d& va = v[static_cast<std::size_t>(c.antagonist_body)];
  return Vector2d(cd.t.dot(vc) - an.t.dot(va), cd.n.dot(vc) - an.n.dot(va));
}

// Adds the velocity change M⁻¹ H Δr of both bodies.
void inject(const Interaction2D& c, const Vector2d& dr, const std::vector<Vector3d>& inverse_mass,
            std::vector<Vector3d>& v) {
  const BodyRows cd = rows(c, c.lever_candidate), an = rows(c, c.lever_antagonist);
  const auto icd = static_cast<std::size_t>(c.candidate_body), ian = static_cast<std::size_t>(c.antagonist_body);
  v[icd] += inverse_mass[icd].cwiseProduct(dr(0) * cd.t + dr(1) * cd.n);
  v[ian] -= inverse_mass[ian].cwiseProduct(dr(0) * an.t + dr(1) * an.n);
}

Matrix2d delassus_block(const Interaction2D& c, const std::vector<Vector3d>& inverse_mass) {
  Matrix2d W = Matrix2d::Zero();
  for (int side = 0; side < 2; ++side) {
    const BodyRows b = rows(c, side == 0 ? c.lever_candidate : c.lever_antagonist);
    const Vector3d& m = inverse_mass[static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body)];
    W(0, 0) += b.t.cwiseProduct(m).dot(b.t);
    W(0, 1) += b.t.cwiseProduct(m).dot(b.n);
    W(1, 1) += b.n.cwiseProduct(m).dot(b.n);
  }
  W(1, 0) = W(0, 1);
  return W;
}

bool check_passes(NlgsNorm norm, const NlgsNorms& q) {
  const bool quad = std::fabs(q.mean_dvor) < 1.0 && std::fabs(q.quad_dv) < 1.0 && std::fabs(q.quad_dvr) < 1.0;
  const bool maxm = std::fabs(q.mean_dvor) < 1.0 && std::fabs(q.maxm_dv) < 1.0 && std::fabs(q.maxm_dvr) < 1.0;
  switch (norm) {
    case NlgsNorm::quad:
    case NlgsNorm::quad_normal: return quad;
    case NlgsNorm::maxm: return maxm;
    case NlgsNorm::qm16: return quad && std::fabs(q.maxm_dv) < 16.666 && std::fabs(q.maxm_dvr) < 16.666;
  }
  return quad;
}

}  // namespace

NlgsResult solve_nlgs_2d(const Scene2D& scene, RigidBodies2D& bodies, std::vector<Interaction2D>& contacts, double h,
                         const NlgsOptions& options) {
  NlgsResult result;
  const std::size_t count = contacts.size();
  std::vector<Vector3d>& v = bodies.velocity;
  // Start from the free velocity plus the warm-start reactions.
  v = bodies.velocity_free;
  std::vector<double> q_norm2(count, 0.0);
  for (Interaction2D& c : contacts) {
    c.W = delassus_block(c, bodies.inverse_mass);
    prepare_local_problem_2d(scene.laws[static_cast<std::size_t>(c.law)].law, c, h);
    if (c.inactive) c.r.setZero();
    c.skip_count = 0;
    c.skip_threshold = 1;
  }
  for (std::size_t a = 0; a < count; ++a) {
    const Interaction2D& c = contacts[a];
    q_norm2[a] = (relative_velocity(c, bodies.velocity_free) + c.covfree).squaredNorm();
    if (!c.r.isZero(0.0)) inject(c, c.r, bodies.inverse_mass, v);
  }
  result.free_velocity_norm = std::sqrt(std::accumulate(q_norm2.begin(), q_norm2.end(), 0.0));

  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 random(12345u);

  // One Gauss–Seidel pass; the post pass never skips and is not counted as an iteration.
  auto sweep = [&](bool post) {
    for (std::size_t k : order) {
      Interaction2D& c = contacts[k];
      const ContactLaw& law = scene.laws[static_cast<std::size_t>(c.law)].law;
      if (c.inactive) {
        if (!c.r.isZero(0.0)) {
          inject(c, -c.r, bodies.inverse_mass, v);
          c.r.setZero();
        }
        c.status = ContactStatus::noctc;
        continue;
      }
      // Vanishing contacts are visited less and less often (numerics.md §4 skip heuristic).
      if (!post && c.r.isZero(0.0)) {
        if (++c.skip_count < c.skip_threshold * (c.skip_threshold + 1) / 2) continue;
        ++c.skip_threshold;
      }
      const Vector2d u = relative_velocity(c, v);
      const Vector2d ufree_loc = u - c.W * c.r;
      const LocalSolution2D s = solve_local_problem_2d(law, c, ufree_loc);
      Vector2d r = options.relax * s.r + (1.0 - options.relax) * c.r;
      if (std::fabs(r(0)) < 1e-24) r(0) = 0.0;
      if (std::fabs(r(1)) < 1e-24) r(1) = 0.0;
      const Vector2d dr = r - c.r;
      if (!dr.isZero(0.0)) inject(c, dr, bodies.inverse_mass, v);
      c.r = r;
      c.status = s.status;
      if (!r.isZero(0.0)) {
        c.skip_count = 0;
        c.skip_threshold = 1;
      }
    }
    if (!post) ++result.iterations;
  };

  // One check pass: the local solve applied to the current state without updating it.
  auto check = [&]() {
    double sum_dvdv = 0, max_dvdv = 0, sum_dvdvrr = 0, max_dvdvrr = 0, sum_dvor = 0, sum_wrr = 0, sum_wrwr = 0;
    double residual2 = 0;
    std::size_t vanishing = 0;
    result.active = 0;
    for (std::size_t k = 0; k < count; ++k) {
      Interaction2D& c = contacts[k];
      // The skip heuristic restarts after every check.
      c.skip_count = 0;
      c.skip_threshold = 1;
      const ContactLaw& law = scene.laws[static_cast<std::size_t>(c.law)].law;
      const Vector2d u = relative_velocity(c, v);
      const Vector2d ufree_loc = u - c.W * c.r;
      residual2 += local_residual_squared_2d(law, c, c.r, ufree_loc);
      Vector2d r = c.r, r2 = Vector2d::Zero();
      if (!c.inactive) r2 = solve_local_problem_2d(law, c, ufree_loc).r;
      else r.setZero();
      const Vector2d u2 = c.W * r2 + ufree_loc;
      const Vector2d mean = 0.5 * (r + r2);
      const Vector2d dv = u - u2;
      if (mean.isZero(0.0)) ++vanishing;
      if (!c.r.isZero(0.0)) ++result.active;
      const double dvdv = dv.squaredNorm();
      sum_dvdv += dvdv;
      max_dvdv = std::max(max_dvdv, dvdv);
      sum_dvdvrr += dvdv * mean.squaredNorm();
      max_dvdvrr = std::max(max_dvdvrr, dvdv * mean.squaredNorm());
      sum_dvor += mean.dot(dv);
      const Vector2d wr = c.W * r, wr2 = c.W * r2;
      sum_wrr += 0.5 * (wr.dot(r) + wr2.dot(r2));
      sum_wrwr += 0.5 * (wr.squaredNorm() + wr2.squaredNorm());
    }
    result.residual_absolute = std::sqrt(residual2);
    result.residual_relative =
        result.free_velocity_norm > 0.0 ? result.residual_absolute / result.free_velocity_norm : result.residual_absolute;
    const double active = static_cast<double>(count - vanishing);
    NlgsNorms& q = result.norms;
    const double tol = options.tolerance;
    if (active >= 1.0 && sum_wrr > 1e-18 && sum_wrwr > 1e-18) {
      q.quad_wr = std::sqrt(sum_wrwr / active);
      const double mean_wrr = sum_wrr / active;
      q.quad_dv = std::sqrt(sum_dvdv / active) / (q.quad_wr * tol);
      q.maxm_dv = std::sqrt(max_dvdv) / (q.quad_wr * tol);
      q.quad_dvr = std::sqrt(sum_dvdvrr / active) / (mean_wrr * tol);
      q.maxm_dvr = std::sqrt(max_dvdvrr) / (mean_wrr * tol);
      q.mean_dvor = sum_dvor / (sum_wrr * tol);
    } else {
      q = NlgsNorms{0.111e-11, 0.111e-11, 0.111e-11, 0.111e-11, 0.111e-11, 0.0};
    }
    if (!std::isfinite(q.mean_dvor) || !std::isfinite(q.quad_dv) || !std::isfinite(residual2)) result.diverged = true;
    bool passed = check_passes(options.norm, q);
    if (options.residual_target > 0.0) passed = passed || result.residual_relative <= options.residual_target;
    return passed;
  };

  if (count > 0) {
    for (int block = 0; block < options.gs_it2; ++block) {
      if (options.quick_scramble) std::shuffle(order.begin(), order.end(), random);
      for (int i = 0; i < options.gs_it1; ++i) sweep(false);
      result.converged = check();
      if (result.converged || result.diverged) break;
    }
  } else {
    result.converged = true;
  }

  // Post (docs/lmgc90-facts/rigid-2d.md §5.3): velocities rebuilt from scratch (Rnod = H r),
  // one more relaxed sweep, then the final local velocities and statuses.
  v = bodies.velocity_free;
  for (const Interaction2D& c : contacts)
    if (!c.r.isZero(0.0)) inject(c, c.r, bodies.inverse_mass, v);
  if (count > 0) sweep(true);
  // The achieved error is the one of the reactions actually returned (after the post sweep).
  double residual2 = 0.0;
  result.active = 0;
  for (const Interaction2D& c : contacts) {
    const Vector2d u = relative_velocity(c, v);
    residual2 += local_residual_squared_2d(scene.laws[static_cast<std::size_t>(c.law)].law, c, c.r, u - c.W * c.r);
    if (!c.r.isZero(0.0)) ++result.active;
  }
  result.residual_absolute = std::sqrt(residual2);
  result.residual_relative =
      result.free_velocity_norm > 0.0 ? result.residual_absolute / result.free_velocity_norm : result.residual_absolute;
  // Contact impulses of every body (Ireac = Σ H r), driven dofs included (TORQUE EVOLUTION).
  std::fill(bodies.impulse.begin(), bodies.impulse.end(), Vector3d::Zero());
  for (const Interaction2D& c : contacts) {
    const BodyRows cd = rows(c, c.lever_candidate), an = rows(c, c.lever_antagonist);
    bodies.impulse[static_cast<std::size_t>(c.candidate_body)] += c.r(0) * cd.t + c.r(1) * cd.n;
    bodies.impulse[static_cast<std::size_t>(c.antagonist_body)] -= c.r(0) * an.t + c.r(1) * an.n;
  }
  for (Interaction2D& c : contacts) {
    c.u = relative_velocity(c, v);
    if (c.inactive || c.r.isZero(0.0)) {
      if (c.r.isZero(0.0)) c.status = ContactStatus::noctc;
    }
    finish_step_2d(scene.laws[static_cast<std::size_t>(c.law)].law, c, h);
  }
  return result;
}

}  // namespace lmgc::solver
