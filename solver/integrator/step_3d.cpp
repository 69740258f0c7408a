#include "solver/integrator/step_3d.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "solver/bodies/rigid_3d_properties.hpp"
#include "solver/model/contact_kinematics_3d.hpp"

namespace lmgc::solver {

namespace {

using Eigen::Vector3d;

// recup_rloc_PRPRx: a PRPRx point takes the previous step's reaction of the point of the same pair
// closer than 1e-3 (squared 1e-6, `tol_recup_rloc`), both seen from the candidate body.
constexpr double kRecupSquaredDistance = 1e-6;

}  // namespace

void increment_step(Scene3D& scene, StepContext& step) {
  RigidBodies3D& b = scene.bodies;
  step.time += step.h;
  ++step.step;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.displacement[i] = b.displacement_begin[i];
    b.velocity[i] = b.velocity_begin[i];
    b.impulse[i].setZero();
  }
  // Driven velocities hold at t_begin too (LMGC90 imposes them over DOF.INI's values).
  const double t_begin = step.begin_time();
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force) b.velocity_begin[static_cast<std::size_t>(d.body)](d.dof) = d.value(t_begin);
}

void compute_external_forces(Scene3D& scene, const StepContext& step) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vector6d f;
    f << b.mass[i] * scene.gravity, gyroscopic_torque(b.inertia[i], b.velocity_begin[i].tail<3>());
    b.external_force[i] = b.visible[i] ? f : Vector6d::Zero();  // invisible bodies wait (source point)
  }
  const double t_begin = step.begin_time();
  for (const DrivenDof2D& d : scene.driven)
    if (d.is_force)
      b.external_force[static_cast<std::size_t>(d.body)](d.dof) +=
          (1.0 - step.theta) * d.value(t_begin) + step.theta * d.value(step.time);
}

void compute_free_velocity(Scene3D& scene, const StepContext& step) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.velocity_free[i] = b.velocity_begin[i] + step.h * b.inverse_mass[i].cwiseProduct(b.external_force[i]);
    for (int d = 0; d < 6; ++d)
      if (b.driven_mask[i] & (1u << d)) b.velocity_free[i](d) = 0.0;
  }
  for (const DrivenDof2D& d : scene.driven)
    if (!d.is_force) b.velocity_free[static_cast<std::size_t>(d.body)](d.dof) = d.value(step.time);
  b.velocity = b.velocity_free;
}

void store_interactions(RunState3D& state, std::span<const Interaction3D> interactions,
                        std::span<const LawState3D> law_states) {
  state.previous.clear();  // keeps its buffer
  for (std::size_t k = 0; k < interactions.size(); ++k)
    state.previous.emplace_back(interactions[k], law_states.empty() ? nullptr : &law_states[k]);
}

void recup_rloc(RunState3D& state) {
  // Key: the contactor pair and, for PRPLx, the candidate vertex; PRPRx points of a pair are then
  // told apart by position (numerics.md §4, recup_rloc_PRPRx / recup_rloc_PRPLx); the first stored
  // entry that matches is taken. The stored entries of each candidate contactor are listed together
  // (LMGC90's verlet lists are by candidate too), so a lookup reads its candidate's few entries.
  const LargeArray<StoredInteraction3D>& previous = state.previous;
  std::size_t contactors = 0;
  for (const StoredInteraction3D& p : previous)
    contactors = std::max<std::size_t>(contactors, static_cast<std::size_t>(p.candidate) + 1);
  thread_local std::vector<std::uint32_t> first, by_candidate, next;
  first.assign(contactors + 1, 0);
  for (const StoredInteraction3D& p : previous) ++first[static_cast<std::size_t>(p.candidate) + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  by_candidate.resize(previous.size());
  next.assign(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < previous.size(); ++k)
    by_candidate[next[static_cast<std::size_t>(previous[k].candidate)]++] = static_cast<std::uint32_t>(k);
  const bool keeps_law_state = !state.law_states.empty();
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    Interaction3D& c = state.contacts[k];
    const StoredInteraction3D* match = nullptr;
    const auto cd = static_cast<std::size_t>(c.candidate);
    if (cd + 1 < first.size())
      for (std::uint32_t m = first[cd]; m < first[cd + 1] && !match; ++m) {
        const StoredInteraction3D& p = previous[by_candidate[m]];
        if (p.family == c.family && p.antagonist == c.antagonist && p.vertex == c.vertex &&
            (c.family != PairFamily3D::PRPRx ||
             (p.candidate_point - c.candidate_point).squaredNorm() < kRecupSquaredDistance))
          match = &p;
      }
    if (!match) {
      c.r.setZero();
      c.status_begin = ContactStatus::nknow;
      continue;
    }
    c.r = match->r;
    c.status_begin = match->status;
    if (keeps_law_state) state.law_states[k].internal = match->internal;
  }
}

void compute_dof(Scene3D& scene, const StepContext& step) {
  RigidBodies3D& b = scene.bodies;
  const double h = step.h, theta = step.theta;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b.visible[i]) continue;  // comp_dof_RBDY3 skips invisible bodies
    b.displacement[i].head<3>() =
        b.displacement_begin[i].head<3>() +
        h * ((1.0 - theta) * b.velocity_begin[i].head<3>() + theta * b.velocity[i].head<3>());
    b.displacement[i].tail<3>().setZero();
    const Vector3d spin = b.velocity[i].tail<3>();
    b.frame[i] = scene.rotation == FrameUpdate::cayley
                     ? update_frame(b.frame_initial[i], spin, h, FrameUpdate::cayley)
                     : update_frame(b.frame_detection[i], theta * spin, h, FrameUpdate::linearised);
  }
}

void update_step(Scene3D& scene, RunState3D& state) {
  RigidBodies3D& b = scene.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.displacement_begin[i] = b.displacement[i];
    b.velocity_begin[i] = b.velocity[i];
    b.frame_initial[i] = b.frame[i];
  }
  // One pass: on a large scene each pass streams the interactions from memory.
  state.previous.clear();  // keeps its buffer
  const bool keeps_law_state = !state.law_states.empty();
  for (std::size_t k = 0; k < state.contacts.size(); ++k) {
    Interaction3D& c = state.contacts[k];
    c.status_begin = c.status;
    state.previous.emplace_back(c, keeps_law_state ? &state.law_states[k] : nullptr);
  }
}

namespace {
// Contactor 1 of body i is a SPHER or POLYR (the bodies a source point handles) of colour `color`.
const Contactor3D* first_contactor(const Scene3D& scene, std::size_t i) {
  for (const Contactor3D& c : scene.contactors)
    if (static_cast<std::size_t>(c.body) == i && c.rank == 1) return &c;
  return nullptr;
}
bool enters_by_source(const Contactor3D* c) {
  return c && (c->type == "SPHER" || c->type == "POLYR");
}
}  // namespace

void init_source_point(Scene3D& scene, std::size_t first, double radius, const Vector3d& point,
                       bool absolute) {
  RigidBodies3D& b = scene.bodies;
  if (first >= b.size()) return;
  scene.source = SourcePoint3D{true, false, first, radius, point};
  for (std::size_t i = 0; i <= first; ++i) b.visible[i] = 1;
  if (absolute) b.reference[first].setZero();
  b.displacement_begin[first].head<3>() = point;
  b.displacement[first] = b.displacement_begin[first];
  for (std::size_t i = first + 1; i < b.size(); ++i) {
    const Contactor3D* c = first_contactor(scene, i);
    if (!enters_by_source(c) || c->color == "BASEx") continue;
    b.visible[i] = 0;
    if (absolute) b.reference[i].setZero();
    b.displacement_begin[i].setZero();
    b.displacement[i].setZero();
    b.velocity_begin[i].head<3>().setZero();
    b.velocity[i].head<3>().setZero();
  }
}

void check_source_point(Scene3D& scene) {
  RigidBodies3D& b = scene.bodies;
  SourcePoint3D& s = scene.source;
  const std::size_t next = s.last + 1;
  if (s.stopped || next >= b.size()) return;
  if (!enters_by_source(first_contactor(scene, next))) {
    s.stopped = true;
    return;
  }
  // The last body's X is its position: its reference was set to 0.
  if ((b.displacement[s.last].head<3>() - s.point).squaredNorm() <= s.radius * s.radius) return;
  s.last = next;
  b.visible[next] = 1;
  b.displacement[next].head<3>() = s.point;
}

namespace {
// LMGC90's macro time loop, one row per call of its command.py (IncrementStep ... UpdateStep).
constexpr std::array<StepStage3D, 8> kStages3D{{
    {"IncrementStep",
     [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) { increment_step(s, st); }},
    {"ComputeFext",
     [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) { compute_external_forces(s, st); }},
    {"ComputeFreeVelocity",
     [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) { compute_free_velocity(s, st); }},
    {"SelectProxTactors",
     [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) { select_prox_tactors(s, st); }},
    {"RecupRloc", [](Scene3D&, RunState3D& st, const NlgsOptions&, NlgsResult&) { recup_rloc(st); }},
    {"ExSolver",
     [](Scene3D& s, RunState3D& st, const NlgsOptions& o, NlgsResult& r) { r = solve_contacts(s, st, o); }},
    // comp_dof_RBDY3 ends with the source point's check.
    {"ComputeDof",
     [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) {
       compute_dof(s, st);
       if (s.source.active) check_source_point(s);
     }},
    {"UpdateStep", [](Scene3D& s, RunState3D& st, const NlgsOptions&, NlgsResult&) { update_step(s, st); }},
}};
}  // namespace

std::span<const StepStage3D> step_stages_3d() {
  return kStages3D;
}

NlgsResult step_3d(Scene3D& scene, RunState3D& state, const NlgsOptions& options) {
  NlgsResult result;
  for (const StepStage3D& stage : kStages3D) stage.run(scene, state, options, result);
  return result;
}

}  // namespace lmgc::solver
