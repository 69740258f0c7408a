#include "solver/model/deformable_bodies.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace lmgc::solver {

bool initialise_mesh_states(DeformableBodies& d, std::string& error, std::size_t& failed_body,
                            std::size_t& failed_element) {
  d.states.assign(d.meshes.bodies.size(), MeshBodyState{});
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    const fem::MeshBody& mesh = d.meshes.bodies[b];
    MeshBodyState& s = d.states[b];
    if (!fem::assemble(mesh, s.matrices, error, &failed_element)) {
      failed_body = b;
      return false;
    }
    const auto n = static_cast<Eigen::Index>(mesh.dofs());
    s.x = s.x_begin = s.v = s.v_begin = s.v_free = s.f_ext = Eigen::VectorXd::Zero(n);
    s.internal_force = s.inertial_force = s.residue = s.rhs = Eigen::VectorXd::Zero(n);
    s.large_strain = mesh.kinematics == fem::Kinematics::total_lagrangian;
    s.history_begin = s.history = fem::initial_point_history(mesh);
    s.point_stress.assign(s.history.size() / fem::kJ2Internal * 4, 0.0);
  }
  return true;
}

bool build_deformable_bodies(const case_folder::CaseFiles& files, fem::Hypothesis hypothesis,
                             DeformableBodies& out, grammar::DiagnosticSink& sink) {
  out = {};
  if (!build_mesh_bodies(files, hypothesis, out.meshes, sink)) return false;
  const std::size_t count = out.meshes.bodies.size();
  if (count == 0) return true;
  std::string error;
  std::size_t b = 0, failed = 0;
  if (!initialise_mesh_states(out, error, b, failed)) {
    // An inverted or degenerate element (a Gauss point where det J ≤ 0): LMGC90 would integrate it
    // with a negative weight (mailx-2d.md §1.4); lmgc refuses the case, at the element's line.
    const grammar::Body* body = nullptr;
    std::size_t rank = 0;
    for (const grammar::Body& candidate : files.bodies->bodies)
      if (candidate.type == grammar::BodyType::mailx && rank++ == b) body = &candidate;
    const grammar::SourceSpan span =
        body && failed < body->elements.size() ? body->elements[failed].type.span : grammar::SourceSpan{};
    sink.report("L3011", grammar::Location{(files.case_dir / "DATBOX" / "BODIES.DAT").string(), span},
                "MAILx body " + std::to_string(b + 1) + ": " + error);
    return false;
  }
  // Driven dofs of the nodes: a MAILx block's rank is the body's, its node numbers the body's nodes.
  if (files.drv_dof)
    for (const grammar::DrvDofBody& body : files.drv_dof->bodies) {
      if (body.body_type.value != "MAILx" || body.model.value != "MECAx") continue;
      const std::int64_t rank = body.rank.value;
      if (rank < 1 || rank > static_cast<std::int64_t>(count)) continue;  // lmgc-check: L2003
      const auto b = static_cast<std::size_t>(rank - 1);
      const int dimension = out.meshes.bodies[b].dimension;
      for (const grammar::DrvDofNode& node : body.nodes)
        for (const grammar::DrivenDof& dof : node.dofs) {
          const std::int64_t k = node.number.value, c = dof.dof.value;
          if (k < 1 || static_cast<std::size_t>(k) > out.meshes.bodies[b].nodes() || c < 1 || c > dimension)
            continue;
          DrivenDof2D d;
          d.body = static_cast<std::int32_t>(b);
          d.dof = static_cast<std::int32_t>((k - 1) * dimension + (c - 1));
          d.is_force = dof.kind.value == "force";
          if (dof.uses_evolution) {
            auto it = files.evolutions.find(dof.evolution_file.value);
            if (it != files.evolutions.end())
              for (const auto& point : it->second.points)
                d.evolution.push_back({point.time.value, point.value.value});
          } else {
            for (std::size_t p = 0; p < 6; ++p) d.coefficients[p] = dof.parameters[p].value;
          }
          if (!d.is_force) out.states[b].velocity_driven.push_back(d.dof);
          out.driven.push_back(d);
        }
    }
  // DOF.INI: X and V of every node.
  if (files.dof_ini) {
    std::size_t b = 0;
    for (const auto& section : files.dof_ini->sections)
      for (const grammar::DofBody& body : section.bodies) {
        if (body.body_type.value != "MAILx" || body.model.value != "MECAx") continue;
        const std::int64_t rank = body.number.value;
        if (rank < 1 || rank > static_cast<std::int64_t>(count)) continue;
        b = static_cast<std::size_t>(rank - 1);
        MeshBodyState& s = out.states[b];
        const int dimension = out.meshes.bodies[b].dimension;
        for (std::size_t k = 0; k < body.nodes.size() && k < out.meshes.bodies[b].nodes(); ++k)
          for (int c = 0; c < dimension; ++c) {
            const auto i = static_cast<Eigen::Index>(k * static_cast<std::size_t>(dimension) +
                                                     static_cast<std::size_t>(c));
            if (static_cast<std::size_t>(c) < body.nodes[k].x.size())
              s.x_begin(i) = body.nodes[k].x[static_cast<std::size_t>(c)].value;
            if (static_cast<std::size_t>(c) < body.nodes[k].v.size())
              s.v_begin(i) = body.nodes[k].v[static_cast<std::size_t>(c)].value;
          }
        s.x = s.x_begin;
        s.v = s.v_begin;
      }
  }
  return true;
}

void increment_deformable(DeformableBodies& d, const StepContext& step) {
  for (MeshBodyState& s : d.states) {
    s.v = s.v_begin;
    s.contact_impulse.resize(0);  // this step's contacts set it
    s.inverted.reset();
    s.bulk_current = false;
    // The first iterate of a large-strain body: X = X_begin + hV_begin (mecaMAILx_IncrementStep).
    if (s.large_strain) s.x = s.x_begin + step.h * s.v_begin;
  }
}

void external_forces_deformable(DeformableBodies& d, const Eigen::Vector3d& gravity,
                                const StepContext& step) {
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    MeshBodyState& s = d.states[b];
    const int dimension = d.meshes.bodies[b].dimension;
    // Gravity as the mass matrix times the nodal gravity field (lumped or consistent alike).
    Eigen::VectorXd g(s.x.size());
    for (Eigen::Index i = 0; i < g.size(); ++i) g(i) = gravity(i % dimension);
    s.f_ext = s.matrices.mass * g;
  }
  for (const DrivenDof2D& dd : d.driven)
    if (dd.is_force)
      d.states[static_cast<std::size_t>(dd.body)].f_ext(dd.dof) +=
          (1.0 - step.theta) * dd.value(step.begin_time()) + step.theta * dd.value(step.time);
}

namespace {

std::vector<fem::DrivenVelocity> driven_velocities(const DeformableBodies& d, std::size_t b, double time) {
  std::vector<fem::DrivenVelocity> driven;
  for (const DrivenDof2D& dd : d.driven)
    if (!dd.is_force && static_cast<std::size_t>(dd.body) == b) driven.push_back({dd.dof, dd.value(time)});
  return driven;
}

[[noreturn]] void singular(std::size_t b) {
  // Not a problem any θ-scheme solves (LMGC90's factorisation fails on it too): stop, say why.
  throw std::runtime_error("MAILx body " + std::to_string(b + 1) +
                           ": its iteration matrix M + θhC + (θh)²K is singular on its free dofs (a body "
                           "that can move rigidly without mass): give it a density or drive its dofs");
}

// F_int and K_t of large-strain body b at X_θ = X_begin + θh((1 − θ)V_begin + θV) of its iterate V.
void bulk_large_strain(DeformableBodies& d, std::size_t b, const StepContext& step) {
  MeshBodyState& s = d.states[b];
  const double h = step.h, theta = step.theta;
  const Eigen::VectorXd x_theta = s.x_begin + theta * h * ((1.0 - theta) * s.v_begin + theta * s.v);
  fem::InvertedElement inverted;
  s.bulk_current = fem::large_strain_forces(d.meshes.bodies[b], x_theta, s.bulk_force, &s.bulk_tangent,
                                            inverted, {&s.history_begin, nullptr, nullptr});
  if (!s.bulk_current) s.inverted = inverted;
}

// One Newton iteration of a large-strain body from its iterate V: R(V), K̂_t = M + θhC + (θh)²K_t
// factorised, V_free = V + K̂_t⁻¹ R with the driven velocities imposed.
void free_velocity_large_strain(DeformableBodies& d, std::size_t b, const StepContext& step) {
  MeshBodyState& s = d.states[b];
  if (!s.bulk_current && !s.inverted) bulk_large_strain(d, b, step);
  if (s.inverted) {
    s.v_free = s.v;
    return;
  }
  s.bulk_current = false;  // the next iteration has another iterate
  const double h = step.h, theta = step.theta;
  if (!s.scheme.prepare(s.matrices.mass, s.bulk_tangent, h, theta, s.damping, s.velocity_driven)) singular(b);
  s.prepared_h = 0.0;  // a linear K̂ is not kept
  s.contact_compliance.resize(0, 0);
  s.compliance_row.clear();
  s.rhs = s.matrices.mass * (s.v_begin - s.v) + h * (s.f_ext - s.bulk_force);
  if (s.damping.size()) s.rhs -= h * (s.damping * (theta * s.v + (1.0 - theta) * s.v_begin));
  Eigen::VectorXd imposed = Eigen::VectorXd::Zero(s.v.size());
  for (const fem::DrivenVelocity& dv : driven_velocities(d, b, step.time))
    imposed(dv.dof) = dv.value - s.v(dv.dof);
  s.v_free = s.v + s.scheme.increment(s.rhs, imposed);
}

}  // namespace

void bulk_deformable(DeformableBodies& d, const StepContext& step) {
  for (std::size_t b = 0; b < d.states.size(); ++b)
    if (d.states[b].large_strain && !d.states[b].inverted) bulk_large_strain(d, b, step);
}

void set_rayleigh_damping(DeformableBodies& d, double alpha, double beta) {
  d.rayleigh_alpha = alpha;
  d.rayleigh_beta = beta;
  for (MeshBodyState& s : d.states) {
    s.prepared_h = 0.0;  // refactorise K̂
    if (!s.large_strain) continue;
    s.damping = alpha * s.matrices.mass;
    if (s.bulk_tangent.size() && beta != 0.0) s.damping += beta * s.bulk_tangent;
  }
}

void free_velocity_deformable(DeformableBodies& d, const StepContext& step) {
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    MeshBodyState& s = d.states[b];
    if (s.large_strain) {
      free_velocity_large_strain(d, b, step);
      continue;
    }
    if (s.prepared_h != step.h || s.prepared_theta != step.theta) {
      if (!s.scheme.prepare(s.matrices, step.h, step.theta, d.rayleigh_alpha, d.rayleigh_beta,
                            s.velocity_driven))
        singular(b);
      s.prepared_h = step.h;
      s.prepared_theta = step.theta;
      s.contact_compliance.resize(0, 0);  // of the previous K̂
      s.compliance_row.clear();
    }
    // The residual at the iterate V (V_begin at a step's first iteration), for the residue norm.
    const double h = step.h, theta = step.theta;
    const Eigen::VectorXd v_theta = theta * s.v + (1.0 - theta) * s.v_begin;
    s.rhs = s.matrices.mass * (s.v_begin - s.v) -
            h * (s.matrices.stiffness * (s.x_begin + theta * h * v_theta)) -
            h * (s.scheme.damping() * v_theta) + h * s.f_ext;
    s.scheme.free_velocity(s.x_begin, s.v_begin, s.f_ext, driven_velocities(d, b, step.time), s.v_free);
  }
}

void dof_deformable(DeformableBodies& d, const StepContext& step) {
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    MeshBodyState& s = d.states[b];
    if (s.inverted) continue;  // nothing to advance from
    const bool contact = s.contact_impulse.size() == s.v_free.size() && !s.contact_impulse.isZero(0.0);
    // A full solve, not the condensed compliance (mailx-2d-contact.md §8.6).
    s.v = contact ? Eigen::VectorXd(s.v_free + s.scheme.response(s.contact_impulse)) : s.v_free;
    s.x = s.scheme.displacement(s.x_begin, s.v_begin, s.v);
    if (s.large_strain) {
      // LMGC90's ComputeField: F_int at the end configuration X.
      fem::InvertedElement inverted;
      if (!fem::large_strain_forces(d.meshes.bodies[b], s.x, s.internal_force, nullptr, inverted,
                                    {&s.history_begin, &s.history, &s.point_stress})) {
        s.inverted = inverted;
        continue;
      }
      if (!s.history.empty())
        s.internal_force = fem::reported_internal_force(d.meshes.bodies[b], s.point_stress);
      if (s.damping.size()) s.internal_force += s.damping * s.v;
    } else {
      s.internal_force = s.scheme.internal_force(s.x, s.v);
    }
    s.inertial_force = s.matrices.mass * (s.v - s.v_begin) / step.h;
    s.residue = s.internal_force + s.inertial_force - s.f_ext;
    if (contact) s.residue -= s.contact_impulse / step.h;
  }
}

void prepare_contact_compliance(DeformableBodies& d) {
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    MeshBodyState& s = d.states[b];
    if (!s.compliance_row.empty()) continue;
    const std::size_t dofs = d.meshes.bodies[b].dofs();
    const int dimension = d.meshes.bodies[b].dimension;
    s.compliance_row.assign(dofs, -1);
    // The nodes of the body's contactors (CLxxx_PushPreconNodes, ALpxx_PushPreconNodes), their dofs
    // numbered in node order.
    std::vector<std::uint8_t> listed(d.meshes.bodies[b].nodes(), 0);
    for (const MeshContactor& c : d.meshes.contactors)
      if (static_cast<std::size_t>(c.mesh) == b)
        for (std::int32_t n : c.nodes) listed[static_cast<std::size_t>(n)] = 1;
    std::vector<std::int32_t> dof_of_row;
    for (std::size_t n = 0; n < listed.size(); ++n)
      if (listed[n])
        for (int c = 0; c < dimension; ++c) {
          const std::size_t dof = n * static_cast<std::size_t>(dimension) + static_cast<std::size_t>(c);
          s.compliance_row[dof] = static_cast<std::int32_t>(dof_of_row.size());
          dof_of_row.push_back(static_cast<std::int32_t>(dof));
        }
    const auto rows = static_cast<Eigen::Index>(dof_of_row.size());
    s.contact_compliance.resize(rows, rows);
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs));
    for (Eigen::Index j = 0; j < rows; ++j) {
      unit(dof_of_row[static_cast<std::size_t>(j)]) = 1.0;
      const Eigen::VectorXd column = s.scheme.response(unit);
      unit(dof_of_row[static_cast<std::size_t>(j)]) = 0.0;
      for (Eigen::Index i = 0; i < rows; ++i)
        s.contact_compliance(i, j) = column(dof_of_row[static_cast<std::size_t>(i)]);
    }
  }
}

void update_deformable(DeformableBodies& d) {
  for (MeshBodyState& s : d.states) {
    s.x_begin = s.x;
    s.v_begin = s.v;
    s.history_begin = s.history;
  }
}

double compute_residue_norm(DeformableBodies& d, const StepContext& step) {
  double norm = 0.0;
  for (std::size_t b = 0; b < d.states.size(); ++b) {
    MeshBodyState& s = d.states[b];
    if (s.inverted) return std::numeric_limits<double>::infinity();
    // LMGC90 keeps it as the body's residue (Fint EVOLUTION's Res columns; mailx-2d.md §8.4).
    Eigen::VectorXd& residue = s.residue;
    residue = s.rhs;
    if (s.contact_impulse.size() == residue.size()) residue += s.contact_impulse;
    for (std::int32_t dof : s.velocity_driven) residue(dof) = 0.0;
    const auto largest = [](const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; };
    double scale =
        step.h * std::max({largest(s.internal_force), largest(s.inertial_force), largest(s.f_ext)});
    if (scale <= 0.1) scale = 1.0;
    norm = std::max(norm, largest(residue) / scale);
  }
  return norm;
}

std::optional<std::pair<std::size_t, fem::InvertedElement>> inverted_element(const DeformableBodies& d) {
  for (std::size_t b = 0; b < d.states.size(); ++b)
    if (d.states[b].inverted) return std::make_pair(b, *d.states[b].inverted);
  return std::nullopt;
}

double kinetic_energy(const DeformableBodies& d) {
  double e = 0.0;
  for (const MeshBodyState& s : d.states) e += 0.5 * s.v.dot(s.matrices.mass * s.v);
  return e;
}

}  // namespace lmgc::solver
