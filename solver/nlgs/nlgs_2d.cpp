// NLGS over 2D interactions. docs/lmgc90-facts/numerics.md §3-§4, docs/lmgc90-facts/rigid-2d.md §5.
// The sweeps read a compact array of contacts (bodies, local frame, levers, Delassus block, free
// velocity shift, μ, the block's reciprocals: 128 bytes) and write a separate one of reactions (24 bytes).
// A visit to a contact without reaction, which mostly ends in passing it by, reads a 48-byte record of
// its own (OpenContactTest2D) instead of the contact's. Laws that modify the block or add a correction
// (cohesive, wet, glued, elastic...) keep those terms in an array that only they read. On a large scene the
// sweeps stream these arrays from memory, and only the small reaction record is written back per update.
// The full Interaction2D records are read before and written after.
#include "solver/nlgs/nlgs_2d.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>

#include "solver/laws/law_local_problem_2d.hpp"
#include "solver/nlgs/local_solver_2d.hpp"
#include "solver/nlgs/open_contact_visits.hpp"
#include "solver/nlgs/sweep_group_2d.hpp"
#include "solver/nlgs/sweep_wavefront.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

// Read by every sweep. The (t, n) components of each term sit side by side in a Vector2d, so that a
// sweep computes both components of the relative velocity, of W r and of the impulse on a body in one
// packed operation each (Eigen's 2-double packets), lane by lane in the order the scalar formulas
// take: the same values bit for bit, in fewer instructions (the sweep is bound by its instruction count).
// Two whole cache lines: a sweep of a large scene streams these records from memory at the memory's
// bandwidth, so W_tn is stored once and a tangential law shift other than a plain contact's ±0 is kept
// with the law terms, which keeps a visit to two lines.
struct alignas(64) SweepContact2D {
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // (nx, ny); t = (ny, -nx)
  Eigen::Vector2d lever_cd = Eigen::Vector2d::Zero(), lever_an = Eigen::Vector2d::Zero();  // (ℓ×t, ℓ×n)
  Eigen::Vector2d w_t = Eigen::Vector2d::Zero();  // W's first column (W_tt, W_tn)
  double w_nn = 0;
  double cov_n = 0;  // law shift of the normal free velocity
  double mu = 0;
  SignoriniCoulombReciprocals2D inverse;  // of (W, mu): the sweeps multiply instead of dividing
  std::int32_t cd = 0, an = 0;            // body indices
  // Index into the LawTerms2D array; plain (WW = W, no correction, a zero tangential shift) or inactive.
  std::int32_t law_terms = plain;
  // A plain contact's tangential law shift, +0 or -0 (RST_CLB's rstt = 0 times a negative v_t): its
  // sign is kept, since adding +0 turns a -0 velocity into +0 where adding -0 keeps it.
  float zero_shift_t = 0.0f;

  static constexpr std::int32_t plain = -1, inactive_contact = -2;
  bool inactive() const { return law_terms == inactive_contact; }
  bool has_law_terms() const { return law_terms >= 0; }

  double nx() const { return normal.x(); }
  double ny() const { return normal.y(); }
  double gcd_t() const { return lever_cd.x(); }
  double gcd_n() const { return lever_cd.y(); }
  double gan_t() const { return lever_an.x(); }
  double gan_n() const { return lever_an.y(); }
  double wtt() const { return w_t.x(); }
  double wtn() const { return w_t.y(); }
  double wnn() const { return w_nn; }
  Eigen::Vector2d w_n() const { return Eigen::Vector2d(w_t.y(), w_nn); }  // W's second column
};
static_assert(sizeof(SweepContact2D) == 128);

// What a sweep reads to pass by a contact without reaction that is due for a visit: the normal part
// of its relative velocity and its normal law shift, from the normal, the levers' normal parts and the
// bodies. Most visits of a packing's open contacts end there. In its own 48-byte record, so that they
// do not bring in the 128-byte sweep record, which on a large scene comes from beyond the caches at
// every visit.
struct OpenContactTest2D {
  double nx = 0, ny = 0, lever_cd_n = 0, lever_an_n = 0;
  // −∞ for a contact that is never passed by on this test (law terms, inactive): u_n − ∞ < 0.
  double cov_n = -std::numeric_limits<double>::infinity();
  std::int32_t cd = 0, an = 0;

  static OpenContactTest2D of(const SweepContact2D& c) {
    OpenContactTest2D t;
    t.nx = c.nx();
    t.ny = c.ny();
    t.lever_cd_n = c.gcd_n();
    t.lever_an_n = c.gan_n();
    if (c.law_terms == SweepContact2D::plain) t.cov_n = c.cov_n;
    t.cd = c.cd;
    t.an = c.an;
    return t;
  }
  // u_n + cov_n >= 0, with relative_velocity's normal lane operation for operation (the same bits).
  bool stays_open(const Eigen::Vector3d* v) const {
    const Eigen::Vector3d& a = v[cd];
    const Eigen::Vector3d& b = v[an];
    const double un =
        ((nx * (a.x() - b.x()) + ny * (a.y() - b.y())) + lever_cd_n * a.z()) - lever_an_n * b.z();
    return un + cov_n >= 0.0;
  }
};
static_assert(sizeof(OpenContactTest2D) == 48);

// The terms of a law beyond plain Signorini–Coulomb on W (contact-laws.md §2-§3).
struct LawTerms2D {
  std::uint8_t glued = 0, wet = 0, cohesive = 0;
  // Plain Signorini–Coulomb on W but for a tangential shift (RST_CLB's restitution): solved as the
  // sweep's plain path solves, with the block's reciprocals.
  std::uint8_t shift_only = 0;
  double cov_t = 0;                   // law shift of the tangential free velocity
  double wwtt = 0, wwnn = 0;          // modified diagonal of the law (WW off-diagonal = W's)
  double cor_t = 0, cor_n = 0;        // law correction added to the reaction
  double kt = 0, kn = 0, radh_t = 0;  // cohesive zone: r_coh = (radh_t, 0) + diag(kt, kn) uu
  // Cohesive zone: A = (I − WW K)⁻¹ and A WW, fixed between the checks (cohesive_solve).
  Matrix2d A = Matrix2d::Zero(), A_WW = Matrix2d::Zero();
};

// The cohesive zone's fixed matrices (contact-laws.md §3.5), once per contact and step, and again
// after a check that changed β, so that a visit does not invert and multiply them.
void prepare_cohesive_terms(double wtn, LawTerms2D& l) {
  Matrix2d WW;
  WW << l.wwtt, wtn, wtn, l.wwnn;
  Matrix2d M = Matrix2d::Identity();
  M(0, 0) -= l.wwtt * l.kt;
  M(0, 1) -= wtn * l.kn;
  M(1, 0) -= wtn * l.kt;
  M(1, 1) -= l.wwnn * l.kn;
  l.A = M.inverse();
  l.A_WW = l.A * WW;
}

// Bodies' arrays by raw pointer: a sweep holds them in registers, where through the vectors it
// reloaded their data pointers after every velocity store (Eigen's stores may alias anything).
inline Vector2d relative_velocity(const SweepContact2D& c, const Vector3d* v) {
  const Vector3d& a = v[c.cd];
  const Vector3d& b = v[c.an];
  // ut = ((tx dx + ty dy) + ℓt_cd a_ω) − ℓt_an b_ω and un alike, both lanes at once.
  const Vector2d across_x(c.ny(), c.nx()), across_y(-c.nx(), c.ny());  // (tx, nx), (ty, ny)
  return across_x * (a.x() - b.x()) + across_y * (a.y() - b.y()) + c.lever_cd * a.z() - c.lever_an * b.z();
}

// W r, both components at once: (W_tt r_t + W_tn r_n, W_tn r_t + W_nn r_n).
inline Vector2d w_times(const SweepContact2D& c, double rt, double rn) {
  return c.w_t * rt + c.w_n() * rn;
}

// u − W r.
inline Vector2d minus_w_r(const SweepContact2D& c, const Vector2d& u, double rt, double rn) {
  return u - w_times(c, rt, rn);
}

[[gnu::always_inline]] inline void inject(const SweepContact2D& c, double dt_, double dn,
                                          const Vector3d* inverse_mass, Vector3d* v) {
  const Vector2d tangent(c.ny(), -c.nx());
  const Vector2d f = tangent * dt_ + c.normal * dn;  // (fx, fy)
  const std::int32_t i = c.cd, j = c.an;
  const Vector3d& mi = inverse_mass[i];
  const Vector3d& mj = inverse_mass[j];
  v[i].head<2>() += mi.head<2>().cwiseProduct(f);
  v[i].z() += mi.z() * (dt_ * c.gcd_t() + dn * c.gcd_n());
  v[j].head<2>() -= mj.head<2>().cwiseProduct(f);
  v[j].z() -= mj.z() * (dt_ * c.gan_t() + dn * c.gan_n());
}

Matrix2d delassus_block(const Interaction2D& c, const std::vector<Vector3d>& inverse_mass) {
  Matrix2d W = Matrix2d::Zero();
  const Vector2d tangent = c.tangent();
  for (int side = 0; side < 2; ++side) {
    const Vector2d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
    const Vector3d t(tangent.x(), tangent.y(), lever(0)), n(c.normal.x(), c.normal.y(), lever(1));
    const Vector3d& m =
        inverse_mass[static_cast<std::size_t>(side == 0 ? c.candidate_body : c.antagonist_body)];
    W(0, 0) += t.cwiseProduct(m).dot(t);
    W(0, 1) += t.cwiseProduct(m).dot(n);
    W(1, 1) += n.cwiseProduct(m).dot(n);
  }
  W(1, 0) = W(0, 1);
  return W;
}

// The cohesive-zone reaction (contact-laws.md §3.5): with A = (I − WW K)⁻¹ the auxiliary
// problem is uu = A (v + WW radh) + A WW rr, solved for rr; then r = rr + radh + K uu.
void cohesive_solve(const SweepContact2D& c, const LawTerms2D& l, double vt, double vn, double& rt,
                    double& rn, ContactStatus& status) {
  const Vector2d shifted(vt + l.wwtt * l.radh_t, vn + c.wtn() * l.radh_t);  // v + WW (radh_t, 0)
  const Vector2d uf = l.A * shifted;
  const LocalSolution2D s = solve_signorini_coulomb_2d(l.A_WW, uf, c.mu);
  const Vector2d uu = uf + l.A_WW * s.r;
  rt = s.r(0) + l.radh_t + l.kt * uu(0);
  rn = s.r(1) + l.kn * uu(1);
  status = cohesive_status(s.status);
  if (s.status == ContactStatus::noctc && rn != 0.0) status = ContactStatus::Cstck;
}

// The law's reaction (correction included) for the shifted local free velocity (vt, vn), when
// the law has terms beyond W. Out of line: rare, and it would bloat the sweep's hot loop.
[[gnu::noinline]] void law_terms_solve(const SweepContact2D& c, const LawTerms2D& l, double vt, double vn,
                                       double& rt, double& rn, ContactStatus& status) {
  if (l.glued) {
    // Bilateral glue: WW r = -v.
    const double det = l.wwtt * l.wwnn - c.wtn() * c.wtn();
    rt = -(l.wwnn * vt - c.wtn() * vn) / det;
    rn = -(-c.wtn() * vt + l.wwtt * vn) / det;
    status = ContactStatus::stick;
    return;
  }
  if (l.cohesive) {
    cohesive_solve(c, l, vt, vn, rt, rn, status);
    return;
  }
  if (l.shift_only) {
    solve_signorini_coulomb_2d(c.wtt(), c.wtn(), c.wnn(), c.inverse, vt, vn, c.mu, rt, rn, status);
    return;
  }
  ContactStatus plain = ContactStatus::noctc;
  solve_signorini_coulomb_2d(l.wwtt, c.wtn(), l.wwnn, vt, vn, c.mu, rt, rn, plain);
  rt += l.cor_t;
  rn += l.cor_n;
  status = l.wet && (l.cor_n != 0.0 || l.cor_t != 0.0) ? wet_status(plain) : plain;
}

// The law's reaction (correction included) for the local free velocity ufree_loc. The plain
// Signorini–Coulomb path, taken by almost every contact, is inlined in the sweep.
[[gnu::always_inline]] inline void local_solve(const SweepContact2D& c, const std::vector<LawTerms2D>& terms,
                                               double uft, double ufn, double& rt, double& rn,
                                               ContactStatus& status) {
  if (c.has_law_terms()) [[unlikely]] {
    const LawTerms2D& l = terms[static_cast<std::size_t>(c.law_terms)];
    // Through locals (as the plain path's fallback): the sweep's rt, rn and status stay in registers.
    double law_rt = 0.0, law_rn = 0.0;
    ContactStatus law_status = ContactStatus::noctc;
    law_terms_solve(c, l, uft + l.cov_t, ufn + c.cov_n, law_rt, law_rn, law_status);
    rt = law_rt;
    rn = law_rn;
    status = law_status;
    return;
  }
  const double vt = uft + static_cast<double>(c.zero_shift_t), vn = ufn + c.cov_n;
  solve_signorini_coulomb_2d(c.wtt(), c.wtn(), c.wnn(), c.inverse, vt, vn, c.mu, rt, rn, status);
}

// Adds a contact's impulse to its two bodies (Ireac = Σ H r).
void add_impulses(const SweepContact2D& k, double rt, double rn, std::vector<Vector3d>& impulse) {
  const double tx = k.ny(), ty = -k.nx();
  const Vector3d f(rt * tx + rn * k.nx(), rt * ty + rn * k.ny(), 0.0);
  impulse[static_cast<std::size_t>(k.cd)] += f + Vector3d(0, 0, rt * k.gcd_t() + rn * k.gcd_n());
  impulse[static_cast<std::size_t>(k.an)] -= f + Vector3d(0, 0, rt * k.gan_t() + rn * k.gan_n());
}

// The sweep arrays and the group lists outlive a solve (one set per thread), so that a large scene
// keeps their pages, huge ones where the kernel gives them (large_array.hpp), and a small scene's
// step does not allocate them again.
// The sweep runs segment after segment: the groups [groups_end of the previous segment,
// groups_end), then the updates alone at scalar_positions [scalar_end of the previous, scalar_end).
struct SweepSegment {
  std::uint32_t groups_end, scalar_end;
};
struct SweepArrays2D {
  LargeArray<SweepContact2D> hot, hot_spare;
  LargeArray<ContactReaction2D> reaction, reaction_spare;
  LargeArray<ContactStatus> final_status;  // by slot, from the post pass
  LargeArray<OpenContactTest2D> open_test;
  DueVisits due_visits;
  std::vector<SweepGroup2D> groups;
  std::vector<SweepSegment> segments;
  std::vector<std::uint32_t> scalar_positions;
  std::vector<std::uint32_t>
      pending_stamp;  // by body: the serial of the pending group while it holds the body
  std::vector<Vector3d> velocity_before_post;
};
SweepArrays2D& sweep_arrays() {
  thread_local SweepArrays2D arrays;
  return arrays;
}

// The NLGS of one step, as LMGC90's ExSolver runs it: set-up, blocks of gs_it1 sweeps each ended by
// a check, the post sweep, the end of the step. Its fields are the solve's state, shared by the
// stages; the kernels (a contact's local solve, its relative velocity, the injection of its
// reaction) are the 2D rigid ones above.
struct Nlgs2D {
  Nlgs2D(const Scene2D& scene_, RigidBodies2D& bodies_, LargeArray<Interaction2D>& contacts_,
         std::span<LawState2D> law_states_, const LawStep& step_, const NlgsOptions& options_,
         QuickScramble& scramble_)
      : scene(scene_),
        bodies(bodies_),
        contacts(contacts_),
        law_states(law_states_),
        law_step(step_),
        options(options_),
        scramble(scramble_),
        h(step_.h),
        time(step_.time),
        count(contacts_.size()),
        v(bodies_.velocity),
        inverse_mass(bodies_.inverse_mass),
        order(count),
        slot(count),
        prefetch_slots(count >= kPrefetchSlotsFrom),
        law_updates_at_check(scene_.laws.size()),
        keeps_law_state(!law_states_.empty()),
        relax(options_.relax),
        keep(1.0 - options_.relax),
        relaxed(relax != 1.0),
        use_groups(options_.vector_sweeps && count >= 4 && sweep_groups_available()),
        due_visits_fit(count >= options_.due_visits_from && options_.gs_it1 > 0 &&
                       DueVisits::ring_length(options_.gs_it1) <= 64),
        stored_delassus(options_.storage == NlgsStorage::stored_delassus_loops) {}

  NlgsResult run() {
    set_up();

    if (count > 0) {
      for (int block = 0; block < options.gs_it2; ++block) {
        const auto sweeps_start = std::chrono::steady_clock::now();
        if (options.quick_scramble) scramble_order();
        // Where less than a quarter of the updates form groups, the plain loop: forming the groups (a
        // pass over every contact's record) and running the others through the segment lists cost more
        // than the groups save. Only loaded contacts form groups: with fewer than a quarter loaded, none
        // are formed.
        constexpr std::size_t quarter = 4;  // share of the updates below which the plain loop runs
        // The previous block's groups serve again while the contacts with a reaction are about as
        // many as when they were formed (within 1/16) and the order has not changed (no quick
        // scramble): which contacts share a body does not change within a step, so a group still runs
        // updates that commute with the ones between, and a lane that has lost its reaction is left to
        // the scalar update, as within a block; a contact that has gained one runs alone. The same
        // iterates bit for bit, without a pass over every contact's record to form them again.
        const bool reuse_groups =
            grouped && !options.quick_scramble &&
            16 * std::max(loaded, loaded_at_formation) <= 17 * std::min(loaded, loaded_at_formation);
        if (!reuse_groups) {
          grouped = false;
          if (use_groups && quarter * loaded >= count) {
            form_groups();
            loaded_at_formation = loaded;
            grouped = quarter * (4 * groups.size()) >= count;
            prefetch_groups = groups.size() >= kPrefetchGroupsFrom;
          }
        }
        if (!grouped && due_visits_fit) {
          due_visits.start_block(count, static_cast<std::int32_t>(result.iterations), options.gs_it1);
          for (int i = 0; i < options.gs_it1; ++i) sweep(std::false_type{}, std::true_type{});
        } else {
          for (int i = 0; i < options.gs_it1; ++i) sweep(std::false_type{}, std::false_type{});
        }
        result.sweep_seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - sweeps_start).count();
        result.converged = check();
        loaded = result.active;
        if (result.converged || result.diverged) break;
      }
    } else {
      result.converged = true;
    }
    post();
    end_of_step();
    return result;
  }

  // Prep: Delassus blocks, the laws' local problems, the sweep arrays; V = V_free + M⁻¹ H r_warm.
  void set_up() {
    std::iota(order.begin(), order.end(), 0u);
    reorder();
    hot.assign(count, SweepContact2D{});
    open_test.resize(count);
    reaction.assign(count, ContactReaction2D{});
    final_status.assign(count, ContactStatus::noctc);
    for (std::size_t l = 0; l < scene.laws.size(); ++l)
      any_update_at_check |= (law_updates_at_check[l] = updates_at_check(scene.laws[l].law)) != 0;
    v = bodies.velocity_free;
    double q2 = 0.0;
    // The law's local problem is built beside each interaction, which keeps what the law changed.
    LocalProblem2D c;
    for (std::size_t a = 0; a < count; ++a) {
      static_cast<Interaction2D&>(c) = contacts[a];
      c.internal = keeps_law_state ? law_states[a].internal : std::array<double, 6>{};
      const ContactLaw& law = scene.laws[static_cast<std::size_t>(c.law)].law;
      c.W = delassus_block(c, inverse_mass);
      prepare_local_problem_2d(law, c, law_step);
      if (c.inactive) c.r.setZero();
      contacts[a] = c;
      if (keeps_law_state) law_states[a].internal = c.internal;
      if (prefetch_slots) {
        prefetch_gathered<true>(hot, slot, a);
        prefetch_gathered<true>(reaction, slot, a);
        prefetch_gathered<true>(open_test, slot, a);
      }
      SweepContact2D& k = hot[slot[a]];
      k.cd = c.candidate_body;
      k.an = c.antagonist_body;
      k.normal = c.normal;
      k.lever_cd = c.lever_candidate;
      k.lever_an = c.lever_antagonist;
      k.w_t = Vector2d(c.W(0, 0), c.W(0, 1));
      k.w_nn = c.W(1, 1);
      k.cov_n = c.covfree(1);
      k.mu = c.mu;
      k.inverse = signorini_coulomb_reciprocals_2d(k.wtt(), k.wtn(), k.wnn(), k.mu);
      // The flags tested below from these locals: read back from `l`, whose three bytes were just
      // stored one by one, they would be loaded as one word that has to wait for the stores.
      const bool glued = std::holds_alternative<CoupledDof>(law), wet = is_wet_law(law);
      LawTerms2D l;
      l.glued = glued;
      l.wet = wet;
      l.cohesive = c.cohesive;
      l.wwtt = c.WW(0, 0);
      l.wwnn = c.WW(1, 1);
      l.cor_t = c.correction(0);
      l.cor_n = c.correction(1);
      l.kt = c.cohesive_slope(0);
      l.kn = c.cohesive_slope(1);
      l.radh_t = c.cohesive_shift_t;
      l.cov_t = c.covfree(0);
      const bool plain_but_shift = !glued && !wet && !c.cohesive && l.wwtt == k.wtt() && l.wwnn == k.wnn() &&
                                   l.cor_t == 0.0 && l.cor_n == 0.0;
      l.shift_only = plain_but_shift;
      if (l.cohesive) prepare_cohesive_terms(k.wtn(), l);
      if (c.inactive) {
        k.law_terms = SweepContact2D::inactive_contact;  // no law term is read for it
      } else if (plain_but_shift && l.cov_t == 0.0) {
        k.zero_shift_t = static_cast<float>(l.cov_t);  // exact, sign included
      } else {
        k.law_terms = static_cast<std::int32_t>(terms.size());
        terms.push_back(l);
      }
      open_test[slot[a]] = OpenContactTest2D::of(k);
      ContactReaction2D& s = reaction[slot[a]];
      s.rt = c.r(0);
      s.rn = c.r(1);
      loaded += s.rt != 0.0 || s.rn != 0.0;
      // ‖q‖: free local velocities of the problem (law shifts included), fc3d/FORMAT.md §3.
      q2 += (relative_velocity(k, bodies.velocity_free.data()) + c.covfree).squaredNorm();
    }
    inject_all();
    result.free_velocity_norm = std::sqrt(q2);
    if (options.quick_scramble) scramble.prepare(count);
  }

  // The sweeps run the updates in wavefront order (sweep_wavefront.hpp: the same result bit for
  // bit, consecutive updates seldom sharing a body), and the two sweep arrays are laid out in that
  // order, so that a sweep reads memory in sequence. The set-up writes each contact's records at its
  // slot, and the passes in contact order (the checks, the end of the step) read them there, so their
  // sums keep their order; the arrays are permuted only when the quick scramble changes the order,
  // not gathered into the order before every block and scattered back after it.
  void reorder() {
    wavefront.reorder(
        order,
        [&](std::uint32_t a) {
          // A long list's records come from beyond the caches (detection wrote them), and the reorder
          // waits on this load. The record kPrefetchAhead on in contact order is the one that many
          // places on in `order`, which is the contact order; after a quick scramble it is not, and
          // the prefetch only guesses wrong.
          prefetch_ahead<false>(contacts, a);
          return std::pair(contacts[a].candidate_body, contacts[a].antagonist_body);
        },
        [&](std::int32_t i) { return !inverse_mass[static_cast<std::size_t>(i)].isZero(0.0); }, bodies.size(),
        execution);
    for (std::size_t p = 0; p < count; ++p) slot[execution[p]] = static_cast<std::uint32_t>(p);
  }

  // Injected in contact order, as the velocities' sums always were.
  void inject_all() {
    for (std::size_t a = 0; a < count; ++a) {
      if (prefetch_slots) {
        prefetch_gathered<false>(hot, slot, a);
        prefetch_gathered<false>(reaction, slot, a);
      }
      const ContactReaction2D& s = reaction[slot[a]];
      if (s.rt != 0.0 || s.rn != 0.0) inject(hot[slot[a]], s.rt, s.rn, inverse_mass.data(), v.data());
    }
  }

  const LawTerms2D& law_terms_of(const SweepContact2D& c) const {
    return c.has_law_terms() ? terms[static_cast<std::size_t>(c.law_terms)] : plain_terms;
  }

  // After a check changed a contact's law state (update_law_at_check): its μ and cohesive terms.
  // A contact whose law updates at checks is cohesive at the start, so it has its LawTerms2D.
  void refresh_law_terms(std::size_t a, const LocalProblem2D& c) {
    SweepContact2D& k = hot[slot[a]];
    k.mu = c.mu;
    k.inverse = signorini_coulomb_reciprocals_2d(k.wtt(), k.wtn(), k.wnn(), k.mu);
    if (!k.has_law_terms()) return;
    LawTerms2D& l = terms[static_cast<std::size_t>(k.law_terms)];
    l.cohesive = c.cohesive;
    l.kt = c.cohesive_slope(0);
    l.kn = c.cohesive_slope(1);
    l.radh_t = c.cohesive_shift_t;
    if (l.cohesive) prepare_cohesive_terms(k.wtn(), l);
  }

  // A check's or the post pass's re-evaluation of contact a's law state (update_law_at_check) from
  // the velocity (ut, un) of its local solution, into `problem`; true when the state changed, and
  // then the interaction keeps the new state.
  bool update_law_state(std::size_t a, double ut, double un, LocalProblem2D& problem) {
    const auto l = static_cast<std::size_t>(contacts[a].law);
    if (!law_updates_at_check[l]) return false;
    static_cast<Interaction2D&>(problem) = contacts[a];
    problem.internal = keeps_law_state ? law_states[a].internal : std::array<double, 6>{};
    if (!update_law_at_check(scene.laws[l].law, problem, Vector2d(ut, un), law_step)) return false;
    contacts[a] = problem;
    if (keeps_law_state) law_states[a].internal = problem.internal;
    return true;
  }

  // The quick scramble's new order: the sweep arrays permuted into it.
  void scramble_order() {
    scramble.scramble(order);
    hot_spare.resize(count);
    reaction_spare.resize(count);
    const std::vector<std::uint32_t> old_slot = slot;
    reorder();
    for (std::size_t p = 0; p < count; ++p) {
      hot_spare[p] = hot[old_slot[execution[p]]];
      reaction_spare[p] = reaction[old_slot[execution[p]]];
    }
    std::swap(hot, hot_spare);
    std::swap(reaction, reaction_spare);
    for (std::size_t p = 0; p < count; ++p) open_test[p] = OpenContactTest2D::of(hot[p]);
  }

  void form_groups() {
    groups.clear();
    segments.clear();
    scalar_positions.clear();
    pending_stamp.assign(bodies.size(), 0u);
    std::uint32_t serial = 1, pending[4];
    int filled = 0;
    std::size_t scalars_in_segment = 0;
    auto moves = [&](std::int32_t body) { return !inverse_mass[static_cast<std::size_t>(body)].isZero(0.0); };
    // A group keeps one translational inverse mass per body (SweepGroup2D): bit for bit the same
    // along x and y, which a body with one of the two driven is not.
    auto same_along_x_and_y = [&](std::int32_t body) {
      const Vector3d& m = inverse_mass[static_cast<std::size_t>(body)];
      return std::bit_cast<std::uint64_t>(m.x()) == std::bit_cast<std::uint64_t>(m.y());
    };
    auto emit_scalar = [&](std::uint32_t p) {
      scalar_positions.push_back(p);
      ++scalars_in_segment;
    };
    // The pending contacts as a group, or alone when fewer than four.
    auto flush = [&] {
      if (filled == 4) {
        if (scalars_in_segment > 0) {
          segments.push_back({static_cast<std::uint32_t>(groups.size()),
                              static_cast<std::uint32_t>(scalar_positions.size())});
          scalars_in_segment = 0;
        }
        SweepGroup2D& g = groups.emplace_back();
        for (int lane = 0; lane < 4; ++lane) {
          const SweepContact2D& c = hot[pending[lane]];
          g.nx[lane] = c.nx();
          g.ny[lane] = c.ny();
          g.lever_cd_t[lane] = c.gcd_t();
          g.lever_cd_n[lane] = c.gcd_n();
          g.lever_an_t[lane] = c.gan_t();
          g.lever_an_n[lane] = c.gan_n();
          g.wtt[lane] = c.wtt();
          g.wtn[lane] = c.wtn();
          g.wnn[lane] = c.wnn();
          g.cov_n[lane] = c.cov_n;
          g.mu[lane] = c.mu;
          g.inverse_det[lane] = c.inverse.det;
          g.inverse_forward[lane] = c.inverse.forward;
          g.inverse_backward[lane] = c.inverse.backward;
          const Vector3d& mi = inverse_mass[static_cast<std::size_t>(c.cd)];
          const Vector3d& mj = inverse_mass[static_cast<std::size_t>(c.an)];
          g.inverse_mass_cd[lane] = mi.x();
          g.inverse_inertia_cd[lane] = mi.z();
          g.inverse_mass_an[lane] = mj.x();
          g.inverse_inertia_an[lane] = mj.z();
          g.cd[lane] = c.cd;
          g.an[lane] = c.an;
          g.position[lane] = pending[lane];
        }
      } else {
        for (int lane = 0; lane < filled; ++lane) emit_scalar(pending[lane]);
      }
      filled = 0;
      ++serial;
    };
    // In execution order. A pending group runs where it is flushed, so the updates emitted alone
    // meanwhile, later in the order, run before it: they share no movable body with it (else it is
    // flushed first), and two updates that share none commute exactly. Within a wavefront level
    // nothing is shared; across levels the pending contacts join the next level's when they can.
    for (std::uint32_t p = 0; p < count; ++p) {
      const SweepContact2D& k = hot[p];
      const bool cd_pending = moves(k.cd) && pending_stamp[static_cast<std::size_t>(k.cd)] == serial;
      const bool an_pending = moves(k.an) && pending_stamp[static_cast<std::size_t>(k.an)] == serial;
      if (cd_pending || an_pending) flush();
      const ContactReaction2D& s = reaction[p];
      const bool plain = k.law_terms == SweepContact2D::plain &&
                         !(any_update_at_check &&
                           law_updates_at_check[static_cast<std::size_t>(contacts[execution[p]].law)]);
      if (!plain || (s.rt == 0.0 && s.rn == 0.0) || !same_along_x_and_y(k.cd) || !same_along_x_and_y(k.an)) {
        emit_scalar(p);
        continue;
      }
      pending[filled++] = p;
      pending_stamp[static_cast<std::size_t>(k.cd)] = pending_stamp[static_cast<std::size_t>(k.an)] = serial;
      if (filled == 4) flush();
    }
    flush();
    segments.push_back(
        {static_cast<std::uint32_t>(groups.size()), static_cast<std::uint32_t>(scalar_positions.size())});
  }

  // One Gauss–Seidel pass (in execution order, the sweep order's result); the post pass never skips and
  // is not counted as an iteration.
  // Instantiated once per kind (std::bool_constant): the post pass's tests fold away in the sweeps.
  // The sweeps by due visits are an instantiation of their own, so that the walk of every contact
  // compiles as it would without them (one body for both slows the walk).
  void sweep(auto post_kind, auto due_visits_kind) {
    constexpr bool post = decltype(post_kind)::value;
    constexpr bool by_due = decltype(due_visits_kind)::value;
    const SweepContact2D* sweep_hot = hot.data();
    const OpenContactTest2D* sweep_open_test = open_test.data();
    Vector3d* const velocity = v.data();
    const Vector3d* const inverse_masses = inverse_mass.data();
    ContactReaction2D* sweep_reaction = reaction.data();
    const auto sweep_number = static_cast<std::int32_t>(result.iterations);
    // The update at execution position `index`.
    auto update = [&](std::size_t index) __attribute__((always_inline)) {
      ContactReaction2D& s = sweep_reaction[index];
      // A contact without reaction that this sweep passes by is decided on its reaction record alone:
      // in a packing most contacts are open, and reading their sweep record as well made the
      // sweeps of large scenes stream nearly five times the memory (the post pass never skips).
      // Only a contact without reaction has its next solve ahead of the sweep (a reaction restarts
      // the schedule, next = 0), so `next` alone decides, before the reaction is compared with zero.
      // (The sweeps by due visits come only to contacts whose schedule is due.)
      if (!post && !by_due && s.visits.passes_by(sweep_number)) return;
      const bool without_reaction = s.rt == 0.0 && s.rn == 0.0;
      if (!post && without_reaction) {
        s.visits.count_solve(sweep_number);
        // A plain contact without reaction stays without one while u_n + cov_n >= 0 (its local solve
        // returns r = 0, and the update would inject nothing): decided on the relative velocity alone,
        // without the solve and the update. Most open contacts of a packing stay open at their visits.
        if (sweep_open_test[index].stays_open(velocity)) return;
      }
      const SweepContact2D& c = sweep_hot[index];
      if (c.inactive()) {
        if (s.rt != 0.0 || s.rn != 0.0) {
          inject(c, -s.rt, -s.rn, inverse_masses, velocity);
          s.rt = s.rn = 0.0;
        }
        if (post) final_status[index] = ContactStatus::noctc;
        return;
      }
      const Vector2d u = relative_velocity(c, velocity);
      const Vector2d uf = minus_w_r(c, u, s.rt, s.rn);
      const double uft = uf.x(), ufn = uf.y();
      double rt, rn;
      ContactStatus status;
      local_solve(c, terms, uft, ufn, rt, rn, status);
      // LMGC90's post pass (solve_nlgs i_post) re-evaluates the laws' state as a check does, from
      // this local solution's velocity; the end of the step then stores it unless the final
      // velocity's is taken.
      if (post && any_update_at_check) [[unlikely]] {
        const Vector2d u_solved = w_times(c, rt, rn) + uf;
        LocalProblem2D problem;
        update_law_state(execution[index], u_solved.x(), u_solved.y(), problem);
      }
      if (relaxed) {
        rt = relax * rt + keep * s.rt;
        rn = relax * rn + keep * s.rn;
      }
      if (std::fabs(rt) < 1e-24) rt = 0.0;
      if (std::fabs(rn) < 1e-24) rn = 0.0;
      // Injected even when zero: whether a reaction changed is as good as random in a sweep of
      // active contacts, and the mispredicted test costs more than the update.
      inject(c, rt - s.rt, rn - s.rn, inverse_masses, velocity);
      s.rt = rt;
      s.rn = rn;
      if (post) final_status[index] = status;
      // rt != 0 || rn != 0 on the bits, less the sign (-0 is zero, NaN is not): no branch.
      s.visits.restart_if(((std::bit_cast<std::uint64_t>(rt) | std::bit_cast<std::uint64_t>(rn)) << 1) != 0);
    };
    if constexpr (by_due) {
      due_visits.sweep(
          sweep_number,
          [&](std::size_t index) __attribute__((always_inline)) {
            update(index);
            return sweep_reaction[index].visits;
          },
          // What the visit will read: the sweep record of a contact with a reaction (both lines),
          // else its open-contact test (which may straddle two).
          [&](std::size_t index) __attribute__((always_inline)) {
            const ContactReaction2D& s = sweep_reaction[index];
            if (s.rt != 0.0 || s.rn != 0.0) {
              const char* record = reinterpret_cast<const char*>(sweep_hot + index);
              __builtin_prefetch(record);
              __builtin_prefetch(record + sizeof(SweepContact2D) - 1);
            } else {
              const char* test = reinterpret_cast<const char*>(sweep_open_test + index);
              __builtin_prefetch(test);
              __builtin_prefetch(test + sizeof(OpenContactTest2D) - 1);
            }
          });
    } else if (!post && grouped) {
      std::uint32_t group = 0, scalar = 0;
      const std::size_t group_count = groups.size();
      for (const SweepSegment& segment : segments) {
        for (; group < segment.groups_end; ++group) {
          const SweepGroup2D& g = groups[group];
          if (prefetch_groups && group + kGroupsAhead < group_count) {
            const char* ahead = reinterpret_cast<const char*>(groups.data() + group + kGroupsAhead);
            for (std::size_t line = 0; line < sizeof(SweepGroup2D); line += 64)
              __builtin_prefetch(ahead + line);
          }
          const int done = sweep_group_2d(g, sweep_reaction, velocity, relaxed, relax, keep);
          if (done != 0xF) [[unlikely]]
            for (int lane = 0; lane < 4; ++lane)
              if ((done & (1 << lane)) == 0) update(g.position[lane]);
        }
        for (; scalar < segment.scalar_end; ++scalar) update(scalar_positions[scalar]);
      }
    } else {
      for (std::size_t index = 0; index < count; ++index) update(index);
    }
    if (!post) ++result.iterations;
  }

  // Natural-map residual of one contact at the current state (law in auxiliary variables).
  double residual2_of(const SweepContact2D& c, const ContactReaction2D& s, double uft, double ufn) const {
    if (c.inactive()) return s.rt * s.rt + s.rn * s.rn;
    const LawTerms2D& l = law_terms_of(c);
    const double wwtt = c.has_law_terms() ? l.wwtt : c.wtt(), wwnn = c.has_law_terms() ? l.wwnn : c.wnn();
    const double cov_t = c.has_law_terms() ? l.cov_t : static_cast<double>(c.zero_shift_t);
    if (l.cohesive) {
      // Natural map of the auxiliary problem: uu = v + WW r, rr = r − radh − K uu.
      const double ut = uft + cov_t + wwtt * s.rt + c.wtn() * s.rn;
      const double un = ufn + c.cov_n + c.wtn() * s.rt + wwnn * s.rn;
      const double rrt = s.rt - l.radh_t - l.kt * ut, rrn = s.rn - l.kn * un;
      return natural_map_residual_squared_2d(Vector2d(rrt, rrn), Vector2d(ut, un), c.mu);
    }
    const double rrt = s.rt - l.cor_t, rrn = s.rn - l.cor_n;
    const double ut = uft + cov_t + wwtt * rrt + c.wtn() * rrn;
    const double un = ufn + c.cov_n + c.wtn() * rrt + wwnn * rrn;
    if (l.glued) return ut * ut + un * un;
    return natural_map_residual_squared_2d(Vector2d(rrt, rrn), Vector2d(ut, un), c.mu);
  }

  // One check pass (numerics.md §4.1): the local solve applied to the current state, no update.
  bool check() {
    NlgsCheckSums sums;
    double residual2 = 0;
    std::size_t vanishing = 0;
    result.active = 0;
    result.hover = result.stick = result.slide = 0;
    const bool normal_only = options.norm == NlgsNorm::quad_normal;
    for (std::size_t a = 0; a < count; ++a) {
      if (prefetch_slots) {
        prefetch_gathered<false>(hot, slot, a);
        prefetch_gathered<true>(reaction, slot, a);
      }
      const SweepContact2D& c = hot[slot[a]];
      ContactReaction2D& s = reaction[slot[a]];
      s.visits.restart();  // after every check
      const Vector2d u = relative_velocity(c, v.data());
      const Vector2d uf = minus_w_r(c, u, s.rt, s.rn);
      const double uft = uf.x(), ufn = uf.y();
      residual2 += residual2_of(c, s, uft, ufn);
      double r1t = s.rt, r1n = s.rn, r2t = 0, r2n = 0;
      if (!c.inactive()) {
        ContactStatus status;
        local_solve(c, terms, uft, ufn, r2t, r2n, status);
        result.count_nature(status_nature(status));
      } else {
        r1t = r1n = 0.0;
        ++result.hover;
      }
      const Vector2d u2 = w_times(c, r2t, r2n) + uf;
      const double u2t = u2.x(), u2n = u2.y();
      // Laws that re-evaluate their state at a check do it with this solution's velocity; the
      // sweeps after the check read the contact's new terms.
      if (any_update_at_check && !c.inactive()) {
        LocalProblem2D problem;
        if (update_law_state(a, u2t, u2n, problem)) refresh_law_terms(a, problem);
      }
      const double mt = 0.5 * (r1t + r2t), mn = 0.5 * (r1n + r2n);
      const double dvt = u(0) - u2t, dvn = u(1) - u2n;
      if (mt == 0.0 && mn == 0.0) ++vanishing;
      if (s.rt != 0.0 || s.rn != 0.0) ++result.active;
      if (normal_only) {
        // 'QuaN ': normal components only.
        const double dvdv = dvn * dvn, wrr = 0.5 * c.wnn() * (r1n * r1n + r2n * r2n);
        sums.add(dvdv, dvdv * mn * mn, mn * dvn, wrr, c.wnn() * wrr);
        continue;
      }
      const double dvdv = dvt * dvt + dvn * dvn, rr = mt * mt + mn * mn;
      const Vector2d w1 = w_times(c, r1t, r1n), w2 = w_times(c, r2t, r2n);
      const double w1t = w1.x(), w1n = w1.y(), w2t = w2.x(), w2n = w2.y();
      sums.add(dvdv, dvdv * rr, mt * dvt + mn * dvn, 0.5 * (w1t * r1t + w1n * r1n + w2t * r2t + w2n * r2n),
               0.5 * (w1t * w1t + w1n * w1n + w2t * w2t + w2n * w2n));
    }
    result.residual_absolute = std::sqrt(residual2);
    result.residual_relative = result.free_velocity_norm > 0.0
                                   ? result.residual_absolute / result.free_velocity_norm
                                   : result.residual_absolute;
    sums.active = static_cast<double>(count - vanishing);
    NlgsNorms& q = result.norms;
    q = nlgs_norms(sums, options.tolerance);
    if (!std::isfinite(q.mean_dvor) || !std::isfinite(q.quad_dv) || !std::isfinite(residual2))
      result.diverged = true;
    bool passed = nlgs_check_passes(options.norm, q);
    if (options.residual_target > 0.0) passed = passed || result.residual_relative <= options.residual_target;
    return passed;
  }

  void post() {
    // Post (docs/lmgc90-facts/rigid-2d.md §5.3): velocities rebuilt from scratch (Rnod = H r),
    // one more relaxed sweep, then the final local velocities and statuses.
    v = bodies.velocity_free;
    inject_all();
    // With Stored_Delassus_Loops, LMGC90's post sweep updates the reactions without injecting them
    // (mod_nlgs solve_nlgs: injj_ only when not SDLactif): the bodies end the step with the
    // impulses and velocities of the reactions before it. Exchange_Local_Global injects them.
    if (stored_delassus) {
      velocity_before_post = v;
      std::fill(bodies.impulse.begin(), bodies.impulse.end(), Vector3d::Zero());
      for (std::size_t a = 0; a < count; ++a) {
        const SweepContact2D& k = hot[slot[a]];
        const ContactReaction2D& s = reaction[slot[a]];
        add_impulses(k, s.rt, s.rn, bodies.impulse);
      }
    }
    if (count > 0) sweep(std::true_type{}, std::false_type{});
  }

  void end_of_step() {
    // The achieved error is the one of the reactions actually returned (after the post sweep).
    double residual2 = 0.0;
    result.active = 0;
    if (!stored_delassus) std::fill(bodies.impulse.begin(), bodies.impulse.end(), Vector3d::Zero());
    LawState2D unused_law_state;  // the state handed to a law without internals, which does not touch it
    for (std::size_t a = 0; a < count; ++a) {
      prefetch_ahead<true>(contacts, a);  // the records the end writes, as in the reorder
      if (prefetch_slots) {
        prefetch_gathered<false>(hot, slot, a);
        prefetch_gathered<false>(reaction, slot, a);
      }
      const SweepContact2D& k = hot[slot[a]];
      const ContactReaction2D& s = reaction[slot[a]];
      Interaction2D& c = contacts[a];
      const Vector2d u = relative_velocity(k, v.data());
      const Vector2d uf = minus_w_r(k, u, s.rt, s.rn);
      residual2 += residual2_of(k, s, uf.x(), uf.y());
      if (s.rt != 0.0 || s.rn != 0.0) ++result.active;
      c.r = Vector2d(s.rt, s.rn);
      c.u = u;
      const LawTerms2D& l = law_terms_of(k);
      const bool wet_or_cohesive = l.wet || l.cohesive;
      c.status =
          (s.rt == 0.0 && s.rn == 0.0 && !wet_or_cohesive) ? ContactStatus::noctc : final_status[slot[a]];
      // Contact impulses of every body (Ireac = Σ H r), driven dofs included (TORQUE EVOLUTION).
      if (!stored_delassus) add_impulses(k, s.rt, s.rn, bodies.impulse);
      finish_step_2d(scene.laws[static_cast<std::size_t>(c.law)].law, c,
                     keeps_law_state ? law_states[a] : unused_law_state, h, time);
    }
    if (stored_delassus) v = velocity_before_post;
    result.residual_absolute = std::sqrt(residual2);
    result.residual_relative = result.free_velocity_norm > 0.0
                                   ? result.residual_absolute / result.free_velocity_norm
                                   : result.residual_absolute;
  }

  const Scene2D& scene;
  RigidBodies2D& bodies;
  LargeArray<Interaction2D>& contacts;
  std::span<LawState2D> law_states;
  const LawStep& law_step;
  const NlgsOptions& options;
  QuickScramble& scramble;
  const double h, time;
  NlgsResult result;
  const std::size_t count;
  std::vector<Vector3d>& v;
  const std::vector<Vector3d>& inverse_mass;
  std::vector<std::uint32_t> order, execution, slot;
  SweepWavefront wavefront;
  SweepArrays2D& arrays = sweep_arrays();
  LargeArray<SweepContact2D>& hot = arrays.hot;
  LargeArray<SweepContact2D>& hot_spare = arrays.hot_spare;
  LargeArray<ContactReaction2D>& reaction = arrays.reaction;
  LargeArray<ContactReaction2D>& reaction_spare = arrays.reaction_spare;
  LargeArray<ContactStatus>& final_status = arrays.final_status;
  LargeArray<OpenContactTest2D>& open_test = arrays.open_test;
  // The passes in contact order (the set-up, the injections, the checks, the end of the step) read
  // the sweep records at each contact's slot. In a square box of disks a window's wavefront levels
  // interleave two or three rows, so from one contact to the next the slot moves on by 1, 3 or 5
  // records, a pattern the hardware prefetcher does not keep up with: the end pass's first read of a
  // record and the set-up's first store wait on memory. So those passes ask for the records
  // kPrefetchAhead contacts on, once the sweep records outgrow half of a core's L2 (below that they
  // are in L2, and the prefetches are instructions spent).
  static constexpr std::size_t kPrefetchSlotsFrom = (512 * 1024) / sizeof(SweepContact2D);
  const bool prefetch_slots;
  std::vector<LawTerms2D> terms;
  std::vector<std::uint8_t> law_updates_at_check;
  bool any_update_at_check = false;
  std::size_t loaded = 0;  // contacts with a reaction: the warm start's, then each check's
  // The law's local problem is built beside each interaction, which keeps what the law changed.
  const bool keeps_law_state;
  const LawTerms2D plain_terms;  // WW = W, no correction (wwtt, wwnn unused: W's are read)
  const double relax, keep;
  const bool relaxed;  // RELAX 1 (every example): the blend is skipped, not multiplied out
  // Groups of four plain updates that share no movable body, run at once (sweep_group_2d.hpp), for
  // the contacts with a reaction when they are formed: the open ones are passed by on their
  // reaction records (the scalar path), a group's lanes would mostly idle. Formed at the first
  // block, and again after a check that changed the number of loaded contacts by more than 1/16 or
  // a quick scramble (the order has changed): see reuse_groups below.
  const bool use_groups;
  bool grouped = false;                 // this block's sweeps run the groups
  std::size_t loaded_at_formation = 0;  // contacts with a reaction when the groups were formed
  // The sweeps that run no groups visit the contacts their schedules make due (open_contact_visits.hpp)
  // in a long list (NlgsOptions::due_visits_from), where a block is short enough for a small ring of
  // bitmaps (gs_it1 up to about 2000).
  DueVisits& due_visits = arrays.due_visits;
  const bool due_visits_fit;
  std::vector<SweepGroup2D>& groups = arrays.groups;
  // A sweep reads the groups in sequence, and its first load of a group misses the caches once they
  // no longer hold the array. So the group kGroupsAhead on is prefetched, once the array outgrows what
  // a core's L2 keeps beside the bodies and the reactions (below that the array is in L2, and the
  // prefetches are instructions spent).
  static constexpr std::size_t kGroupsAhead = 8;
  static constexpr std::size_t kPrefetchGroupsFrom = (512 * 1024) / sizeof(SweepGroup2D);
  bool prefetch_groups = false;
  std::vector<SweepSegment>& segments = arrays.segments;
  std::vector<std::uint32_t>& scalar_positions = arrays.scalar_positions;
  std::vector<std::uint32_t>& pending_stamp = arrays.pending_stamp;
  // With Stored_Delassus_Loops, LMGC90's post sweep updates the reactions without injecting them
  // (mod_nlgs solve_nlgs: injj_ only when not SDLactif): the bodies end the step with the
  // impulses and velocities of the reactions before it. Exchange_Local_Global injects them.
  const bool stored_delassus;
  std::vector<Vector3d>& velocity_before_post = arrays.velocity_before_post;
};

}  // namespace

NlgsResult solve_nlgs_2d(const Scene2D& scene, RigidBodies2D& bodies, LargeArray<Interaction2D>& contacts,
                         std::span<LawState2D> law_states, const LawStep& step, const NlgsOptions& options,
                         QuickScramble& scramble) {
  return Nlgs2D(scene, bodies, contacts, law_states, step, options, scramble).run();
}

}  // namespace lmgc::solver
