#include "solver/nlgs/nlgs_3d.hpp"

#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <numeric>

#include "solver/model/contact_kinematics_3d.hpp"
#include "solver/nlgs/law_local_problem_3d.hpp"
#include "solver/nlgs/local_solver_3d.hpp"
#include "solver/nlgs/open_contact_visits.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// How far ahead in sweep order the sweeps fetch the interaction of a contact they will solve.
constexpr std::size_t kPrefetchDistance = 32;

// Asks for the cache lines a sweep's local solve reads of an interaction: its first 376 bytes (up to
// r), seven lines at most as records of 504 bytes fall.
void prefetch_interaction(const Interaction3D& c) {
  const char* bytes = reinterpret_cast<const char*>(&c);
  for (std::size_t offset = 0; offset <= 384; offset += 64) __builtin_prefetch(bytes + offset);
}

// The block the law's local problem is posed with: W, plus ELASTIC_REPELL_CLB's compliance on n.
Matrix3d law_block(const Interaction3D& c) {
  if (c.normal_compliance == 0.0 || c.form != LocalForm3D::coulomb) return c.W;
  Matrix3d WW = c.W;
  WW(1, 1) += c.normal_compliance;
  return WW;
}

// The reaction with the cohesion impulse (correction) of the WET / Mohr laws added, and back: Mohr
// adds it only to a contact that stays closed (mod_nlgs_3D solve_nlgs :4547-4552).
Vector3d with_cohesion(const Interaction3D& c, Vector3d rr) {
  if (c.correction != 0.0 && !(c.correction_needs_contact && rr(1) <= 0.0)) rr(1) += c.correction;
  return rr;
}
Vector3d cohesion_free(const Interaction3D& c, Vector3d r) {
  if (c.correction != 0.0 && !(c.correction_needs_contact && r.isZero(0.0))) r(1) -= c.correction;
  return r;
}

ContactStatus status_of(const Vector3d& r, double mu) {
  if (r(1) <= 0.0) return ContactStatus::noctc;
  const double tangential = std::hypot(r(0), r(2));
  return tangential < mu * r(1) * (1.0 - 1e-10) ? ContactStatus::stick : ContactStatus::slide;
}

// Whether each contact is without reaction, beside its visits: a sweep passes most open contacts by
// on these 12 bytes without reading their 504-byte interaction (open_contact_visits.hpp): in a
// packing most contacts are open, and a pass-by would read two cache lines of it.
struct OpenContact {
  OpenContactSchedule visits;
  bool no_reaction = true;
  bool solved_at(std::int32_t sweep) const { return !no_reaction || !visits.passes_by(sweep); }
};

// The NLGS of one step, as LMGC90's ExSolver runs it: set-up, blocks of gs_it1 sweeps each ended by
// a check, the post sweep, the end of the step. The kernels (the local solve of a contact, its
// relative velocity and the injection of its reaction) are the 3D rigid ones.
class Nlgs3D {
 public:
  Nlgs3D(Scene3D& scene, RunState3D& state, const NlgsOptions& options)
      : scene_(scene),
        state_(state),
        options_(options),
        b_(scene.bodies),
        contacts_(state.contacts),
        V_(scene.bodies.velocity),
        law_step_{state.h, state.time, state.step == 1, !state.laws_initialized && !state.contacts.empty()} {}

  NlgsResult run() {
    set_up();
    for (int check = 0; check < options_.gs_it2; ++check) {
      sweep_block();
      if (check_pass()) break;
    }
    if (contacts_.empty()) result_.converged = true;
    post();
    end_of_step();
    return result_;
  }

 private:
  // One pass over the interactions (on large scenes each pass streams them from memory): the law's
  // problem, |q|, the warm start's impulse and whether the contact starts without reaction.
  void set_up() {
    V_ = b_.velocity_free;
    for (auto& impulse : b_.impulse) impulse.setZero();
    if (!contacts_.empty()) state_.laws_initialized = true;
    law_updates_at_check_.resize(scene_.laws.size());
    for (std::size_t l = 0; l < scene_.laws.size(); ++l)
      law_updates_at_check_[l] = updates_at_check(scene_.laws[l].law);
    open_.resize(contacts_.size());
    double q_squared = 0.0;
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      Interaction3D& c = contacts_[k];
      // Each law's derived problem (its own file, solver/laws/*.hpp).
      if (!prepare_law(scene_.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k), law_step_))
        c.inactive = true;
      if (c.inactive) c.r.setZero();
      const Vector3d q = local_velocity(c, b_.velocity_free) + c.covfree;
      if (!c.inactive) q_squared += q.squaredNorm();
      if (!c.inactive && !c.r.isZero(0.0)) inject(c, c.r, b_, V_);
      open_[k].no_reaction = c.r.isZero(0.0);
    }
    result_.free_velocity_norm = std::sqrt(q_squared);
    local_tolerance_ = 1e-10 * std::max(result_.free_velocity_norm, 1e-300);
    keep_tolerance_ = local_tolerance_ / 20.0;
    W_inverse_.resize(contacts_.size());
    inverted_.assign(contacts_.size(), 0);
    // Sweep order: detection order, or LMGC90's quick scramble before each block of gs_it1 sweeps
    // (nlgs_3D_SetWithQuickScramble; quick_scramble.hpp).
    order_.resize(contacts_.size());
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    if (options_.quick_scramble) state_.scramble.prepare(contacts_.size());
  }

  // Contact k's law state; in a scene whose laws keep none, one that no law reads.
  LawState3D& law_state(std::size_t k) {
    return state_.law_states.empty() ? unused_law_state_ : state_.law_states[k];
  }

  // Each block's inverse in the local solver's order, once per step, when its contact first meets a
  // compressive free velocity: a contact that stays open, as most of a packing's do, never needs it.
  const Matrix3d& inverse_of(std::size_t k) {
    if (!inverted_[k]) {
      const Matrix3d W_normal_first = swap_normal_first(law_block(contacts_[k]));
      bool invertible = false;
      const double scale = W_normal_first.cwiseAbs().maxCoeff();
      W_normal_first.computeInverseWithCheck(W_inverse_[k], invertible, 1e-14 * scale * scale * scale);
      if (!invertible) W_inverse_[k].setConstant(std::nan(""));
      inverted_[k] = 1;
    }
    return W_inverse_[k];
  }

  // One local solve of contact k with the others frozen; returns the new reaction. The local problem
  // is posed on rr = r − correction e_n (cohesive laws, contact-laws.md §3.2), r = rr + correction.
  Vector3d local_solve(std::size_t k, Vector3d& q_local, double forcing) {
    const Interaction3D& c = contacts_[k];
    // Rods, wires, cohesive zones: the law's own local problem (law_local_problem_3d.hpp), whatever
    // the resolution (LMGC90's diagonal variants of these are not reproduced).
    if (c.form != LocalForm3D::coulomb) {
      q_local = local_velocity(c, V_) - c.W * c.r + c.covfree;
      return solve_law_form_3d(c, law_state(k), q_local, c.r, local_tolerance_);
    }
    // The others' contribution and the free velocity, plus the cohesion term −c h W e_n.
    const Vector3d correction(0.0, c.correction, 0.0);
    const Vector3d rr_previous = cohesion_free(c, c.r);
    if (options_.diagonal_resolution) {
      // solve_nlgs with diagonal_resolution (mod_nlgs_3D): only the diagonal self-terms removed.
      const Vector3d diagonal = c.W.diagonal();
      q_local = local_velocity(c, V_) - diagonal.cwiseProduct(c.r - correction) + c.covfree;
      if (q_local(1) >= 0.0) return with_cohesion(c, Vector3d::Zero());
      Vector3d r = -q_local.cwiseQuotient(law_block(c).diagonal());  // invWnn = 1/WWnn
      const double bound = c.mu * r(1), tangential_squared = r(0) * r(0) + r(2) * r(2);
      // Inside the cone by a margin far above the sum of squares' round-off, |r_T| > bound cannot hold,
      // and std::hypot (costly, and called at every update) is only taken near or outside it: the
      // same decisions and reactions bit for bit.
      if (bound >= 0.0 && tangential_squared < bound * bound * (1.0 - 1e-12)) return with_cohesion(c, r);
      const double tangential = std::hypot(r(0), r(2));
      if (tangential > bound && tangential > 1e-18) {
        r(0) *= bound / tangential;
        r(2) *= bound / tangential;
      }
      return with_cohesion(c, r);
    }
    q_local = local_velocity(c, V_) - c.W * (c.r - correction) + c.covfree;
    // A separating free velocity needs no inverse: the solver returns r = 0 before it would invert.
    const Matrix3d* inverse = q_local(1) < 0.0 ? &inverse_of(k) : nullptr;
    const LocalSolution3D s = solve_signorini_coulomb_3d(
        swap_normal_first(law_block(c)), inverse, swap_normal_first(q_local), c.mu,
        swap_normal_first(rr_previous), local_tolerance_, forcing, keep_tolerance_);
    ++result_.local_solves;
    return with_cohesion(c, swap_normal_first(s.r));
  }

  // The reaction a sweep gives contact k, relaxed.
  Vector3d sweep_reaction(std::size_t k) {
    Vector3d q_local;
    Vector3d r_new = local_solve(k, q_local, kSweepForcing);
    if (options_.relax != 1.0) r_new = options_.relax * r_new + (1.0 - options_.relax) * contacts_[k].r;
    return r_new;
  }

  // After a sweep that changed no reaction: whether the open contacts it may have passed by would
  // keep theirs too. Then every local solve returns its contact's reaction, no velocity moves, and
  // the rest of the block would repeat this state bit for bit, so it is skipped (counted as done).
  bool stands_still() {
    for (std::size_t k = 0; k < contacts_.size(); ++k)
      if (open_[k].no_reaction && !contacts_[k].inactive && sweep_reaction(k) != contacts_[k].r) return false;
    return true;
  }

  // gs_it1 sweeps, in the block's order.
  void sweep_block() {
    const auto sweeps_start = std::chrono::steady_clock::now();
    if (options_.quick_scramble) state_.scramble.scramble(order_);
    for (OpenContact& o : open_) o.visits.restart();
    for (int sweep = 0; sweep < options_.gs_it1; ++sweep) {
      bool changed = false;
      for (std::size_t position = 0; position < order_.size(); ++position) {
        // The contact this sweep will solve a few dozen positions on is fetched now: when most
        // contacts are passed by, the solved ones lie far apart in a list larger than the caches,
        // and each waited for its interaction's lines to come from memory.
        if (position + kPrefetchDistance < order_.size()) {
          const std::size_t ahead = order_[position + kPrefetchDistance];
          if (open_[ahead].solved_at(sweep)) prefetch_interaction(contacts_[ahead]);
        }
        const std::size_t k = order_[position];
        OpenContact& o = open_[k];
        if (o.no_reaction && o.visits.skip(sweep)) continue;
        Interaction3D& c = contacts_[k];
        if (c.inactive) continue;
        const Vector3d r_new = sweep_reaction(k);
        o.no_reaction = r_new.isZero(0.0);
        if (!o.no_reaction) o.visits.restart();
        if (r_new != c.r) {
          inject(c, r_new - c.r, b_, V_);
          changed = true;
        }
        c.r = r_new;
      }
      ++result_.iterations;
      if (!changed && sweep + 1 < options_.gs_it1 && stands_still()) {
        const int rest = options_.gs_it1 - sweep - 1;
        result_.iterations += rest;
        result_.sweeps_skipped += rest;
        break;
      }
    }
    result_.sweep_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - sweeps_start).count();
  }

  // Check pass (numerics.md §4.1): one more local solve per contact, r left unchanged. True when the
  // block loop ends: converged, or diverged.
  bool check_pass() {
    NlgsCheckSums sums;
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      Interaction3D& c = contacts_[k];
      if (c.inactive) continue;
      Vector3d q_local;
      const Vector3d r_check = local_solve(k, q_local, 0.0);
      // Laws that re-evaluate their state at a check do it with the velocity of this solution.
      if (law_updates_at_check_[static_cast<std::size_t>(c.law)])
        update_law_at_check(scene_.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k),
                            local_velocity(c, V_) + c.W * (r_check - c.r), law_step_);
      const Vector3d mean_r = 0.5 * (c.r + r_check);
      const Vector3d dv = c.W * (c.r - r_check);
      const double dvdv = dv.squaredNorm();
      const double rr = mean_r.squaredNorm();
      if (rr == 0.0) continue;
      sums.active += 1.0;
      const Vector3d wr = c.W * c.r, wr_check = c.W * r_check;
      sums.add(dvdv, dvdv * rr, mean_r.dot(dv), 0.5 * (wr.dot(c.r) + wr_check.dot(r_check)),
               0.5 * (wr.squaredNorm() + wr_check.squaredNorm()));
    }
    result_.norms = nlgs_norms(sums, options_.tolerance);
    if (!std::isfinite(result_.norms.mean_dvor) || !std::isfinite(result_.norms.quad_dv)) {
      result_.diverged = true;
      return true;
    }
    result_.converged = nlgs_check_passes(options_.norm, result_.norms);
    return result_.converged;
  }

  // Post (mod_nlgs_3D solve_nlgs i_post after RnodHRloc): the velocities rebuilt from scratch
  // (Vfree + M^-1 H r), then one more relaxed sweep that solves every contact. With
  // Stored_Delassus_Loops LMGC90 does not inject that sweep's changes: the bodies end the step with
  // the velocities and impulses of the reactions before it, the contacts keep the new reactions.
  void post() {
    if (contacts_.empty()) return;
    V_ = b_.velocity_free;
    for (Interaction3D& c : contacts_)
      if (!c.inactive && !c.r.isZero(0.0)) inject(c, c.r, b_, V_);
    if (stored_delassus()) {
      velocity_before_post_ = V_;
      for (const Interaction3D& c : contacts_)
        if (!c.inactive && !c.r.isZero(0.0)) add_impulse(c, c.r, b_.impulse);
    }
    for (const std::size_t k : order_) {
      Interaction3D& c = contacts_[k];
      if (c.inactive) continue;
      Vector3d q_local;
      const Vector3d r_solved = local_solve(k, q_local, kSweepForcing);
      // Laws that re-evaluate their state at a check do it here too, from this solution's velocity.
      if (law_updates_at_check_[static_cast<std::size_t>(c.law)])
        update_law_at_check(scene_.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k),
                            local_velocity(c, V_) + c.W * (r_solved - c.r), law_step_);
      const Vector3d r_new = options_.relax != 1.0
                                 ? Vector3d(options_.relax * r_solved + (1.0 - options_.relax) * c.r)
                                 : r_solved;
      if (r_new != c.r) inject(c, r_new - c.r, b_, V_);
      c.r = r_new;
    }
  }

  // End of the solve, in one pass: Ireac of every body from the final reactions, relative velocities,
  // statuses, and the natural-map residual of the local problems (fc3d/FORMAT.md §3) in the auxiliary
  // variables u + covfree.
  void end_of_step() {
    double residual_squared = 0.0;
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
      Interaction3D& c = contacts_[k];
      if (!stored_delassus() && !c.inactive && !c.r.isZero(0.0)) add_impulse(c, c.r, b_.impulse);
      c.u = local_velocity(c, V_);
      if (c.inactive) {
        c.status = ContactStatus::noctc;
        continue;
      }
      if (c.r.squaredNorm() > 0.0) ++result_.active;
      if (c.form != LocalForm3D::coulomb) {
        const Vector3d uu = c.u + c.covfree;
        c.status = law_form_status_3d(c, law_state(k), c.r, uu);
        residual_squared += law_form_residual_3d(c, law_state(k), c.r, uu).squaredNorm();
      } else {
        const Vector3d rr = cohesion_free(c, c.r);
        c.status = status_of(rr, c.mu);
        Vector3d uu = c.u + c.covfree;
        uu(1) += c.normal_compliance * rr(1);  // ELASTIC_REPELL_CLB's WW (0 for the other laws)
        residual_squared += natural_map_3d(swap_normal_first(rr), swap_normal_first(uu), c.mu).squaredNorm();
      }
      finish_law(scene_.laws[static_cast<std::size_t>(c.law)].law, c, law_state(k), law_step_);
    }
    if (stored_delassus() && !contacts_.empty()) V_ = std::move(velocity_before_post_);
    result_.residual_absolute = std::sqrt(residual_squared);
    result_.residual_relative = result_.free_velocity_norm > 0.0
                                    ? result_.residual_absolute / result_.free_velocity_norm
                                    : result_.residual_absolute;
  }

  bool stored_delassus() const { return options_.storage == NlgsStorage::stored_delassus_loops; }

  // Inexact local solves in the sweeps: a Newton solve also stops at 1/100 of the residual of its
  // start (mostly the previous reaction), so sweeps far from convergence do not pay for 1e-10; near
  // convergence the start is already close and the tolerance rules. The check pass solves exactly.
  static constexpr double kSweepForcing = 1e-2;

  Scene3D& scene_;
  RunState3D& state_;
  const NlgsOptions& options_;
  RigidBodies3D& b_;
  LargeArray<Interaction3D>& contacts_;
  std::vector<Vector6d>& V_;
  const LawStep law_step_;
  NlgsResult result_;
  std::vector<std::uint8_t> law_updates_at_check_;
  LawState3D unused_law_state_;
  std::vector<OpenContact> open_;
  double local_tolerance_ = 0.0;
  // A sticking contact keeps its previous reaction when that solves its problem within 1/20 of the
  // local tolerance (local_solver_3d.hpp): converged sweeps then repeat their reactions bit for bit
  // and the rest of the block is skipped (sweep_block), where exact solves traded round-off for
  // hundreds of sweeps. 1/20 keeps the achieved residual at or below the exact solves'.
  double keep_tolerance_ = 0.0;
  std::vector<Matrix3d> W_inverse_;
  std::vector<std::uint8_t> inverted_;
  std::vector<std::size_t> order_;
  std::vector<Vector6d> velocity_before_post_;
};

}  // namespace

NlgsResult solve_contacts(Scene3D& scene, RunState3D& state, const NlgsOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  NlgsResult result = Nlgs3D(scene, state, options).run();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lmgc::solver
