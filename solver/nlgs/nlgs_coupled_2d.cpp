#include "solver/nlgs/nlgs_coupled_2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <variant>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "solver/laws/law_local_problem_2d.hpp"
#include "solver/model/contact_kinematics_2d.hpp"
#include "solver/model/mesh_contact_2d.hpp"
#include "solver/nlgs/local_solver_2d.hpp"
#include "solver/nlgs/open_contact_visits.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

// One side of a contact as the blocks see it: the body it moves and, per local component (t, n),
// the coefficients of H on that body's dofs. A rigid body: (t_x, t_y, ℓ×t) on (vx, vy, ω); a mesh:
// the rows of mesh_side_rows on the four dofs of the side's two nodes, which index rows of the body's
// condensed compliance. `h` maps velocities to the side's local velocity, `hr` the contact's impulse
// to the body's: the same rows but for a DISKL.
struct Side {
  bool mesh = false;
  bool moves = false;  // a rigid body with an inverse mass, or a mesh
  std::int32_t body = 0;
  std::array<std::int32_t, 4> rows{};         // mesh: rows of contact_compliance of (a_x, a_y, b_x, b_y)
  std::array<std::int32_t, 4> dofs{};         // mesh: the dofs themselves
  std::array<std::array<double, 4>, 2> h{};   // [component][entry]; rigid: 3 entries
  std::array<std::array<double, 4>, 2> hr{};  // the same for the impulse
};

Side side_of(const Scene2D& scene, const Interaction2D& c, int side) {
  Side s;
  const Vector2d t = c.tangent(), n = c.normal;
  if (side_on_mesh(c.family, side)) {
    const MeshSideRows m = mesh_side_rows(scene, c, side);
    const MeshBodyState& state = scene.deformable.states[static_cast<std::size_t>(m.side.mesh)];
    s.mesh = true;
    s.moves = true;
    s.body = m.side.mesh;
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d) {
        const std::size_t e = static_cast<std::size_t>(2 * k + d);
        s.dofs[e] = 2 * m.side.nodes[static_cast<std::size_t>(k)] + d;
        s.rows[e] = state.compliance_row[static_cast<std::size_t>(s.dofs[e])];
      }
    s.h = m.velocity;
    s.hr = m.reaction;
  } else {
    s.body = side == 0 ? c.candidate_body : c.antagonist_body;
    s.moves = !scene.bodies.inverse_mass[static_cast<std::size_t>(s.body)].isZero(0.0);
    const Vector2d& lever = side == 0 ? c.lever_candidate : c.lever_antagonist;
    s.h[0] = {t.x(), t.y(), lever(0), 0.0};
    s.h[1] = {n.x(), n.y(), lever(1), 0.0};
    s.hr = s.h;
  }
  return s;
}

bool same_body(const Side& a, const Side& b) {
  return a.mesh == b.mesh && a.body == b.body;
}

// The block of W coupling the velocity of side a (of contact i) to the reaction on side b (of
// contact j), both on one body: H_aᵀ A H_b.
Matrix2d side_block(const Scene2D& scene, const Side& a, const Side& b) {
  Matrix2d W = Matrix2d::Zero();
  if (a.mesh) {
    const Eigen::MatrixXd& C = scene.deformable.states[static_cast<std::size_t>(a.body)].contact_compliance;
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 2; ++l) {
        double w = 0.0;
        for (std::size_t p = 0; p < 4; ++p)
          for (std::size_t q = 0; q < 4; ++q)
            w += a.h[static_cast<std::size_t>(k)][p] * C(a.rows[p], b.rows[q]) *
                 b.hr[static_cast<std::size_t>(l)][q];
        W(k, l) = w;
      }
  } else {
    const Vector3d& m = scene.bodies.inverse_mass[static_cast<std::size_t>(a.body)];
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 2; ++l) {
        double w = 0.0;
        for (std::size_t p = 0; p < 3; ++p)
          w += a.h[static_cast<std::size_t>(k)][p] * m(static_cast<Eigen::Index>(p)) *
               b.hr[static_cast<std::size_t>(l)][p];
        W(k, l) = w;
      }
  }
  return W;
}

// Laws whose first internal variable is the contact length ('taille_ele'): LMGC90 fills it with the
// candidate's length for CLALp and CLJCx, 0 otherwise (mod_nlgs prep_nlgs, GAP_SGR_CLB and kin).
bool first_internal_is_length(const ContactLaw& law) {
  const grammar::LawKind* kind = grammar::find_law_kind(law_keyword(law));
  return kind && !kind->internals_2d.slots.empty() &&
         kind->internals_2d.slots[0].text.starts_with("taille_ele");
}

struct CoupledNlgs2D {
  CoupledNlgs2D(Scene2D& scene_, LargeArray<Interaction2D>& contacts_, std::span<LawState2D> law_states_,
                const LawStep& step_, const NlgsOptions& options_, QuickScramble& scramble_)
      : scene(scene_),
        contacts(contacts_),
        law_states(law_states_),
        law_step(step_),
        options(options_),
        scramble(scramble_),
        count(contacts_.size()),
        keeps_law_state(!law_states_.empty()) {}

  NlgsResult run() {
    set_up();
    if (count > 0) {
      for (int block = 0; block < options.gs_it2; ++block) {
        const auto start = std::chrono::steady_clock::now();
        if (options.quick_scramble) {
          std::iota(order.begin(), order.end(), 0u);
          scramble.scramble(order);
        }
        for (int i = 0; i < options.gs_it1; ++i) sweep(false);
        result.sweep_seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.converged = check();
        if (result.converged || result.diverged) break;
      }
    } else {
      result.converged = true;
    }
    post();
    end_of_step();
    return result;
  }

  void set_up() {
    prepare_contact_compliance(scene.deformable);
    problems.resize(count);
    sides.resize(count);
    free_velocity.resize(count);
    final_status.assign(count, ContactStatus::noctc);
    post_velocity.assign(count, Vector2d::Zero());
    solved_in_post.assign(count, 0);
    schedule.assign(count, OpenContactSchedule{});
    order.resize(count);
    std::iota(order.begin(), order.end(), 0u);
    any_update_at_check = false;
    internal_is_length.clear();
    for (const NamedLaw& l : scene.laws) {
      any_update_at_check |= updates_at_check(l.law);
      // Not the cohesive zones': their prepare sets their length (cohesive_zone.hpp).
      internal_is_length.push_back(first_internal_is_length(l.law) && law_internal_count(l.law) <= 1);
    }
    double q2 = 0.0;
    for (std::size_t a = 0; a < count; ++a) {
      LocalProblem2D& p = problems[a];
      static_cast<Interaction2D&>(p) = contacts[a];
      p.internal = keeps_law_state ? law_states[a].internal : std::array<double, 6>{};
      sides[a] = {side_of(scene, p, 0), side_of(scene, p, 1)};
      p.W = block(a, a);
      const ContactLaw& law = scene.laws[static_cast<std::size_t>(p.law)].law;
      prepare_local_problem_2d(law, p, law_step);
      if (internal_is_length[static_cast<std::size_t>(p.law)])
        p.internal[0] = (p.family == PairFamily2D::CLALp || p.family == PairFamily2D::CLJCx) ? p.length : 0.0;
      if (p.inactive) p.r.setZero();
      contacts[a] = p;
      if (keeps_law_state) law_states[a].internal = p.internal;
      free_velocity[a] = local_free_velocity(a);
      q2 += (free_velocity[a] + p.covfree).squaredNorm();
    }
    // The blocks of every two contacts that share a body that moves (mailx-2d-contact.md §8.3).
    std::vector<std::vector<std::pair<std::uint32_t, int>>> on_body_rigid(scene.bodies.size()),
        on_mesh(scene.deformable.states.size());
    for (std::size_t a = 0; a < count; ++a)
      for (int s = 0; s < 2; ++s) {
        const Side& side = sides[a][static_cast<std::size_t>(s)];
        if (!side.moves) continue;
        auto& list = side.mesh ? on_mesh[static_cast<std::size_t>(side.body)]
                               : on_body_rigid[static_cast<std::size_t>(side.body)];
        if (list.empty() || list.back().first != a) list.emplace_back(static_cast<std::uint32_t>(a), s);
      }
    // In compressed rows: contact a's coupled contacts adjacent_contact[adjacent_start[a] ..
    // adjacent_start[a + 1]) and their blocks, side by side in two arrays that a sweep reads in order.
    adjacent_start.assign(count + 1, 0);
    adjacent_contact.clear();
    adjacent_block.clear();
    std::vector<std::int64_t> seen(count, -1);
    for (std::size_t a = 0; a < count; ++a) {
      adjacent_start[a] = adjacent_contact.size();
      for (int s = 0; s < 2; ++s) {
        const Side& side = sides[a][static_cast<std::size_t>(s)];
        if (!side.moves) continue;
        const auto& list = side.mesh ? on_mesh[static_cast<std::size_t>(side.body)]
                                     : on_body_rigid[static_cast<std::size_t>(side.body)];
        for (const auto& [j, unused] : list) {
          if (j == a || seen[j] == static_cast<std::int64_t>(a)) continue;
          seen[j] = static_cast<std::int64_t>(a);
          adjacent_contact.push_back(j);
          adjacent_block.push_back(block(a, j));
        }
      }
    }
    adjacent_start[count] = adjacent_contact.size();
    reaction.resize(count);
    for (std::size_t a = 0; a < count; ++a) reaction[a] = problems[a].r;
    result.free_velocity_norm = std::sqrt(q2);
    if (options.quick_scramble) scramble.prepare(count);
  }

  // W_ab: the velocity of contact a per unit reaction of contact b, summed over the bodies they
  // share, signed by the side each sees it from.
  Matrix2d block(std::size_t a, std::size_t b) const {
    Matrix2d W = Matrix2d::Zero();
    for (int sa = 0; sa < 2; ++sa)
      for (int sb = 0; sb < 2; ++sb) {
        const Side& x = sides[a][static_cast<std::size_t>(sa)];
        const Side& y = sides[b][static_cast<std::size_t>(sb)];
        if (!x.moves || !same_body(x, y)) continue;
        const double sign = sa == sb ? 1.0 : -1.0;
        W += sign * side_block(scene, x, y);
      }
    return W;
  }

  // H_aᵀ V_free.
  Vector2d local_free_velocity(std::size_t a) const {
    Vector2d u = Vector2d::Zero();
    for (int s = 0; s < 2; ++s) {
      const Side& side = sides[a][static_cast<std::size_t>(s)];
      const double sign = s == 0 ? 1.0 : -1.0;
      if (side.mesh) {
        const Eigen::VectorXd& v = scene.deformable.states[static_cast<std::size_t>(side.body)].v_free;
        for (int k = 0; k < 2; ++k)
          for (std::size_t e = 0; e < 4; ++e)
            u(k) += sign * side.h[static_cast<std::size_t>(k)][e] * v(side.dofs[e]);
      } else {
        const Vector3d& v = scene.bodies.velocity_free[static_cast<std::size_t>(side.body)];
        for (int k = 0; k < 2; ++k)
          for (std::size_t e = 0; e < 3; ++e)
            u(k) += sign * side.h[static_cast<std::size_t>(k)][e] * v(static_cast<Eigen::Index>(e));
      }
    }
    return u;
  }

  // v_free_a + Σ_j≠a W_aj r_j: what contact a's law solves for.
  Vector2d others(std::size_t a) const {
    Vector2d u = free_velocity[a];
    for (std::size_t k = adjacent_start[a]; k < adjacent_start[a + 1]; ++k)
      u += adjacent_block[k] * reaction[adjacent_contact[k]];
    return u;
  }

  // The law's reaction for the local free velocity uf (law shifts not included).
  static void law_reaction(const LocalProblem2D& p, const ContactLaw& law, const Vector2d& uf, Vector2d& r,
                           ContactStatus& status) {
    const Vector2d v = uf + p.covfree;
    if (std::holds_alternative<CoupledDof>(law)) {
      r = -p.WW.inverse() * v;  // bilateral: WW r = −v
      status = ContactStatus::stick;
      return;
    }
    if (p.cohesive) {
      // contact-laws.md §3.5: A = (I − WW K)⁻¹; uu = A (v + WW radh) + A WW rr; r = rr + radh + K uu.
      const Matrix2d K = p.cohesive_slope.asDiagonal();
      const Matrix2d A = (Matrix2d::Identity() - p.WW * K).inverse();
      const Vector2d radh(p.cohesive_shift_t, 0.0);
      const Vector2d ufree = A * (v + p.WW * radh);
      const LocalSolution2D s = solve_signorini_coulomb_2d(A * p.WW, ufree, p.mu);
      const Vector2d uu = ufree + A * p.WW * s.r;
      r = s.r + radh + K * uu;
      status = cohesive_status(s.status);
      if (s.status == ContactStatus::noctc && r(1) != 0.0) status = ContactStatus::Cstck;
      return;
    }
    const LocalSolution2D s = solve_signorini_coulomb_2d(p.WW, v, p.mu);
    r = s.r + p.correction;
    const bool wet = is_wet_law(law);
    status = wet && !p.correction.isZero(0.0) ? wet_status(s.status) : s.status;
  }

  // Natural-map residual of contact a at the current reactions (law in auxiliary variables).
  double residual2(std::size_t a, const Vector2d& uf) const {
    const LocalProblem2D& p = problems[a];
    if (p.inactive) return p.r.squaredNorm();
    const ContactLaw& law = scene.laws[static_cast<std::size_t>(p.law)].law;
    const Vector2d v = uf + p.covfree;
    if (p.cohesive) {
      const Vector2d uu = v + p.WW * p.r;
      const Vector2d rr = p.r - Vector2d(p.cohesive_shift_t, 0.0) - p.cohesive_slope.cwiseProduct(uu);
      return natural_map_residual_squared_2d(rr, uu, p.mu);
    }
    const Vector2d rr = p.r - p.correction;
    const Vector2d u = v + p.WW * rr;
    if (std::holds_alternative<CoupledDof>(law)) return u.squaredNorm();
    return natural_map_residual_squared_2d(rr, u, p.mu);
  }

  const ContactLaw& law_of(std::size_t a) const {
    return scene.laws[static_cast<std::size_t>(problems[a].law)].law;
  }

  // A check's or the post sweep's re-evaluation of a law's state from the velocity u of its local
  // solution (cohesive zones); the contact keeps the new state.
  void update_law_state(std::size_t a, const Vector2d& u) {
    LocalProblem2D& p = problems[a];
    if (!updates_at_check(law_of(a))) return;
    if (update_law_at_check(law_of(a), p, u, law_step)) {
      contacts[a] = p;
      if (keeps_law_state) law_states[a].internal = p.internal;
    }
  }

  void sweep(bool post) {
    const double relax = options.relax, keep = 1.0 - options.relax;
    for (std::size_t position = 0; position < count; ++position) {
      const std::size_t a = order[position];
      LocalProblem2D& p = problems[a];
      if (p.inactive) continue;
      const bool open = p.r(0) == 0.0 && p.r(1) == 0.0;
      if (!post && open && schedule[a].skip(sweeps)) continue;
      const Vector2d uf = others(a);
      Vector2d r;
      ContactStatus status;
      law_reaction(p, law_of(a), uf, r, status);
      if (post && any_update_at_check) update_law_state(a, p.W * r + uf);
      r = relax * r + keep * p.r;
      if (std::fabs(r(0)) < 1e-24) r(0) = 0.0;
      if (std::fabs(r(1)) < 1e-24) r(1) = 0.0;
      p.r = r;
      reaction[a] = r;
      if (post) {
        final_status[a] = status;
        // LMGC90's i_post: the contact's velocity from its new reaction and the free velocity it was
        // solved with (the reactions of the contacts after it in the sweep are still the previous
        // ones): what Vloc_Rloc reports and the laws' end-of-step update reads.
        Vector2d u = uf + p.W * r;
        if (std::fabs(u(0)) < 1e-24) u(0) = 0.0;
        if (std::fabs(u(1)) < 1e-24) u(1) = 0.0;
        post_velocity[a] = u;
        solved_in_post[a] = 1;
      }
      if (!post) schedule[a].restart_if(r(0) != 0.0 || r(1) != 0.0);
    }
    if (!post) {
      ++sweeps;
      ++result.iterations;
    }
  }

  bool check() {
    NlgsCheckSums sums;
    double residual_sum = 0.0;
    std::size_t vanishing = 0;
    result.active = 0;
    result.hover = result.stick = result.slide = 0;
    const bool normal_only = options.norm == NlgsNorm::quad_normal;
    for (std::size_t a = 0; a < count; ++a) {
      schedule[a].restart();
      LocalProblem2D& p = problems[a];
      const Vector2d uf = others(a);
      const Vector2d u = uf + p.W * p.r;
      residual_sum += residual2(a, uf);
      Vector2d r1 = p.r, r2 = Vector2d::Zero();
      if (!p.inactive) {
        ContactStatus status;
        law_reaction(p, law_of(a), uf, r2, status);
        result.count_nature(status_nature(status));
      } else {
        r1.setZero();
        ++result.hover;
      }
      const Vector2d u2 = p.W * r2 + uf;
      if (any_update_at_check && !p.inactive) update_law_state(a, u2);
      const Vector2d mean = 0.5 * (r1 + r2);
      const Vector2d dv = u - u2;
      if (mean.isZero(0.0)) ++vanishing;
      if (!p.r.isZero(0.0)) ++result.active;
      if (normal_only) {
        const double dvdv = dv(1) * dv(1), wrr = 0.5 * p.W(1, 1) * (r1(1) * r1(1) + r2(1) * r2(1));
        sums.add(dvdv, dvdv * mean(1) * mean(1), mean(1) * dv(1), wrr, p.W(1, 1) * wrr);
        continue;
      }
      const Vector2d w1 = p.W * r1, w2 = p.W * r2;
      const double dvdv = dv.squaredNorm();
      sums.add(dvdv, dvdv * mean.squaredNorm(), mean.dot(dv), 0.5 * (w1.dot(r1) + w2.dot(r2)),
               0.5 * (w1.squaredNorm() + w2.squaredNorm()));
    }
    result.residual_absolute = std::sqrt(residual_sum);
    result.residual_relative = result.free_velocity_norm > 0.0
                                   ? result.residual_absolute / result.free_velocity_norm
                                   : result.residual_absolute;
    sums.active = static_cast<double>(count - vanishing);
    result.norms = nlgs_norms(sums, options.tolerance);
    const NlgsNorms& q = result.norms;
    if (!std::isfinite(q.mean_dvor) || !std::isfinite(q.quad_dv) || !std::isfinite(residual_sum))
      result.diverged = true;
    bool passed = nlgs_check_passes(options.norm, q);
    if (options.residual_target > 0.0) passed = passed || result.residual_relative <= options.residual_target;
    return passed;
  }

  void post() {
    // The bodies take the reactions before the post sweep with Stored_Delassus_Loops (the post sweep
    // does not inject: rigid-2d.md §5.3), the ones after it otherwise.
    const bool stored_delassus = options.storage == NlgsStorage::stored_delassus_loops;
    if (stored_delassus) apply_impulses();
    if (count > 0) sweep(true);
    if (!stored_delassus) apply_impulses();
  }

  // Rigid bodies: I = Σ H r, V = V_free + M⁻¹ I; meshes: I_reac = Σ Hᵀ r (ComputeDof solves for V).
  void apply_impulses() {
    RigidBodies2D& b = scene.bodies;
    std::fill(b.impulse.begin(), b.impulse.end(), Vector3d::Zero());
    for (MeshBodyState& s : scene.deformable.states)
      s.contact_impulse = Eigen::VectorXd::Zero(s.v_free.size());
    for (std::size_t a = 0; a < count; ++a) {
      const Vector2d& r = problems[a].r;
      if (r.isZero(0.0)) continue;
      for (int s = 0; s < 2; ++s) {
        const Side& side = sides[a][static_cast<std::size_t>(s)];
        const double sign = s == 0 ? 1.0 : -1.0;
        if (side.mesh) {
          Eigen::VectorXd& impulse =
              scene.deformable.states[static_cast<std::size_t>(side.body)].contact_impulse;
          for (std::size_t e = 0; e < 4; ++e)
            impulse(side.dofs[e]) += sign * (side.hr[0][e] * r(0) + side.hr[1][e] * r(1));
        } else {
          Vector3d& impulse = b.impulse[static_cast<std::size_t>(side.body)];
          for (std::size_t e = 0; e < 3; ++e)
            impulse(static_cast<Eigen::Index>(e)) += sign * (side.hr[0][e] * r(0) + side.hr[1][e] * r(1));
        }
      }
    }
    for (std::size_t i = 0; i < b.size(); ++i)
      b.velocity[i] = b.velocity_free[i] + b.inverse_mass[i].cwiseProduct(b.impulse[i]);
  }

  void end_of_step() {
    double residual_sum = 0.0;
    result.active = 0;
    LawState2D unused;
    for (std::size_t a = 0; a < count; ++a) {
      LocalProblem2D& p = problems[a];
      const Vector2d uf = others(a);
      residual_sum += residual2(a, uf);
      if (!p.r.isZero(0.0)) ++result.active;
      Interaction2D& c = contacts[a];
      c = p;
      c.u = solved_in_post[a] ? post_velocity[a] : uf + p.W * p.r;
      const bool wet_or_cohesive = is_wet_law(law_of(a)) || p.cohesive;
      c.status = (p.r.isZero(0.0) && !wet_or_cohesive) ? ContactStatus::noctc : final_status[a];
      finish_step_2d(law_of(a), c, keeps_law_state ? law_states[a] : unused, law_step.h, law_step.time);
    }
    result.residual_absolute = std::sqrt(residual_sum);
    result.residual_relative = result.free_velocity_norm > 0.0
                                   ? result.residual_absolute / result.free_velocity_norm
                                   : result.residual_absolute;
  }

  Scene2D& scene;
  LargeArray<Interaction2D>& contacts;
  std::span<LawState2D> law_states;
  const LawStep& law_step;
  const NlgsOptions& options;
  QuickScramble& scramble;
  const std::size_t count;
  const bool keeps_law_state;
  bool any_update_at_check = false;
  NlgsResult result;
  std::int32_t sweeps = 0;
  std::vector<LocalProblem2D> problems;
  std::vector<std::array<Side, 2>> sides;
  std::vector<Vector2d> free_velocity;
  std::vector<std::size_t> adjacent_start;
  std::vector<std::uint32_t> adjacent_contact;
  std::vector<Matrix2d> adjacent_block;  // velocity of the row's contact per unit reaction of the other
  std::vector<Vector2d> reaction;        // the contacts' reactions, as problems[a].r, compact for the sweeps
  std::vector<ContactStatus> final_status;
  std::vector<Vector2d> post_velocity;
  std::vector<std::uint8_t> solved_in_post;
  std::vector<OpenContactSchedule> schedule;
  std::vector<std::uint32_t> order;
  std::vector<std::uint8_t> internal_is_length;  // per law: first_internal_is_length
};

}  // namespace

NlgsResult solve_nlgs_coupled_2d(Scene2D& scene, LargeArray<Interaction2D>& contacts,
                                 std::span<LawState2D> law_states, const LawStep& step,
                                 const NlgsOptions& options, QuickScramble& scramble) {
  return CoupledNlgs2D(scene, contacts, law_states, step, options, scramble).run();
}

}  // namespace lmgc::solver
