// COMMAND.DAT's time step against the fastest time scales that can be read off the data:
//  - a penalty contact law (parameter 'F/gap' = k, ELASTIC_REPELL_CLB and relatives) on bodies of
//    mass m oscillates with period 2 pi sqrt(m/k); with dt > sqrt(m/k) the spring is not resolved
//    (fewer than 2 pi steps per period);
//  - a body falling freely through a height d reaches v = sqrt(2 g d) and then moves v dt per step;
//    contacts are created only within the alert distance, so when v dt exceeds it the contact is
//    first seen already penetrated. Equivalently: the fall lasts sqrt(2 d / g), longer than the
//    time scale alert / (g dt) after which a body falling from rest moves more than the alert
//    distance per step.
// The fall height of a disk or sphere is measured down to the first contactor below it that a
// visibility row lets it touch (per-column search over a grid of columns: n log n).
// docs/lmgc90-facts/contact-laws.md §1.2 (alert), §3.3 (penalty laws); numerics.md §5.1 (detection).
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

#include "grammar/command/expand.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "spatial/multilevel_grid.hpp"
#include "validate/case_index.hpp"
#include "validate/checks.hpp"
#include "validate/rigid_layout.hpp"
#include "validate/visibility_table.hpp"

namespace lmgc::validate {
namespace {

using grammar::Location;

constexpr double kPi = 3.14159265358979323846;
// Columns wider than this many cells make an obstacle 'wide' (checked against every body).
constexpr double kMaxColumnsPerObstacle = 64.0;

// The TIME STEP value of COMMAND.DAT: the first argument line after a 'TIME STEP' line.
std::optional<grammar::Real> time_step_value(const grammar::CommandFile& file, double dt) {
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    if (file.lines[i].keyword != "TIME STEP") continue;
    for (std::size_t j = i + 1; j < file.lines.size() && j <= i + 2; ++j) {
      const auto& value = file.lines[j].value;
      if (value && !value->reals.empty() && value->reals[0].value == dt) return value->reals[0];
    }
  }
  return std::nullopt;
}

// Mass of a rigid body from its density and its equivalent radius (avrd) or its contactors;
// nullopt when it cannot be estimated.
std::optional<double> rigid_mass(const grammar::Body& body,
                                 const std::unordered_map<std::string, const grammar::BulkLaw*>& bulk,
                                 int dimension) {
  if (!body.rigid_bulk) return std::nullopt;
  auto it = bulk.find(body.rigid_bulk->behav.value);
  if (it == bulk.end() || it->second->density_field || !(it->second->density.value > 0.0))
    return std::nullopt;
  const double density = it->second->density.value;
  const double avrd = body.rigid_bulk->avrd.value;
  if (avrd > 0.0)
    return density * (dimension == 2 ? kPi * avrd * avrd : 4.0 / 3.0 * kPi * avrd * avrd * avrd);
  double measure = 0.0;
  for (const auto& c : body.contactors) {
    const std::string& t = c.type.value;
    const double r = c.values.empty() ? 0.0 : c.values[0].value;
    if (t == "DISKx" || t == "DISKb") {
      measure += kPi * r * r;
    } else if (t == "SPHER" || t == "SPHEb") {
      measure += 4.0 / 3.0 * kPi * r * r * r;
    } else if (t == "JONCx" && c.values.size() >= 2) {
      measure += 4.0 * c.values[0].value * c.values[1].value + kPi * c.values[1].value * c.values[1].value;
    } else if (t == "PLANx" && c.values.size() >= 3) {
      measure += 8.0 * c.values[0].value * c.values[1].value * c.values[2].value;
    } else if (t == "POLYG") {
      double area2 = 0.0;
      for (std::size_t k = 0; k < c.vertices.size(); ++k) {
        const auto& a = c.vertices[k];
        const auto& b = c.vertices[(k + 1) % c.vertices.size()];
        area2 += a[0].value * b[1].value - a[1].value * b[0].value;
      }
      measure += std::fabs(0.5 * area2);
    } else {
      return std::nullopt;
    }
  }
  if (!(measure > 0.0)) return std::nullopt;
  return density * measure;
}

// The highest position of the centre of a disk of radius r at horizontal coordinate u above a
// capsule (segment a-b thickened by t), in (horizontal, height) coordinates; -inf when none.
double capsule_top(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double t, double r, double u) {
  const double reach = t + r;
  double best = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& e : {a, b})
    if (std::fabs(u - e.x()) <= reach)
      best = std::max(best, e.y() + std::sqrt(reach * reach - (u - e.x()) * (u - e.x())));
  Eigen::Vector2d d = b - a;
  if (d.norm() > 0.0 && d.x() != 0.0) {
    d.normalize();
    Eigen::Vector2d n(-d.y(), d.x());
    if (n.y() < 0.0) n = -n;
    const Eigen::Vector2d p = a + reach * n, q = b + reach * n;
    if (u >= std::min(p.x(), q.x()) && u <= std::max(p.x(), q.x()))
      best = std::max(best, p.y() + (q.y() - p.y()) * (u - p.x()) / (q.x() - p.x()));
  }
  return best;
}

// The case seen along gravity: height = position . up, horizontal coordinates across it.
struct Frame {
  Eigen::Vector3d up, h1, h2;
  double height(const Eigen::Vector3d& p) const { return p.dot(up); }
};

struct Obstacle {
  std::size_t index;              // in the layout
  double top;                     // highest point along 'up'
  double u_lo, u_hi, v_lo, v_hi;  // horizontal extent
};

struct Fall {
  double ratio = 0.0;  // per-step travel / alert
  std::size_t body = 0, below = 0;
  double height = 0.0, speed = 0.0;
  const grammar::SeeEntry* row = nullptr;
};

// The worst free fall of the case (largest v dt / alert), if any exceeds 1.
std::optional<Fall> worst_fall(const CaseFiles& files, const RigidLayout& layout, double dt) {
  if (!files.bulk_behav || !files.tact_behav) return std::nullopt;
  const auto& placed = layout.contactors;
  Eigen::Vector3d gravity(files.bulk_behav->gravity[0].value, files.bulk_behav->gravity[1].value,
                          layout.dimension == 3 ? files.bulk_behav->gravity[2].value : 0.0);
  const double g = gravity.norm();
  if (!(g > 0.0) || !std::isfinite(g) || placed.empty()) return std::nullopt;
  Frame frame;
  frame.up = -gravity / g;
  if (layout.dimension == 2) {
    frame.h1 = Eigen::Vector3d(frame.up.y(), -frame.up.x(), 0.0);
    frame.h2 = Eigen::Vector3d::Zero();
  } else {
    frame.h1 = frame.up.unitOrthogonal();
    frame.h2 = frame.up.cross(frame.h1);
  }
  const SeeTable see(*files.tact_behav);

  // Obstacles in columns of width w (twice the median radius of the disks and spheres).
  std::vector<double> radii;
  for (const auto& p : placed)
    if ((p.shape == RigidShape::disk || p.shape == RigidShape::sphere) && p.radius > 0.0)
      radii.push_back(p.radius);
  if (radii.empty()) return std::nullopt;
  std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2), radii.end());
  const double w = 2.0 * radii[radii.size() / 2];
  auto column = [&](double x) { return spatial::grid_index(x, w); };
  std::unordered_map<std::int64_t, std::vector<Obstacle>> columns;  // key: column (2D), column pair (3D)
  auto key = [](std::int64_t a, std::int64_t b) { return a * 1'000'003 + b; };
  std::vector<Obstacle> capsules, wide;
  double largest_round = 0.0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& p = placed[i];
    if (!p.lo.allFinite() || !p.hi.allFinite()) continue;
    Obstacle o{i, -std::numeric_limits<double>::infinity(), 0, 0, 0, 0};
    if (p.shape == RigidShape::disk || p.shape == RigidShape::sphere) {
      const double u = p.centre.dot(frame.h1), v = p.centre.dot(frame.h2);
      o = {i, frame.height(p.centre) + p.radius, u - p.radius, u + p.radius, v - p.radius, v + p.radius};
      largest_round = std::max(largest_round, p.radius);
    } else {
      // Corners of the bounding box along gravity.
      double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo, v_lo = u_lo, v_hi = -u_lo,
             top = -u_lo;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d c((corner & 1) ? p.hi.x() : p.lo.x(), (corner & 2) ? p.hi.y() : p.lo.y(),
                                (corner & 4) ? p.hi.z() : p.lo.z());
        u_lo = std::min(u_lo, c.dot(frame.h1)), u_hi = std::max(u_hi, c.dot(frame.h1));
        v_lo = std::min(v_lo, c.dot(frame.h2)), v_hi = std::max(v_hi, c.dot(frame.h2));
        top = std::max(top, frame.height(c));
      }
      o = {i, top, u_lo, u_hi, v_lo, v_hi};
      if (p.shape == RigidShape::stadium) {
        capsules.push_back(o);
        continue;
      }
    }
    const std::int64_t a0 = column(o.u_lo), a1 = column(o.u_hi);
    const std::int64_t b0 = layout.dimension == 3 ? column(o.v_lo) : 0,
                       b1 = layout.dimension == 3 ? column(o.v_hi) : 0;
    if (double(a1 - a0 + 1) * double(b1 - b0 + 1) > kMaxColumnsPerObstacle || a1 < a0 || b1 < b0) {
      wide.push_back(o);
      continue;
    }
    for (std::int64_t a = a0; a <= a1; ++a)
      for (std::int64_t b = b0; b <= b1; ++b) columns[key(a, b)].push_back(o);
  }
  for (auto& [k, list] : columns)
    std::sort(list.begin(), list.end(), [](const Obstacle& x, const Obstacle& y) { return x.top > y.top; });

  std::optional<Fall> worst;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const auto& c = placed[i];
    if ((c.shape != RigidShape::disk && c.shape != RigidShape::sphere) || c.translation_driven ||
        !(c.radius > 0.0) || !c.centre.allFinite())
      continue;
    const double z = frame.height(c.centre);
    const double u = c.centre.dot(frame.h1), v = c.centre.dot(frame.h2);
    double best_stop = -std::numeric_limits<double>::infinity();
    const Obstacle* best = nullptr;
    const grammar::SeeEntry* best_row = nullptr;
    auto consider = [&](const Obstacle& o) {
      const auto& p = placed[o.index];
      if (p.body_index == c.body_index) return;
      const grammar::SeeEntry* row = see.find(c.see_class, p.see_class);
      if (!row) return;
      double stop;
      if (p.shape == RigidShape::disk || p.shape == RigidShape::sphere) {
        const double dh = std::hypot(p.centre.dot(frame.h1) - u, p.centre.dot(frame.h2) - v);
        const double reach = c.radius + p.radius;
        if (dh >= reach || frame.height(p.centre) >= z) return;
        stop = frame.height(p.centre) + std::sqrt(reach * reach - dh * dh);
      } else if (p.shape == RigidShape::stadium) {
        const Eigen::Vector3d along = p.axes.col(0) * p.half.x();
        const Eigen::Vector3d e0 = p.centre - along, e1 = p.centre + along;
        stop = capsule_top({e0.dot(frame.h1), frame.height(e0)}, {e1.dot(frame.h1), frame.height(e1)},
                           p.half.y(), c.radius, u);
      } else {
        if (o.u_hi < u - c.radius || o.u_lo > u + c.radius) return;
        if (layout.dimension == 3 && (o.v_hi < v - c.radius || o.v_lo > v + c.radius)) return;
        stop = o.top + c.radius;
      }
      if (stop > z + 1e-12 * c.radius || stop <= best_stop) return;
      best_stop = stop, best = &o, best_row = row;
    };
    const std::int64_t a0 = column(u - c.radius), a1 = column(u + c.radius);
    const std::int64_t b0 = layout.dimension == 3 ? column(v - c.radius) : 0,
                       b1 = layout.dimension == 3 ? column(v + c.radius) : 0;
    if (double(a1 - a0 + 1) * double(b1 - b0 + 1) > kMaxColumnsPerObstacle) continue;  // a giant: no estimate
    for (std::int64_t a = a0; a <= a1; ++a)
      for (std::int64_t b = b0; b <= b1; ++b) {
        auto it = columns.find(key(a, b));
        if (it == columns.end()) continue;
        const auto& list = it->second;
        // Obstacles whose top is above z + largest radius lie entirely above the body's centre.
        auto from = std::partition_point(list.begin(), list.end(),
                                         [&](const Obstacle& o) { return o.top > z + largest_round; });
        for (auto o = from; o != list.end(); ++o) {
          if (o->top + c.radius <= best_stop) break;  // sorted by top: nothing below can be higher
          consider(*o);
        }
      }
    for (const Obstacle& o : capsules) consider(o);
    for (const Obstacle& o : wide) consider(o);
    if (!best || !best_row || !(best_row->alert.value > 0.0)) continue;
    const double fall = std::max(0.0, z - best_stop);
    const double speed = std::sqrt(2.0 * g * fall);
    const double ratio = speed * dt / best_row->alert.value;
    if (ratio > 1.0 && (!worst || ratio > worst->ratio))
      worst = Fall{ratio, i, best->index, fall, speed, best_row};
  }
  return worst;
}

}  // namespace

void check_time_step(const CaseFiles& files, grammar::DiagnosticSink& sink, const CheckOptions& options) {
  if (!files.bodies) return;
  // The time step of the run's driver, and where it is written.
  double dt = 0.0;
  Location at_dt;
  if (script_drives(files, options)) {
    const auto calls = files.command_script->calls_to("TimeEvolution_SetTimeStep");
    if (calls.empty() || calls.back()->arguments.empty() || !calls.back()->arguments[0].value.number) return;
    const grammar::ScriptCall& call = *calls.back();
    dt = *call.arguments[0].value.number;
    at_dt = Location{files.command_script->path,
                     grammar::SourceSpan{call.line, call.column,
                                         static_cast<std::uint16_t>(call.column + call.name.size())}};
  } else if (command_dat_drives(files, options)) {
    grammar::DiagnosticSink scratch;  // COMMAND.DAT's own problems are reported by its reader
    const grammar::CommandRunParameters run = grammar::command_run_parameters(*files.command, scratch);
    dt = run.dt;
    const std::optional<grammar::Real> dt_value = time_step_value(*files.command, dt);
    at_dt = Location{datbox_path(files, "COMMAND.DAT"), dt_value ? dt_value->span : grammar::SourceSpan{}};
  }
  if (!(dt > 0.0) || !std::isfinite(dt)) return;
  const std::string tact_path = datbox_path(files, "TACT_BEHAV.DAT");
  const std::string bodies_path = datbox_path(files, "BODIES.DAT");

  const RigidLayout layout = place_rigid_contactors(files);

  // Penalty laws: dt against sqrt(m / k).
  if (files.tact_behav && files.bulk_behav) {
    const int dimension = layout.dimension;
    const auto bulk = bulk_laws_by_name(*files.bulk_behav);
    const auto laws = contact_laws_by_name(*files.tact_behav);
    // Lightest free body of each contactor class.
    std::unordered_map<std::string, std::pair<double, const PlacedContactor*>> lightest;
    std::unordered_map<const grammar::Body*, std::optional<double>> masses;
    for (const auto& p : layout.contactors) {
      if (p.translation_driven) continue;
      auto [it, inserted] = masses.emplace(p.body, std::nullopt);
      if (inserted) it->second = rigid_mass(*p.body, bulk, dimension);
      if (!it->second) continue;
      auto [entry, fresh] = lightest.emplace(p.see_class, std::make_pair(*it->second, &p));
      if (!fresh && *it->second < entry->second.first) entry->second = {*it->second, &p};
    }
    for (const auto& see : files.tact_behav->sees) {
      auto law = laws.find(see.law_nickname.value);
      if (law == laws.end()) continue;
      const grammar::LawKind* kind = grammar::find_law_kind(law->second->keyword.value);
      if (!kind) continue;
      double k = 0.0;
      for (std::size_t i = 0; i < kind->parameters.size() && i < law->second->parameters.size(); ++i)
        if (kind->parameters[i] == "F/gap") k = law->second->parameters[i].value;
      if (!(k > 0.0)) continue;
      const PlacedContactor* body = nullptr;
      double m = std::numeric_limits<double>::infinity();
      for (const std::string& cls :
           {see_class(see.candidate_body.value, see.candidate_contactor.value, see.candidate_colour.value),
            see_class(see.antagonist_body.value, see.antagonist_contactor.value,
                      see.antagonist_colour.value)}) {
        auto it = lightest.find(cls);
        if (it != lightest.end() && it->second.first < m) m = it->second.first, body = it->second.second;
      }
      if (!body) continue;
      const double period = std::sqrt(m / k);
      if (dt <= period) continue;
      report_related(
          sink, "L3013", at_dt,
          fmt::format("time step {:.3g} is larger than sqrt(m/k) = {:.3g} of the penalty law '{}' ({}, "
                      "F/gap = {:.3g}) on {} {} (mass {:.3g}): the contact spring is not resolved",
                      dt, period, law->second->nickname.value, law->second->keyword.value, k,
                      grammar::body_type_keyword(body->body->type), body->rank, m),
          {{Location{tact_path, see.law_nickname.span}, "the visibility row using the law"},
           {Location{bodies_path, body->contactor->type.span}, "the lightest body it applies to"}},
          fmt::format("take dt <= {:.3g} (a tenth of the period 2 pi sqrt(m/k) is usual)",
                      0.2 * kPi * period));
    }
  }

  // Free falls: v dt against the alert distance.
  if (const std::optional<Fall> fall = worst_fall(files, layout, dt)) {
    const PlacedContactor& body = layout.contactors[fall->body];
    const PlacedContactor& below = layout.contactors[fall->below];
    const double alert = fall->row->alert.value;
    report_related(
        sink, "L3013", at_dt,
        fmt::format(
            "time step {:.3g} is too large for the fall of {} {}: falling {:.3g} onto {} {}, it reaches a "
            "speed of {:.3g} and moves {:.3g} per step, more than the alert distance {:.3g}; the contact is "
            "first seen already penetrated",
            dt, grammar::body_type_keyword(body.body->type), body.rank, fall->height,
            grammar::body_type_keyword(below.body->type), below.rank, fall->speed, fall->speed * dt, alert),
        {{Location{bodies_path, body.contactor->type.span}, "the falling body"},
         {Location{tact_path, fall->row->alert.span}, "the alert distance of the pair"}},
        fmt::format("take dt <= {:.3g}, or an alert distance >= {:.3g}", alert / fall->speed,
                    fall->speed * dt));
  }
}

}  // namespace lmgc::validate
