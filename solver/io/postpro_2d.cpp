#include "solver/io/postpro_2d.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::solver {
namespace {

using Eigen::Vector3d;

// ES15.8 for the time, then (1X,ES14.7) per value.
void line(std::ofstream& out, double time, std::initializer_list<double> values) {
  std::string text;
  grammar::append_fortran_es(text, time, 15, 8);
  for (double v : values) {
    text += ' ';
    grammar::append_fortran_es(text, v, 14, 7);
  }
  text += '\n';
  out << text;
}

}  // namespace

bool postpro_kind_of(std::string_view name, PostproKind2D& kind) {
  struct Row {
    std::string_view name;
    PostproKind2D kind;
  };
  static constexpr Row kRows[] = {
      {"SOLVER INFORMATIONS", PostproKind2D::solver_informations},
      {"VIOLATION EVOLUTION", PostproKind2D::violation_evolution},
      {"KINETIC ENERGY", PostproKind2D::kinetic_energy},
      {"DISSIPATED ENERGY", PostproKind2D::dissipated_energy},
      {"BODY TRACKING", PostproKind2D::body_tracking},
      {"TORQUE EVOLUTION", PostproKind2D::torque_evolution},
      {"COORDINATION NUMBER", PostproKind2D::coordination_number},
      {"AVERAGE VELOCITY EVOLUTION", PostproKind2D::average_velocity_evolution},
      {"NEW MECAx SETS", PostproKind2D::new_meca_sets},
      {"Dep EVOLUTION", PostproKind2D::dep_evolution},
      {"Fint EVOLUTION", PostproKind2D::fint_evolution},
      {"DRY CONTACT NATURE", PostproKind2D::dry_contact_nature},
      {"WET CONTACT NATURE", PostproKind2D::wet_contact_nature},
  };
  for (const Row& r : kRows)
    if (r.name == name) {
      kind = r.kind;
      return true;
    }
  return false;
}

bool Postpro2D::open(const std::filesystem::path& dir, std::vector<PostproCommand2D> commands,
                     std::string& error) {
  commands_ = std::move(commands);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  auto create = [&](const std::string& name, std::size_t command, std::int64_t body) {
    auto file = std::make_unique<std::ofstream>(dir / name, std::ios::trunc);
    if (!*file) {
      error = "cannot write '" + (dir / name).string() + "'";
      return false;
    }
    streams_.push_back({command, body, std::move(file), dir / name});
    stream_sets_.emplace_back();
    return true;
  };
  // POSTPRO.OUT is created empty (datbox-inputs.md §8).
  std::ofstream(dir / "POSTPRO.OUT", std::ios::trunc);
  for (std::size_t i = 0; i < commands_.size(); ++i) {
    const PostproCommand2D& c = commands_[i];
    bool ok = true;
    switch (c.kind) {
      case PostproKind2D::solver_informations:
        ok = create("SOLVER_INFORMATIONS.DAT", i, 0);
        break;
      case PostproKind2D::violation_evolution:
        ok = create("VIOLATION_EVOLUTION.DAT", i, 0);
        break;
      case PostproKind2D::dry_contact_nature:
        ok = create("DRY_CONTACT_NATURE.DAT", i, 0);
        break;
      case PostproKind2D::wet_contact_nature:
        ok = create("WET_CONTACT_NATURE.DAT", i, 0);
        break;
      case PostproKind2D::kinetic_energy:
        ok = create("KINETIC_ENERGY.DAT", i, 0);
        break;
      case PostproKind2D::dissipated_energy:
        ok = create("DISSIPATED_ENERGY.DAT", i, 0);
        break;
      case PostproKind2D::coordination_number:
        ok = create("COORDINATION_NUMBER.DAT", i, 0);
        break;
      case PostproKind2D::average_velocity_evolution:
        ok = create("AVERAGE_VELOCITY_EVOLUTION.DAT", i, 0);
        break;
      case PostproKind2D::body_tracking:
        for (std::int64_t b : c.bodies) ok = ok && create(fmt::format("BODY_{:07d}.DAT", b), i, b);
        break;
      case PostproKind2D::new_meca_sets:
        sets_ = c.sets;  // the sets of the Dep and Fint commands that follow it
        break;
      case PostproKind2D::dep_evolution:
      case PostproKind2D::fint_evolution:
        for (std::size_t k = 0; k < sets_.size(); ++k) {
          ok = ok && create(fmt::format("{}_{:07d}.DAT",
                                        c.kind == PostproKind2D::dep_evolution ? "Dep" : "Fint", k + 1),
                            i, static_cast<std::int64_t>(k + 1));
          if (ok) stream_sets_.back() = sets_[k];
        }
        break;
      case PostproKind2D::torque_evolution:
        for (std::int64_t b : c.bodies) ok = ok && create(fmt::format("TORQUE_{:07d}.DAT", b), i, b);
        break;
    }
    if (!ok) return false;
  }
  return true;
}

bool Postpro2D::write(const Scene2D& scene, const RunState2D& state, const NlgsResult& solver,
                      std::string& error) {
  const RigidBodies2D& b = scene.bodies;
  const double t = state.time, h = state.h;
  if (!state.contacts.empty()) {
    last_norms_ = solver.norms;
    last_nature_ = {solver.hover, solver.stick, solver.slide};
  }

  // Quantities shared by several commands, computed once per step when needed.
  double dissipated_step = 0.0;
  for (const Interaction2D& c : state.contacts) {
    if (c.status == ContactStatus::noctc || c.status == ContactStatus::vnish) continue;
    dissipated_step -=
        0.5 * (c.velocity_begin(1) + c.u(1)) * c.r(1) + 0.5 * (c.velocity_begin(0) + c.u(0)) * c.r(0);
  }
  bool dissipation_counted = false;

  for (Stream& s : streams_) {
    const PostproCommand2D& c = commands_[s.command];
    if (c.period <= 0 || state.step % c.period != 0) continue;
    std::ofstream& out = *s.file;
    switch (c.kind) {
      case PostproKind2D::solver_informations: {
        out << solver_informations_line(t, state.contacts.empty() ? 0 : solver.iterations, last_norms_,
                                        state.contacts.size());
        break;
      }
      case PostproKind2D::violation_evolution: {
        // Penetrations only (negative gaps), DKPLx not included as in LMGC90. LMGC90's get_gaps
        // returns (end, begin) while the caller names them (begin, end): its "begin" columns hold
        // the end-of-step gaps and the reverse; reproduced as written.
        double sum_begin = 0, sum_end = 0, max_begin = 0, max_end = 0;
        std::size_t n = 0;
        for (const Interaction2D& k : state.contacts) {
          // mailx-2d-contact.md §10: nor PLALp, P2P2L, DKDKL.
          if (k.family == PairFamily2D::DKPLx || k.family == PairFamily2D::PTPT2 ||
              k.family == PairFamily2D::PLALp || k.family == PairFamily2D::P2P2L ||
              k.family == PairFamily2D::DKDKL)
            continue;
          const double gb = std::min(0.0, k.gap_begin), ge = std::min(0.0, k.gap_begin + h * k.u(1));
          sum_begin -= gb;
          sum_end -= ge;
          max_begin = std::max(max_begin, -gb);
          max_end = std::max(max_end, -ge);
          ++n;
        }
        const double count = static_cast<double>(std::max<std::size_t>(n, 1));
        line(out, t, {sum_end / count, sum_begin / count, max_end, max_begin});
        break;
      }
      case PostproKind2D::dry_contact_nature: {
        // (ES15.8,5(1X,I8)) with three values: hovering, sticking, sliding (mailx-2d-contact.md §10).
        std::string text;
        grammar::append_fortran_es(text, t, 15, 8);
        for (std::size_t n : last_nature_) text += fmt::format(" {:8d}", n);
        out << text << '\n';
        break;
      }
      case PostproKind2D::wet_contact_nature: {
        // (ES15.8,3(1X,I16)): wet sticking, wet sliding, wet not touching, over the families LMGC90
        // lists (DKDKx, DKJCx, DKKDx, DKPLx, PLPLx). LMGC90 2025 leaves the status unread and writes
        // zeros (mailx-2d-contact.md §10); lmgc counts what the command names.
        std::size_t stick = 0, slide = 0, open = 0;
        for (const Interaction2D& k : state.contacts) {
          if (k.family != PairFamily2D::DKDKx && k.family != PairFamily2D::DKJCx &&
              k.family != PairFamily2D::DKKDx && k.family != PairFamily2D::DKPLx &&
              k.family != PairFamily2D::PLPLx)
            continue;
          stick += k.status == ContactStatus::Wstck;
          slide += k.status == ContactStatus::Wslbw || k.status == ContactStatus::Wslfw;
          open += k.status == ContactStatus::Wnctc;
        }
        std::string text;
        grammar::append_fortran_es(text, t, 15, 8);
        text += fmt::format(" {:16d} {:16d} {:16d}\n", stick, slide, open);
        out << text;
        break;
      }
      case PostproKind2D::dissipated_energy:
        if (!dissipation_counted) {
          dissipated_ += dissipated_step;
          dissipation_counted = true;
        }
        line(out, t, {dissipated_, dissipated_step});
        break;
      case PostproKind2D::kinetic_energy: {
        double kinetic = 0, potential = 0, power = 0;
        for (std::size_t i = 0; i < b.size(); ++i) {
          const Vector3d& v = b.velocity[i];
          kinetic +=
              0.5 * b.mass[i] * (v.x() * v.x() + v.y() * v.y() + v.z() * v.z() * b.gyrd[i] * b.gyrd[i]);
          potential += b.mass[i] * (b.displacement[i].x() * scene.gravity.x() +
                                    b.displacement[i].y() * scene.gravity.y());
          power += (b.impulse[i] / h + b.external_force[i]).dot(v);
        }
        external_work_ += h * power;
        line(out, t,
             {kinetic, kinetic, -external_work_, -potential, 0.0, kinetic + external_work_ + potential});
        break;
      }
      case PostproKind2D::new_meca_sets:
        break;
      case PostproKind2D::dep_evolution:
      case PostproKind2D::fint_evolution: {
        const auto& set = stream_sets_[static_cast<std::size_t>(&s - streams_.data())];
        const DeformableBodies& d = scene.deformable;
        // Dep: the mean of X and V over the entries; Fint: the sums of Reac, Fint, Finert, Fext, Res.
        std::array<double, 10> sum{};
        for (const auto& [body, node] : set) {
          if (body < 1 || static_cast<std::size_t>(body) > d.states.size()) continue;
          const MeshBodyState& m = d.states[static_cast<std::size_t>(body - 1)];
          const auto dof = static_cast<Eigen::Index>(2 * (node - 1));
          if (node < 1 || dof + 1 >= m.x.size()) continue;
          if (c.kind == PostproKind2D::dep_evolution) {
            for (int k = 0; k < 2; ++k) {
              sum[static_cast<std::size_t>(k)] += m.x(dof + k);
              sum[static_cast<std::size_t>(2 + k)] += m.v(dof + k);
            }
          } else {
            for (int k = 0; k < 2; ++k) {
              const auto at = static_cast<std::size_t>(k);
              sum[2 + at] += m.internal_force(dof + k);
              sum[4 + at] += m.inertial_force(dof + k);
              sum[6 + at] += m.f_ext(dof + k);
              sum[8 + at] += m.residue(dof + k);
            }
          }
        }
        if (c.kind == PostproKind2D::dep_evolution) {
          const auto n = static_cast<double>(set.size());
          line(out, t, {sum[0] / n, sum[1] / n, sum[2] / n, sum[3] / n});
        } else {
          line(out, t, {sum[0], sum[1], sum[2], sum[3], sum[4], sum[5], sum[6], sum[7], sum[8], sum[9]});
        }
        break;
      }
      case PostproKind2D::body_tracking: {
        const auto i = static_cast<std::size_t>(s.body - 1);
        if (i >= b.size()) break;
        const Vector3d coor = b.reference[i] + b.displacement[i];
        const Vector3d& x = b.displacement[i];
        const Vector3d& v = b.velocity[i];
        line(out, t, {coor.x(), coor.y(), coor.z(), x.x(), x.y(), x.z(), v.x(), v.y(), v.z()});
        break;
      }
      case PostproKind2D::torque_evolution: {
        const auto i = static_cast<std::size_t>(s.body - 1);
        if (i >= b.size()) break;
        const Vector3d reaction = b.impulse[i] / h;
        const Vector3d& f = b.external_force[i];
        line(out, t, {reaction.x(), reaction.y(), reaction.z(), f.x(), f.y(), f.z()});
        break;
      }
      case PostproKind2D::coordination_number: {
        // Contacts per body with |rn| > 1e-5 (forces); DKKDx, DKJCx and PLJCx count for the candidate only.
        constexpr double kTolerance = 1e-5;
        std::vector<int> plus(b.size(), 0), minus(b.size(), 0);
        for (const Interaction2D& k : state.contacts) {
          if (k.status == ContactStatus::noctc || k.status == ContactStatus::vnish) continue;
          if (is_mesh_family(k.family)) continue;  // rigid bodies' contacts only (mod_postpro_2D)
          const double rn = k.r(1) / h;
          const bool both = k.family == PairFamily2D::DKDKx || k.family == PairFamily2D::DKPLx ||
                            k.family == PairFamily2D::PLPLx;
          auto count = [&](std::int32_t body) {
            if (rn > kTolerance)
              ++plus[static_cast<std::size_t>(body)];
            else if (rn < -kTolerance)
              ++minus[static_cast<std::size_t>(body)];
          };
          count(k.candidate_body);
          if (both) count(k.antagonist_body);
        }
        std::int64_t nbp0 = 0, c0t = 0, c0p = 0, c0m = 0, nbp1 = 0, c1t = 0, c1p = 0, c1m = 0;
        for (std::size_t i = 0; i < b.size(); ++i) {
          const int total = plus[i] + minus[i];
          if (total >= 1) ++nbp0, c0t += total, c0p += plus[i], c0m += minus[i];
          if (total >= 2) ++nbp1, c1t += total, c1p += plus[i], c1m += minus[i];
        }
        std::string text;
        grammar::append_fortran_es(text, t, 15, 8);
        for (std::int64_t v :
             {static_cast<std::int64_t>(b.size()), nbp0, c0t, c0p, c0m, nbp1, c1t, c1p, c1m}) {
          text += ' ';
          grammar::append_fortran_i(text, v, 7);
        }
        out << text << '\n';
        break;
      }
      case PostproKind2D::average_velocity_evolution: {
        Vector3d mean = Vector3d::Zero();
        std::size_t n = 0;
        std::vector<std::uint8_t> counted(b.size(), 0);
        for (const Contactor2D& k : scene.contactors) {
          const auto i = static_cast<std::size_t>(k.body);
          if (counted[i] || k.rank != 1) continue;
          counted[i] = 1;
          if (k.color != c.color) continue;
          mean += b.velocity[i];
          ++n;
        }
        if (n > 0) mean /= static_cast<double>(n);
        line(out, t, {mean.x(), mean.y(), mean.z(), std::hypot(mean.x(), mean.y())});
        break;
      }
    }
  }
  if (flush_clock_.due())
    for (Stream& s : streams_) s.file->flush();
  return streams_good(error);
}

bool Postpro2D::close(std::string& error) {
  for (Stream& s : streams_) s.file->flush();
  const bool ok = streams_good(error);
  streams_.clear();
  return ok;
}

bool Postpro2D::streams_good(std::string& error) const {
  for (const Stream& s : streams_)
    if (!*s.file) {
      error = "cannot write '" + s.path.string() + "' (disk full?)";
      return false;
    }
  return true;
}

std::string solver_informations_line(double time, int iterations, const NlgsNorms& norms,
                                     std::size_t contacts) {
  std::string text;
  grammar::append_fortran_es(text, time, 15, 8);
  text += ' ';
  grammar::append_fortran_i(text, iterations, 8);
  for (double v : {norms.mean_dvor, norms.quad_dv, norms.quad_dvr}) {
    text += ' ';
    grammar::append_fortran_es(text, v, 14, 7);
  }
  text += ' ';
  grammar::append_fortran_i(text, static_cast<std::int64_t>(contacts), 8);
  text += '\n';
  return text;
}

}  // namespace lmgc::solver
