#include "solver/integrator/step_2d.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <span>

#include "solver/detection/mesh_detection_2d.hpp"
#include "solver/model/large_array.hpp"
#include "solver/nlgs/nlgs_coupled_2d.hpp"

namespace lmgc::solver {

using Eigen::Vector2d;
using Eigen::Vector3d;

double DrivenDof2D::value(double t) const {
  if (!evolution.empty()) {
    // Linear interpolation, and linear extrapolation outside (datbox-inputs.md §5).
    if (evolution.size() == 1) return evolution[0][1];
    std::size_t i = 1;
    while (i + 1 < evolution.size() && evolution[i][0] < t) ++i;
    const auto& a = evolution[i - 1];
    const auto& b = evolution[i];
    const double span = b[0] - a[0];
    return span != 0.0 ? a[1] + (b[1] - a[1]) * (t - a[0]) / span : a[1];
  }
  const auto& k = coefficients;  // CT AMP OMEGA PHI RAMPI RAMP
  return (k[0] + k[1] * std::cos(k[2] * t + k[3])) * std::min(1.0, k[4] + k[5] * t);
}

void increment_step(Scene2D& scene, StepContext& step) {
  step.time += step.h;
  ++step.step;
  RigidBodies2D& b = scene.bodies;
  std::fill(b.impulse.begin(), b.impulse.end(), Vector3d::Zero());
  b.velocity = b.velocity_begin;
  if (!scene.deformable.empty()) increment_deformable(scene.deformable, step);
}

void compute_external_forces(Scene2D& scene, const StepContext& step) {
  RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i)
    b.external_force[i] = Vector3d(b.mass[i] * scene.gravity.x(), b.mass[i] * scene.gravity.y(), 0.0);
  // Imposed forces, θ-averaged over the step (numerics.md §1.1).
  for (const DrivenDof2D& d : scene.driven)
    if (d.is_force)
      b.external_force[static_cast<std::size_t>(d.body)](d.dof) +=
          (1.0 - step.theta) * d.value(step.begin_time()) + step.theta * d.value(step.time);
  if (!scene.deformable.empty())
    external_forces_deformable(scene.deformable, Vector3d(scene.gravity.x(), scene.gravity.y(), 0.0), step);
}

void compute_free_velocity(Scene2D& scene, const StepContext& step) {
  RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i)
    b.velocity_free[i] =
        b.visible[i]
            ? Vector3d(b.velocity_begin[i] + step.h * b.inverse_mass[i].cwiseProduct(b.external_force[i]))
            : Vector3d::Zero();
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force && b.visible[static_cast<std::size_t>(d.body)])
      b.velocity_free[static_cast<std::size_t>(d.body)](d.dof) = d.value(step.time);
  if (!scene.deformable.empty()) free_velocity_deformable(scene.deformable, step);
}

void select_prox_tactors(Scene2D& scene, RunState2D& state) {
  RigidBodies2D& b = scene.bodies;
  std::vector<Vector3d> coordinates(b.size());
  for (std::size_t i = 0; i < b.size(); ++i)
    coordinates[i] =
        b.reference[i] + b.displacement_begin[i] + (1.0 - state.theta) * state.h * b.velocity_begin[i];
  if (scene.x_period > 0.0)
    for (auto& c : coordinates) c.x() -= scene.x_period * std::floor(c.x() / scene.x_period);
  if (state.contacts_stored) {
    // The stored list becomes `previous`; the older list's buffer receives the new interactions.
    std::swap(state.previous, state.contacts);
    std::swap(state.previous_law_states, state.law_states);
    state.contacts_stored = false;
  }
  detect_contacts_2d(scene, state.visibility, coordinates, state.contacts);
  if (scene.plan.any_mesh_family) {
    std::vector<Eigen::VectorXd> nodes(scene.deformable.states.size());
    for (std::size_t m = 0; m < nodes.size(); ++m)
      nodes[m] = mesh_detection_coordinates(scene, m, state.theta, state.h);
    detect_mesh_contacts_2d(scene, coordinates, nodes, state.point_pairs, state.contacts);
  }
  state.law_states.clear();
  if (scene_keeps_law_state_2d(scene)) state.law_states.resize(state.contacts.size());
}

bool scene_keeps_law_state_2d(const Scene2D& scene) {
  for (const Visibility2D& v : scene.visibility)
    if (keeps_law_state_2d(scene.laws[static_cast<std::size_t>(v.law)].law)) return true;
  return false;
}

void recup_rloc(RunState2D& state) {
  if (state.contacts_stored) {
    // Stored by stock_rloc with no detection since: each interaction is its own previous one.
    for (Interaction2D& c : state.contacts) c.status_begin = c.status;
    return;
  }
  const LargeArray<Interaction2D>& previous = state.previous;
  // The stored interactions of each candidate contactor, in their order (LMGC90's verlet lists are
  // by candidate too): the lists come in detection order, so a match is looked up among its
  // candidate's few stored interactions.
  std::size_t contactors = 0;
  for (const Interaction2D& p : previous)
    contactors =
        std::max<std::size_t>(contactors, static_cast<std::size_t>(std::max(p.candidate, p.antagonist)) + 1);
  thread_local std::vector<std::uint32_t> first, by_candidate;
  first.assign(contactors + 1, 0);
  for (const Interaction2D& p : previous) ++first[static_cast<std::size_t>(p.candidate) + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  by_candidate.resize(previous.size());
  {
    thread_local std::vector<std::uint32_t> next;
    next.assign(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < previous.size(); ++k)
      by_candidate[next[static_cast<std::size_t>(previous[k].candidate)]++] = static_cast<std::uint32_t>(k);
  }
  const auto stored_of = [&](std::int32_t candidate) {
    const auto c = static_cast<std::size_t>(candidate);
    if (c + 1 >= first.size()) return std::span<const std::uint32_t>{};
    return std::span<const std::uint32_t>(by_candidate.data() + first[c], first[c + 1] - first[c]);
  };
  // PLPLx between two parallel faces: which polygon holds the vertices depends on round-off, so a
  // pair may come back with its roles swapped (LMGC90's own detection keeps them; its
  // recup_rloc_ByPosition_PLPLx matches either role by position). The swapped pair's previous
  // point at the same place (within 1% of the distance between that pair's two points) is the match.
  const auto swapped_match = [&](const Interaction2D& c) -> const Interaction2D* {
    std::array<const Interaction2D*, 2> points{};
    int count = 0;
    for (std::uint32_t k : stored_of(c.antagonist)) {
      const Interaction2D& p = previous[k];
      if (p.family != c.family || p.antagonist != c.candidate) continue;
      if (count < 2) points[static_cast<std::size_t>(count)] = &p;
      ++count;
    }
    if (count != 2) return nullptr;  // face against face: two points
    const double spacing = (points[0]->point - points[1]->point).norm();
    for (const Interaction2D* p : points)
      if ((p->point - c.point).norm() < 0.01 * spacing) return p;
    return nullptr;
  };
  // Internals from the stored list's, where both lists keep them (a warm start from a file, or a
  // scene whose laws have internals); 0 otherwise.
  const bool internals = !state.law_states.empty() && !state.previous_law_states.empty();
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    Interaction2D& c = state.contacts[k];
    const Interaction2D* match = nullptr;
    bool swapped = false;
    for (std::uint32_t m : stored_of(c.candidate)) {
      const Interaction2D& p = previous[m];
      // DKALp's verlet keeps the segment too (mod_DKALp recup_rloc); the other families do not.
      if (p.family == c.family && p.antagonist == c.antagonist && p.candidate_vertex == c.candidate_vertex &&
          (c.family != PairFamily2D::DKALp || p.antagonist_segment == c.antagonist_segment)) {
        match = &p;
        break;
      }
    }
    if (!match && c.family == PairFamily2D::PLPLx) {
      match = swapped_match(c);
      swapped = match != nullptr;
    }
    if (match) {
      c.r = match->r;
      c.status_begin = match->status;
      std::array<double, 6>* internal = internals ? &state.law_states[k].internal : nullptr;
      if (internal)
        *internal = state.previous_law_states[static_cast<std::size_t>(match - previous.data())].internal;
      if (swapped) {
        // n and t turn over with the roles: r_t and a cohesive zone's tangential jump change sign.
        c.r(0) = -c.r(0);
        if (match->cohesive && internal) (*internal)[1] = -(*internal)[1];
      }
    } else {
      c.r.setZero();
      c.status_begin = ContactStatus::nknow;
    }
    c.status = c.status_begin;
  }
}

NlgsResult solve_contacts(Scene2D& scene, RunState2D& state, const NlgsOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const bool first = !state.laws_initialized && !state.contacts.empty();
  const LawStep law_step{state.h, state.time, state.step == 1, first};
  // Contacts on meshes couple every contact of a mesh: a scene that has them (a visibility row of a
  // mesh family) is solved by the coupled NLGS (nlgs_coupled_2d.hpp), its rigid contacts with them.
  NlgsResult result =
      scene.plan.any_mesh_family
          ? solve_nlgs_coupled_2d(scene, state.contacts, state.law_states, law_step, options, state.scramble)
          : solve_nlgs_2d(scene, scene.bodies, state.contacts, state.law_states, law_step, options,
                          state.scramble);
  if (!state.contacts.empty()) state.laws_initialized = true;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void store_interactions(RunState2D& state, std::span<const Interaction2D> interactions,
                        std::span<const LawState2D> law_states) {
  state.previous.assign(interactions.begin(), interactions.end());  // keeps its buffer
  state.previous_law_states.assign(law_states.begin(), law_states.end());
  state.contacts_stored = false;
}

void stock_rloc(RunState2D& state) {
  state.contacts_stored = true;
}

void compute_dof(Scene2D& scene, const StepContext& step) {
  RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i)
    if (b.visible[i])
      b.displacement[i] = b.displacement_begin[i] +
                          step.h * ((1.0 - step.theta) * b.velocity_begin[i] + step.theta * b.velocity[i]);
  apply_bounds(scene);
  if (!scene.deformable.empty()) dof_deformable(scene.deformable, step);
}

void apply_bounds(Scene2D& scene) {
  RigidBodies2D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.visible[i]) continue;
    // Periodic in x: a body leaving [0, period] comes back one period away (check_periodic).
    if (scene.x_period > 0.0) {
      const double x = b.reference[i].x() + b.displacement[i].x();
      if (x > scene.x_period)
        b.displacement[i].x() -= scene.x_period;
      else if (x < 0.0)
        b.displacement[i].x() += scene.x_period;
    }
    const double x = b.reference[i].x() + b.displacement[i].x();
    const double y = b.reference[i].y() + b.displacement[i].y();
    // First bound crossed wins, in LMGC90's order: below, above, left, right.
    int axis = -1;
    double limit = 0.0;
    if (y < scene.y_min)
      axis = 1, limit = scene.y_min;
    else if (y > scene.y_max)
      axis = 1, limit = scene.y_max;
    else if (x < scene.x_min)
      axis = 0, limit = scene.x_min;
    else if (x > scene.x_max)
      axis = 0, limit = scene.x_max;
    if (axis < 0) continue;
    b.visible[i] = 0;
    b.velocity_begin[i].setZero();
    b.velocity[i].setZero();
    b.displacement[i](axis) = limit - b.reference[i](axis);
  }
}

void update_step(Scene2D& scene) {
  RigidBodies2D& b = scene.bodies;
  b.displacement_begin = b.displacement;
  b.velocity_begin = b.velocity;
  if (!scene.deformable.empty()) update_deformable(scene.deformable);
}

namespace {
// LMGC90's macro time loop, one row per call of its command.py (IncrementStep ... UpdateStep).
constexpr std::array<StepStage2D, 9> kStages2D{{
    {"IncrementStep",
     [](Scene2D& s, RunState2D& st, const NlgsOptions&, NlgsResult&) { increment_step(s, st); }},
    {"ComputeFext",
     [](Scene2D& s, RunState2D& st, const NlgsOptions&, NlgsResult&) { compute_external_forces(s, st); }},
    {"ComputeFreeVelocity",
     [](Scene2D& s, RunState2D& st, const NlgsOptions&, NlgsResult&) { compute_free_velocity(s, st); }},
    {"SelectProxTactors",
     [](Scene2D& s, RunState2D& st, const NlgsOptions&, NlgsResult&) { select_prox_tactors(s, st); }},
    {"RecupRloc", [](Scene2D&, RunState2D& st, const NlgsOptions&, NlgsResult&) { recup_rloc(st); }},
    {"ExSolver",
     [](Scene2D& s, RunState2D& st, const NlgsOptions& o, NlgsResult& r) { r = solve_contacts(s, st, o); }},
    {"StockRloc", [](Scene2D&, RunState2D& st, const NlgsOptions&, NlgsResult&) { stock_rloc(st); }},
    {"ComputeDof", [](Scene2D& s, RunState2D& st, const NlgsOptions&, NlgsResult&) { compute_dof(s, st); }},
    {"UpdateStep", [](Scene2D& s, RunState2D&, const NlgsOptions&, NlgsResult&) { update_step(s); }},
}};
}  // namespace

std::span<const StepStage2D> step_stages_2d() {
  return kStages2D;
}

NlgsResult step_2d(Scene2D& scene, RunState2D& state, const NlgsOptions& options) {
  NlgsResult result;
  for (const StepStage2D& stage : kStages2D) stage.run(scene, state, options, result);
  return result;
}

double kinetic_energy(const RigidBodies2D& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vector3d& v = b.velocity[i];
    e += 0.5 * b.mass[i] * (v.x() * v.x() + v.y() * v.y()) + 0.5 * b.inertia[i] * v.z() * v.z();
  }
  return e;
}

}  // namespace lmgc::solver
