#include "chipy/session.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic_catalogue.hpp"
#include "grammar/common/output_file.hpp"
#include "grammar/dof/writer.hpp"
#include "grammar/gpv/writer.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/case_input.hpp"
#include "solver/driver/run_2d.hpp"
#include "solver/driver/run_3d.hpp"
#include "solver/driver/step_log.hpp"
#include "solver/io/display_2d.hpp"
#include "solver/io/display_3d.hpp"
#include "solver/io/exact_state.hpp"
#include "solver/io/mesh_gauss_values.hpp"
#include "solver/io/postpro_2d.hpp"
#include "solver/io/postpro_3d.hpp"
#include "solver/io/state_files_2d.hpp"
#include "solver/io/state_files_3d.hpp"
#include "validate/checks.hpp"
#include "validate/render.hpp"

namespace lmgc::chipy {

namespace fem = solver::fem;

namespace {

namespace fs = std::filesystem;
using solver::NlgsResult;

[[noreturn]] void fail(ErrorKind kind, const std::string& message) {
  throw Error(kind, message);
}

// The stages of a step in LMGC90's order, with the stages each needs earlier in the same step.
// The order of the calls is free where the data allow it; a stage whose input another has not made
// yet, or that comes after a stage that needed it, is refused.
enum Stage : int {
  increment_step,
  compute_fext,
  compute_bulk,
  compute_free_velocity,
  select_prox_tactors,
  recup_rloc,
  ex_solver,
  update_tact_behav,
  stock_rloc,
  compute_dof,
  update_step,
  stage_count
};

struct StageRule {
  std::string_view name;
  std::uint32_t needs;
};

constexpr std::uint32_t bit(Stage s) {
  return 1u << s;
}

constexpr std::array<StageRule, stage_count> kStageRules{{
    {"IncrementStep", 0},
    {"ComputeFext", bit(Stage::increment_step)},
    {"ComputeBulk", bit(Stage::increment_step)},
    {"ComputeFreeVelocity", bit(Stage::compute_fext)},
    {"SelectProxTactors", bit(Stage::increment_step)},
    {"RecupRloc", bit(Stage::select_prox_tactors)},
    {"ExSolver",
     bit(Stage::compute_free_velocity) | bit(Stage::select_prox_tactors) | bit(Stage::recup_rloc)},
    {"UpdateTactBehav", bit(Stage::ex_solver)},
    {"StockRloc", bit(Stage::ex_solver)},
    {"ComputeDof", bit(Stage::ex_solver)},
    {"UpdateStep", bit(Stage::compute_dof) | bit(Stage::stock_rloc)},
}};

std::optional<Stage> stage_of(std::string_view name) {
  for (int s = 0; s < stage_count; ++s)
    if (kStageRules[static_cast<std::size_t>(s)].name == name) return static_cast<Stage>(s);
  return std::nullopt;
}

std::string names_of(std::uint32_t mask) {
  std::string list;
  for (int s = 0; s < stage_count; ++s)
    if (mask & bit(static_cast<Stage>(s)))
      list += (list.empty() ? "" : ", ") + std::string(kStageRules[static_cast<std::size_t>(s)].name);
  return list;
}

std::string reading_name(Reading r) {
  static constexpr std::array<std::string_view, static_cast<int>(Reading::count)> names{
      "ReadBehaviours", "ReadBodies",  "LoadBehaviours", "ReadIniDof",
      "ReadDrivenDof",  "LoadTactors", "ReadIniVlocRloc"};
  return std::string(names[static_cast<std::size_t>(r)]);
}

// The body vectors of chipy's RBDY2_/RBDY3_GetBodyVector and PutBodyVector (mod_RBDY2
// get_vector_RBDY2, put_vector_RBDY2; mod_RBDY3 the same): 'Coor*' are positions (3 in 2D with
// the rotation, 3 in 3D), the others a value per dof.
enum class BodyVector { coor0, coor, coorb, coorm, x, xbeg, v, vbeg, vfree, reac, ireac, fext };
struct BodyVectorName {
  std::string_view name;
  BodyVector vector;
  bool gettable, puttable;
};
constexpr std::array<BodyVectorName, 12> kBodyVectors{{
    {"Coor0", BodyVector::coor0, true, true},
    {"Coor_", BodyVector::coor, true, true},
    {"Coorb", BodyVector::coorb, true, true},
    {"Coorm", BodyVector::coorm, true, false},
    {"X____", BodyVector::x, true, true},
    {"Xbeg_", BodyVector::xbeg, true, true},
    {"V____", BodyVector::v, true, true},
    {"Vbeg_", BodyVector::vbeg, true, true},
    {"Vfree", BodyVector::vfree, true, true},
    {"Reac_", BodyVector::reac, true, true},
    {"Ireac", BodyVector::ireac, true, true},
    {"Fext_", BodyVector::fext, true, true},
}};
// Known to LMGC90, not kept by lmgc's rigid bodies.
constexpr std::array<std::string_view, 5> kUnkeptBodyVectors{"Vaux_", "Raux_", "Iaux_", "Fint_", "Xdriv"};

const BodyVectorName& body_vector_name(std::string_view name, bool put, int dimension) {
  std::string trimmed(name);
  for (const BodyVectorName& v : kBodyVectors)
    if (v.name == trimmed) {
      if (put && !v.puttable)
        fail(ErrorKind::value,
             "RBDY" + std::to_string(dimension) + "_PutBodyVector: '" + trimmed + "' can be read, not set");
      if (dimension == 3 && v.vector == BodyVector::coorm)
        fail(ErrorKind::not_implemented,
             "RBDY3 'Coorm' (the detection configuration) is not offered by lmgc");
      return v;
    }
  for (std::string_view unkept : kUnkeptBodyVectors)
    if (unkept == trimmed)
      fail(ErrorKind::not_implemented, "body vector '" + trimmed +
                                           "': lmgc's rigid bodies do not keep it (they offer Coor0, Coor_, "
                                           "Coorb, X____, Xbeg_, V____, Vbeg_, Vfree, Reac_, Ireac, Fext_)");
  fail(ErrorKind::value,
       "unknown body vector '" + trimmed +
           "' (Coor0, Coor_, Coorb, Coorm, X____, Xbeg_, V____, Vbeg_, Vfree, Reac_, Ireac, "
           "Fext_)");
}

}  // namespace

// What the session keeps of a case once read: the dimension's scene, run state and writers. The
// operations the session needs are virtual; DimensionRun implements them for 2D and 3D.
struct Session::Run {
  virtual ~Run() = default;
  case_folder::CaseFiles files;
  bool started = false;
  bool in_step = false;
  std::uint32_t done = 0;  // the stages run in the step in progress
  std::chrono::steady_clock::time_point step_start;
  NlgsResult result;  // the last ExSolver's
  long dof_written = 0, vloc_rloc_written = 0;
  solver::RunSummary summary;
  std::unique_ptr<solver::StepLog> log;
  bool postpro_open = false, display_open = false;
  std::string stopped;             // why the run cannot go on (a non-finite state, a failed write)
  bool inverted_reported = false;  // an inverted element was reported in the step in progress
  // The script's imposed velocities of this step: (body, dof, value).
  std::vector<std::tuple<std::size_t, int, double>> imposed;

  virtual int dimension() const = 0;
  virtual bool prepare(grammar::DiagnosticSink& sink) = 0;
  virtual std::vector<case_folder::OutputFile> echo_files() const = 0;
  virtual bool start(const run::RunOptions& options, bool warm_start) = 0;
  virtual void run_stage(std::string_view name, const solver::NlgsOptions& options) = 0;
  virtual bool keeps_law_state() const = 0;
  virtual bool has_plplx() const = 0;
  virtual std::string non_finite() const = 0;
  virtual double kinetic_energy() const = 0;
  virtual std::size_t contacts() const = 0;
  virtual double time() const = 0;
  virtual long step() const = 0;
  virtual void set_time_step(double dt) = 0;
  virtual std::string dof_text() const = 0;
  virtual std::string vloc_rloc_text() const = 0;
  virtual std::string exact_state_text() const = 0;
  virtual bool open_postpro(std::string& error) = 0;
  virtual bool write_postpro(std::string& error) = 0;
  virtual bool close_postpro(std::string& error) = 0;
  virtual bool write_display(std::string& error) = 0;
  virtual std::size_t bodies() const = 0;
  virtual int dofs() const = 0;
  virtual int size_of(BodyVector v) const = 0;
  virtual void get_into(BodyVector v, std::size_t body, double* out) const = 0;
  virtual void put(BodyVector v, std::size_t body, std::span<const double> value) = 0;
  virtual bool vlocy_driven(std::size_t body, int dof) const = 0;
  virtual void impose_velocity(std::size_t body, int dof, double value, bool after_free_velocity) = 0;
  virtual double mass(std::size_t body) const = 0;
  virtual bool visible(std::size_t body) const = 0;
  virtual grammar::VlocRlocFile vloc_rloc() const = 0;
  virtual bool has_meshes() const = 0;
  virtual std::string gpv_text() const = 0;
  virtual void set_rayleigh(double alpha, double beta) = 0;
  virtual void compute_bulk() = 0;  // ComputeBulk in a step: large-strain bodies at their iterate
  // mecaMAILx_ComputeResidueNorm (0 without deformable bodies).
  virtual double residue_norm() = 0;
  // "MAILx body b, element e (Q4xxx), Gauss point p is inverted ..." when the last evaluation of a
  // large-strain body failed there (det F ≤ 0, or J2's return mapping).
  virtual std::string inverted() const = 0;
  // Back to the beginning of the step in progress (a redone or abandoned step): positions and
  // velocities, the clock (time_begin, the step before).
  virtual void restore_step_begin() = 0;
  // A step without the contact stages (a case without contact laws): V = V_free for the rigid bodies.
  virtual void skip_contacts() = 0;
  fem::Hypothesis hypothesis = fem::Hypothesis::plane_strain;
  long gpv_written = 0;
  double time_begin = 0.0;  // the clock when the step in progress began
};

namespace {

struct Traits2D {
  using Scene = solver::Scene2D;
  using State = solver::RunState2D;
  using Outputs = solver::RunOutputs2D;
  using Postpro = solver::Postpro2D;
  using Display = solver::DisplayWriter2D;
  static constexpr int kDimension = 2;
  static constexpr int kDofs = 3;
  static bool prepare(const case_folder::CaseFiles& f, Scene& s, Outputs& o, grammar::DiagnosticSink& sink,
                      fem::Hypothesis h) {
    return solver::prepare_run_2d(f, s, o, sink, h);
  }
  static std::vector<case_folder::OutputFile> echo(const case_folder::CaseFiles& f) {
    return solver::echo_files_2d(f);
  }
  static bool start(Scene& s, const run::RunOptions& o, const Outputs& out, State& st,
                    solver::RunSummary& summary) {
    return solver::start_run_2d(s, o, out, st, summary);
  }
  static std::span<const solver::StepStage2D> stages() { return solver::step_stages_2d(); }
  static bool keeps_law_state(const Scene& s) { return solver::scene_keeps_law_state_2d(s); }
  static std::string non_finite(const Scene& s, const State& st) { return solver::non_finite_2d(s, st); }
  static grammar::DofFile dof(const Scene& s, const State& st) { return solver::dof_file_2d(s, st); }
  static grammar::VlocRlocFile vloc_rloc(const Scene& s, const State& st) {
    return solver::vloc_rloc_file_2d(s, st);
  }
};

struct Traits3D {
  using Scene = solver::Scene3D;
  using State = solver::RunState3D;
  using Outputs = solver::RunOutputs3D;
  using Postpro = solver::Postpro3D;
  using Display = solver::DisplayWriter3D;
  static constexpr int kDimension = 3;
  static constexpr int kDofs = 6;
  static bool prepare(const case_folder::CaseFiles& f, Scene& s, Outputs& o, grammar::DiagnosticSink& sink,
                      fem::Hypothesis) {
    return solver::prepare_run_3d(f, s, o, sink);
  }
  static std::vector<case_folder::OutputFile> echo(const case_folder::CaseFiles& f) {
    return solver::echo_files_3d(f);
  }
  static bool start(Scene& s, const run::RunOptions& o, const Outputs& out, State& st,
                    solver::RunSummary& summary) {
    return solver::start_run_3d(s, o, out, st, summary);
  }
  static std::span<const solver::StepStage3D> stages() { return solver::step_stages_3d(); }
  static bool keeps_law_state(const Scene& s) {
    for (const auto& v : s.visibility)
      if (solver::keeps_law_state_3d(s.laws[static_cast<std::size_t>(v.law)].law)) return true;
    return false;
  }
  static std::string non_finite(const Scene& s, const State& st) { return solver::non_finite_3d(s, st); }
  static grammar::DofFile dof(const Scene& s, const State& st) { return solver::dof_file_3d(s, st); }
  static grammar::VlocRlocFile vloc_rloc(const Scene& s, const State& st) {
    return solver::vloc_rloc_file_3d(s, st);
  }
};

template <class T>
struct DimensionRun final : Session::Run {
  typename T::Scene scene;
  typename T::State state;
  typename T::Outputs outputs;
  typename T::Postpro postpro;
  std::unique_ptr<typename T::Display> display;

  int dimension() const override { return T::kDimension; }
  bool prepare(grammar::DiagnosticSink& sink) override {
    outputs.case_dir = files.case_dir;
    return T::prepare(files, scene, outputs, sink, hypothesis);
  }
  std::vector<case_folder::OutputFile> echo_files() const override { return T::echo(files); }
  bool start(const run::RunOptions& options, bool warm_start) override {
    typename T::Outputs o = outputs;
    if (!warm_start) o.warm_start = nullptr;
    started = T::start(scene, options, o, state, summary);
    return started;
  }
  void run_stage(std::string_view name, const solver::NlgsOptions& options) override {
    for (const auto& stage : T::stages())
      if (stage.name == name) {
        stage.run(scene, state, options, result);
        return;
      }
  }
  bool keeps_law_state() const override { return T::keeps_law_state(scene); }
  bool has_plplx() const override {
    if constexpr (T::kDimension == 2) {
      return scene.plan.families[static_cast<std::size_t>(solver::PairFamily2D::PLPLx)];
    } else {
      return false;
    }
  }
  std::string non_finite() const override { return T::non_finite(scene, state); }
  double kinetic_energy() const override { return solver::kinetic_energy(scene.bodies); }
  std::size_t contacts() const override { return state.contacts.size(); }
  double time() const override { return started ? state.time : outputs.initial_time; }
  long step() const override { return started ? state.step : outputs.initial_step; }
  void set_time_step(double dt) override { state.h = dt; }
  std::string dof_text() const override { return grammar::write_dof(T::dof(scene, state)); }
  std::string vloc_rloc_text() const override { return grammar::write_vloc_rloc(T::vloc_rloc(scene, state)); }
  std::string exact_state_text() const override { return solver::write_exact_state(scene, state); }
  grammar::VlocRlocFile vloc_rloc() const override { return T::vloc_rloc(scene, state); }
  bool has_meshes() const override {
    if constexpr (T::kDimension == 2)
      return !scene.deformable.empty();
    else
      return false;
  }
  std::string gpv_text() const override {
    if constexpr (T::kDimension == 2)
      return grammar::write_gpv(solver::gauss_point_values_file(scene.deformable, state.step, state.time));
    else
      return {};
  }
  double residue_norm() override {
    if constexpr (T::kDimension == 2)
      return solver::compute_residue_norm(scene.deformable, state);
    else
      return 0.0;
  }
  std::string inverted() const override {
    if constexpr (T::kDimension == 2) {
      if (const auto found = solver::inverted_element(scene.deformable)) {
        const auto& [body, where] = *found;
        const auto& element = scene.deformable.meshes.bodies[body].elements[where.element];
        return "MAILx body " + std::to_string(body + 1) + ", element " + std::to_string(where.element + 1) +
               " (" + std::string(fem::element_entry(element.kind).name) + "), Gauss point " +
               std::to_string(where.point + 1) +
               (where.return_mapping ? ": its plastic return mapping does not converge in 50 iterations"
                                     : " is inverted (det F <= 0)");
      }
    }
    return {};
  }
  void restore_step_begin() override {
    auto& b = scene.bodies;
    b.displacement = b.displacement_begin;
    b.velocity = b.velocity_begin;
    if constexpr (T::kDimension == 2)
      for (auto& body : scene.deformable.states) {
        body.x = body.x_begin;
        body.v = body.v_begin;
        body.inverted.reset();
      }
    if constexpr (T::kDimension == 3) b.frame = b.frame_initial;
    state.time = time_begin;
    --state.step;
  }
  void compute_bulk() override {
    if constexpr (T::kDimension == 2) solver::bulk_deformable(scene.deformable, state);
  }
  void skip_contacts() override { scene.bodies.velocity = scene.bodies.velocity_free; }
  void set_rayleigh(double alpha, double beta) override {
    if constexpr (T::kDimension == 2) {
      solver::set_rayleigh_damping(scene.deformable, alpha, beta);
    }
  }
  bool open_postpro(std::string& error) override {
    if (outputs.postpro.empty()) return true;
    return postpro.open(files.case_dir / "POSTPRO", outputs.postpro, error);
  }
  bool write_postpro(std::string& error) override {
    return outputs.postpro.empty() || postpro.write(scene, state, result, error);
  }
  bool close_postpro(std::string& error) override { return outputs.postpro.empty() || postpro.close(error); }
  bool write_display(std::string& error) override {
    if (!display) display = std::make_unique<typename T::Display>(files.case_dir / "DISPLAY");
    return display->write(scene, state, error);
  }
  std::size_t bodies() const override { return scene.bodies.size(); }
  int dofs() const override { return T::kDofs; }

  // The size of a body vector: positions 3 (2D: x, y, angle; 3D: x, y, z), the others a value per dof.
  int size_of(BodyVector v) const override {
    return v == BodyVector::coor0 || v == BodyVector::coor || v == BodyVector::coorb || v == BodyVector::coorm
               ? 3
               : T::kDofs;
  }
  template <class V>
  static void copy(const V& v, double* out) {
    for (int k = 0; k < static_cast<int>(v.size()); ++k) out[k] = v(k);
  }
  // Writes body i's vector into out[0, size_of(v)).
  void get_into(BodyVector v, std::size_t i, double* out) const override {
    const auto& b = scene.bodies;
    // Positions: 2D (x, y, angle) = reference + X; 3D (x, y, z) = reference + X(1:3).
    const auto position = [&](const auto& displacement) {
      if constexpr (T::kDimension == 2)
        copy(Eigen::Vector3d(b.reference[i] + displacement), out);
      else
        copy(Eigen::Vector3d(b.reference[i] + displacement.template head<3>()), out);
    };
    switch (v) {
      case BodyVector::coor0:
        return copy(b.reference[i], out);
      case BodyVector::coor:
        return position(b.displacement[i]);
      case BodyVector::coorb:
        return position(b.displacement_begin[i]);
      case BodyVector::coorm:
        if constexpr (T::kDimension == 2)
          copy(Eigen::Vector3d(b.reference[i] + b.displacement_begin[i] +
                               (1.0 - state.theta) * state.h * b.velocity_begin[i]),
               out);
        return;
      case BodyVector::x:
        return copy(b.displacement[i], out);
      case BodyVector::xbeg:
        return copy(b.displacement_begin[i], out);
      case BodyVector::v:
        return copy(b.velocity[i], out);
      case BodyVector::vbeg:
        return copy(b.velocity_begin[i], out);
      case BodyVector::vfree:
        return copy(b.velocity_free[i], out);
      case BodyVector::reac:
        copy(b.impulse[i], out);
        for (int k = 0; k < T::kDofs; ++k) out[k] /= state.h;
        return;
      case BodyVector::ireac:
        return copy(b.impulse[i], out);
      case BodyVector::fext:
        return copy(b.external_force[i], out);
    }
  }
  template <class V>
  static void assign(V& target, std::span<const double> value) {
    for (int k = 0; k < static_cast<int>(target.size()); ++k) target(k) = value[static_cast<std::size_t>(k)];
  }
  void put(BodyVector v, std::size_t i, std::span<const double> value) override {
    auto& b = scene.bodies;
    switch (v) {
      case BodyVector::coor0:
        assign(b.reference[i], value);
        break;
      case BodyVector::coor:
      case BodyVector::coorb: {
        // put_coor / put_coor_begin: X = coor - reference.
        auto& x = v == BodyVector::coor ? b.displacement[i] : b.displacement_begin[i];
        for (int k = 0; k < 3; ++k) x(k) = value[static_cast<std::size_t>(k)] - b.reference[i](k);
        break;
      }
      case BodyVector::x:
        assign(b.displacement[i], value);
        break;
      case BodyVector::xbeg:
        assign(b.displacement_begin[i], value);
        break;
      case BodyVector::v:
        assign(b.velocity[i], value);
        break;
      case BodyVector::vbeg:
        assign(b.velocity_begin[i], value);
        break;
      case BodyVector::vfree:
        assign(b.velocity_free[i], value);
        break;
      case BodyVector::reac:
        assign(b.impulse[i], value);
        b.impulse[i] *= state.h;
        break;
      case BodyVector::ireac:
        assign(b.impulse[i], value);
        break;
      case BodyVector::fext:
        // put_vector 'Fext_' adds to the step's external force.
        for (int k = 0; k < T::kDofs; ++k) b.external_force[i](k) += value[static_cast<std::size_t>(k)];
        break;
      case BodyVector::coorm:
        break;
    }
  }
  bool vlocy_driven(std::size_t body, int dof) const override {
    for (const auto& d : scene.driven)
      if (!d.is_force && static_cast<std::size_t>(d.body) == body && d.dof == dof) return true;
    return false;
  }
  void impose_velocity(std::size_t body, int dof, double value, bool after_free_velocity) override {
    if (!scene.bodies.visible[body]) return;  // set_vlocy_drvdof skips invisible bodies
    if (after_free_velocity) {
      scene.bodies.velocity_free[body](dof) = value;
      scene.bodies.velocity[body](dof) = value;
    }
  }
  double mass(std::size_t body) const override { return scene.bodies.mass[body]; }
  bool visible(std::size_t body) const override { return scene.bodies.visible[body] != 0; }
};

}  // namespace

Session::Session(fs::path case_dir, SessionOptions options)
    : case_dir_(std::move(case_dir)), session_options_(options) {}

Session::~Session() {
  // A script that ends without Finalize (or raises) keeps whole files: POSTPRO lines and the run
  // report are flushed and closed here.
  try {
    end_run_files();
  } catch (...) {
  }
}

void Session::warn(const std::string& message) const {
  if (!session_options_.quiet) std::cerr << "lmgc: warning: " << message << "\n";
}

// Set-up ----------------------------------------------------------------------------------------

void Session::set_dimension(int dimension, int mode) {
  if (dimension != 2 && dimension != 3)
    fail(ErrorKind::value, "SetDimension: the dimension is 2 or 3, not " + std::to_string(dimension));
  if (run_) fail(ErrorKind::order, "SetDimension after the case was read (call it before ReadDatbox)");
  // mod: 1 plane strain, 2 plane stress, 3 axisymmetric (LMGC90 stops on anything else).
  if (dimension == 2 && (mode < 1 || mode > 3))
    fail(ErrorKind::value,
         "SetDimension: mod is 1 (plane strain), 2 (plane stress) or 3 (axisymmetric), not " +
             std::to_string(mode));
  dimension_ = dimension;
  mode_ = mode;
}

void Session::set_time_step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    fail(ErrorKind::value, "TimeEvolution_SetTimeStep: the time step must be a positive finite number");
  options_.dt = dt;
  if (run_ && run_->started) run_->set_time_step(dt);
}

void Session::init_theta(double theta) {
  if (!(theta >= 0.5 && theta <= 1.0))
    fail(ErrorKind::value, "Integrator_InitTheta: θ is in [0.5, 1], not " + std::to_string(theta));
  if (run_ && run_->started) fail(ErrorKind::order, "Integrator_InitTheta after the first step");
  options_.theta = theta;
}

void Session::set_quick_scramble(int dimension) {
  (dimension == 2 ? quick_scramble_2d_ : quick_scramble_3d_) = true;
}

void Session::set_diagonal_resolution() {
  options_.nlgs.diagonal_resolution = true;
}

void Session::set_periodic(std::optional<double> x_period, std::optional<double> y_period) {
  if (run_ && run_->started)
    fail(ErrorKind::not_implemented,
         "SetPeriodicCondition after the first step: lmgc sets periods before it");
  for (const auto& p : {x_period, y_period})
    if (p && (!(*p > 0.0) || !std::isfinite(*p)))
      fail(ErrorKind::value, "SetPeriodicCondition: a period must be a positive finite number");
  if (x_period) options_.x_period = *x_period;
  if (y_period) {
    if (dimension_ == 2)
      fail(ErrorKind::value, "SetPeriodicCondition: yperiod applies to 3D (RBDY3) cases only");
    options_.y_period = *y_period;
  }
}

void Session::set_boundary(char axis, bool maximum, double value) {
  if (!std::isfinite(value)) fail(ErrorKind::value, "RBDY2 boundary: the bound must be a finite number");
  if (run_ && run_->started)
    fail(ErrorKind::not_implemented, "RBDY2 boundaries after the first step: lmgc sets them before it");
  double& bound =
      axis == 'x' ? (maximum ? options_.x_max : options_.x_min) : (maximum ? options_.y_max : options_.y_min);
  bound = value;
}

void Session::new_rotation_scheme() {
  if (run_ && run_->started) fail(ErrorKind::order, "RBDY3_NewRotationScheme after the first step");
  options_.new_rotation_scheme = true;
}

void Session::set_source_point(long first, double radius, double x, double y, double z, bool absolute) {
  if (run_ && run_->started) fail(ErrorKind::order, "RBDY3_SetSourcePoint after the first step");
  if (first < 1 || !(radius > 0.0) || !std::isfinite(radius) || !std::isfinite(x) || !std::isfinite(y) ||
      !std::isfinite(z))
    fail(ErrorKind::value,
         "RBDY3_SetSourcePoint: a first body of at least 1, a positive radius, a finite point");
  options_.source_first = first;
  options_.source_radius = radius;
  options_.source_point[0] = x;
  options_.source_point[1] = y;
  options_.source_point[2] = z;
  options_.source_point_absolute = absolute;
}

void Session::set_cundall_iterations(int iterations) {
  if (iterations < 1) fail(ErrorKind::value, "PRPRx_UseCpCundallDetection: at least 1 iteration");
  options_.cundall_iterations = iterations;
}

void Session::ptpt3_load_network() {
  if (run_ && run_->started) fail(ErrorKind::order, "PTPT3_LoadNetwork after the first step");
  options_.ptpt3_network = true;
}

void Session::ptpt3_use_current_nonuc0(int use) {
  options_.ptpt3_current_nonuc0 = use != 0;
}

// DATBOX -----------------------------------------------------------------------------------------

void Session::read(Reading what) {
  if (finalized_) fail(ErrorKind::order, "the session was finalized (Finalize); call Initialize again");
  if (dimension_ == 0) fail(ErrorKind::order, reading_name(what) + " before SetDimension");
  bool& done = read_[static_cast<int>(what)];
  if (done) fail(ErrorKind::order, reading_name(what) + " twice: the case's files are read once");
  if (run_ && run_->started) fail(ErrorKind::order, reading_name(what) + " after the first step");
  if (!run_) {
    grammar::DiagnosticSink sink(5000);
    auto files = case_folder::load_case(case_dir_, sink, case_folder::LoadOptions{true});
    if (files) {
      // The script drives the run: COMMAND.DAT is not read (LMGC90 2025 no longer reads it), and
      // the calls the script makes are checked as they come, not read from its text.
      files->command.reset();
      files->command_script.reset();
      validate::check_case(*files, sink, validate::CheckOptions{false, false});
    }
    const bool three_d = files && solver::is_rigid_3d_case(*files);
    std::unique_ptr<Run> run;
    if (files && !sink.has_errors()) {
      if (three_d != (dimension_ == 3)) {
        fail(ErrorKind::data, "SetDimension(" + std::to_string(dimension_) + ") but the case's bodies are " +
                                  (three_d ? "RBDY3" : "not all RBDY3"));
      }
      if (three_d)
        run = std::make_unique<DimensionRun<Traits3D>>();
      else
        run = std::make_unique<DimensionRun<Traits2D>>();
      run->files = std::move(*files);
      run->hypothesis = three_d      ? fem::Hypothesis::three_d
                        : mode_ == 2 ? fem::Hypothesis::plane_stress
                        : mode_ == 3 ? fem::Hypothesis::axisymmetric
                                     : fem::Hypothesis::plane_strain;
      run->prepare(sink);
    }
    std::string report;
    bool refused = false;
    for (const auto& d : sink.items()) {
      refused |= grammar::refuses_run(d.code);
      if (d.severity == grammar::Severity::error || grammar::refuses_run(d.code) ||
          (!session_options_.quiet && d.severity == grammar::Severity::warning)) {
        const auto lookup = [&](const std::string& file, std::uint32_t line) -> std::string_view {
          if (!run) return {};
          auto it = run->files.sources.find(file);
          return it == run->files.sources.end() ? std::string_view{} : it->second.line_text(line);
        };
        const std::string text = validate::render_text(d, lookup, {false});
        if (d.severity == grammar::Severity::error || grammar::refuses_run(d.code))
          report += text;
        else
          std::cerr << text;
      }
    }
    if (!files)
      fail(ErrorKind::data, "ReadDatbox: " + case_dir_.string() + " is not a case folder\n" + report);
    if (sink.has_errors()) fail(ErrorKind::data, "the case's data are invalid:\n" + report);
    if (refused) fail(ErrorKind::not_implemented, "the case uses what lmgc does not run yet:\n" + report);
    run_ = std::move(run);
  }
  done = true;
}

void Session::require_case(std::string_view call) const {
  if (finalized_) fail(ErrorKind::order, std::string(call) + " after Finalize");
  if (!run_) fail(ErrorKind::order, std::string(call) + " before the case was read (ReadDatbox)");
}

void Session::write_echo(std::string_view call) {
  require_case(call);
  const auto wanted = [&](const fs::path& path) {
    const std::string p = path.generic_string();
    if (call == "WriteBodies") return p == "OUTBOX/BODIES.OUT";
    if (call == "WriteModels") return p == "OUTBOX/MODELS.OUT";
    if (call == "WriteBehaviours") return p == "OUTBOX/BULK_BEHAV.OUT" || p == "OUTBOX/TACT_BEHAV.OUT";
    if (call == "WriteDrivenDof")  // DRV_DOF.OUT and the evolution files LMGC90 rewrites
      return p.rfind("OUTBOX/", 0) == 0 && p != "OUTBOX/BODIES.OUT" && p != "OUTBOX/BULK_BEHAV.OUT" &&
             p != "OUTBOX/TACT_BEHAV.OUT" && p != "OUTBOX/MODELS.OUT";
    return false;
  };
  for (const auto& file : run_->echo_files()) {
    if (!wanted(file.relative_path)) continue;
    std::string error;
    if (!grammar::write_file_whole(case_dir_ / file.relative_path, file.content, error))
      fail(ErrorKind::output, std::string(call) + ": " + error);
  }
}

void Session::compute_mass() {
  require_case("ComputeMass");  // masses are computed when the case is read
  mass_computed_ = true;
}

// The step ---------------------------------------------------------------------------------------

Session::Run& Session::running(std::string_view call) {
  require_case(call);
  if (!run_->stopped.empty())
    fail(ErrorKind::order, std::string(call) + ": the run stopped: " + run_->stopped);
  return *run_;
}

void Session::start_run() {
  Run& r = *run_;
  // A script that reads part of the case: what lmgc always reads must have been asked for.
  for (Reading needed : {Reading::behaviours, Reading::bodies, Reading::load_behaviours, Reading::ini_dof,
                         Reading::driven_dof}) {
    const bool has_file = needed != Reading::ini_dof || r.files.dof_ini;
    if (has_file && !read_[static_cast<int>(needed)])
      fail(ErrorKind::not_implemented, "IncrementStep: the script never called " + reading_name(needed) +
                                           "; lmgc runs a case with all of its DATBOX read (ReadDatbox)");
  }
  if (r.files.tact_behav && !r.files.tact_behav->laws.empty() && !read_[static_cast<int>(Reading::tactors)])
    fail(ErrorKind::not_implemented,
         "IncrementStep: the script never called LoadTactors; lmgc runs a case "
         "with its contactors loaded (ReadDatbox)");
  options_.nlgs.quick_scramble = r.dimension() == 2 ? quick_scramble_2d_ : quick_scramble_3d_;
  if (!r.start(options_, read_[static_cast<int>(Reading::ini_vloc_rloc)]))
    fail(ErrorKind::data, r.summary.error);
  fs::create_directories(case_dir_ / "OUTBOX");
  run::RunOptions logged = options_;
  logged.quiet = true;  // no progress line: the script's loop length is its own
  r.log = std::make_unique<solver::StepLog>(case_dir_ / "OUTBOX", logged);
  if (!r.log->good()) fail(ErrorKind::output, r.log->error());
}

void Session::stage(std::string_view name) {
  const std::optional<Stage> s = stage_of(name);
  if (!s) fail(ErrorKind::value, "'" + std::string(name) + "' is not a stage of the step");
  Run& r = running(name);
  // ComputeBulk computes the element stiffnesses and internal forces: lmgc's linear bodies keep
  // their stiffness and compute the forces in ComputeFreeVelocity, so the call may come before the
  // time loop (as LMGC90's linear scripts make it) and more than once in a step; it tells that the
  // stiffness exists (Rayleigh damping's βK needs it) and, in a step, computes the large-strain
  // bodies' forces and tangents at their iterate.
  // A Newton iteration (LMGC90's loop of ComputeBulk ... ComputeDof inside a step) starts again when
  // ComputeBulk or ComputeFreeVelocity comes after the step's ComputeDof: the iteration's stages may
  // then run once more; each iteration starts from the velocity the previous one ended with.
  constexpr std::uint32_t kIteration =
      bit(Stage::compute_bulk) | bit(Stage::compute_free_velocity) | bit(Stage::select_prox_tactors) |
      bit(Stage::recup_rloc) | bit(Stage::ex_solver) | bit(Stage::stock_rloc) | bit(Stage::compute_dof);
  if ((*s == Stage::compute_bulk || *s == Stage::compute_free_velocity) && r.in_step &&
      (r.done & bit(Stage::compute_dof)) && !(r.done & bit(Stage::update_tact_behav)))
    r.done &= ~kIteration;
  if (*s == Stage::compute_bulk) {
    bulk_computed_ = true;
    if (!r.in_step) return;
    if (!(r.done & bit(Stage::increment_step))) fail(ErrorKind::order, "ComputeBulk before IncrementStep");
    r.done |= bit(Stage::compute_bulk);
    r.compute_bulk();
    report_inverted(r);
    return;
  }
  // A case without contact laws has nothing for the contact stages to do: a script may leave them
  // out (LMGC90's deformable scripts without contact do); the bodies then end at their free velocity.
  if (r.in_step && !has_contact_laws()) {
    if (*s == Stage::compute_dof && (r.done & bit(Stage::compute_free_velocity)) &&
        !(r.done & bit(Stage::ex_solver))) {
      r.skip_contacts();
      r.result = NlgsResult{};
      r.result.converged = true;  // nothing to solve
      r.done |= bit(Stage::select_prox_tactors) | bit(Stage::recup_rloc) | bit(Stage::ex_solver);
    }
    if (*s == Stage::update_step) r.done |= bit(Stage::stock_rloc);
  }
  // StockRloc again after the Newton loop (the scripts store the converged reactions once more
  // before UpdateStep): it keeps what the last one kept.
  if (*s == Stage::stock_rloc && r.in_step && (r.done & bit(Stage::stock_rloc))) return;
  const StageRule& rule = kStageRules[static_cast<std::size_t>(*s)];
  if (*s == Stage::increment_step) {
    if (r.in_step)
      fail(ErrorKind::order, "IncrementStep before UpdateStep ended step " + std::to_string(r.step()) +
                                 " (missing: " + names_of(kStageRules[Stage::update_step].needs & ~r.done) +
                                 ")");
    if (session_options_.max_steps >= 0 && steps_done_ >= session_options_.max_steps) {
      end_run_files();
      write_last_dof();
      write_last_vloc_rloc();
      write_last_gpv();
      fail(ErrorKind::step_limit, "--max-steps " + std::to_string(session_options_.max_steps) + " reached");
    }
    if (!r.started) start_run();
    r.time_begin = r.time();
    if (pending_time_step_ > 0.0) {  // the step NewtonRaphson_ComputeTimeStep chose
      options_.dt = pending_time_step_;
      r.set_time_step(pending_time_step_);
      pending_time_step_ = 0.0;
    }
    r.in_step = true;
    r.inverted_reported = false;
    r.done = 0;
    r.imposed.clear();
    r.step_start = std::chrono::steady_clock::now();
  } else {
    if (!r.in_step) fail(ErrorKind::order, std::string(name) + " before IncrementStep");
    if (r.done & bit(*s))
      fail(ErrorKind::order, std::string(name) + " twice in step " + std::to_string(r.step()));
    if ((rule.needs & r.done) != rule.needs)
      fail(ErrorKind::order, std::string(name) + " before " + names_of(rule.needs & ~r.done) + " in step " +
                                 std::to_string(r.step()));
    for (int later = 0; later < stage_count; ++later)
      if ((r.done & bit(static_cast<Stage>(later))) &&
          (kStageRules[static_cast<std::size_t>(later)].needs & bit(*s)))
        fail(ErrorKind::order, std::string(name) + " after " +
                                   std::string(kStageRules[static_cast<std::size_t>(later)].name) +
                                   ", which needs it, in step " + std::to_string(r.step()));
  }
  if (*s == Stage::update_step && r.keeps_law_state() && !(r.done & bit(Stage::update_tact_behav)))
    fail(ErrorKind::not_implemented,
         "UpdateStep without UpdateTactBehav: lmgc updates the laws' internal variables at the end of "
         "ExSolver, "
         "as UpdateTactBehav does; a step that leaves them is not run");
  r.run_stage(name, options_.nlgs);
  r.done |= bit(*s);
  if (*s == Stage::compute_free_velocity || *s == Stage::compute_dof) report_inverted(r);
  if (*s == Stage::compute_free_velocity)
    for (const auto& [body, dof, value] : r.imposed) r.impose_velocity(body, dof, value, true);
  if (*s == Stage::update_step) {
    r.in_step = false;
    ++steps_done_;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - r.step_start).count();
    if (const std::string where = r.non_finite(); !where.empty()) {
      r.stopped = "the state is not finite after step " + std::to_string(r.step()) + ": " + where;
      r.summary.fail(solver::RunFailure::non_finite, r.stopped);
      fail(ErrorKind::non_finite, r.stopped + "; no output of this step is written, and no .LAST");
    }
    r.log->record(r.step(), r.time(), r.contacts(), r.result, r.kinetic_energy(), seconds, r.summary);
    if (!r.log->good()) {
      r.stopped = r.log->error();
      fail(ErrorKind::output, r.stopped);
    }
  }
}

void Session::abandon_step(Run& r) {
  r.restore_step_begin();
  r.in_step = false;
}

void Session::report_inverted(Run& r) {
  if (r.inverted_reported) return;
  const std::string where = r.inverted();
  if (where.empty()) return;
  r.inverted_reported = true;
  const std::string what =
      "step " + std::to_string(r.step()) + " (t = " + std::to_string(r.time()) + "): " + where;
  if (!newton_active_) {
    abandon_step(r);
    r.stopped = what;
    fail(ErrorKind::non_finite,
         what +
             "; the step cannot be completed (no Newton loop to redo it with a smaller time "
             "step); no output of this step is written");
  }
  warn(what + ": the Newton loop of this step diverges (NewtonRaphson_CheckConvergence returns 2)");
}

void Session::set_newton_parameter(std::string_view name, double value) {
  const std::string call = "NewtonRaphson_Set" + std::string(name);
  if (!std::isfinite(value)) fail(ErrorKind::value, call + ": the value must be finite");
  const auto count = [&] {
    if (value < 1.0 || value != std::floor(value))
      fail(ErrorKind::value, call + ": the value is a count of at least 1");
    return value > 2e9 ? 2000000000 : static_cast<int>(value);
  };
  if (name == "FinalTime") {
    newton_.final_time = value;
  } else if (name == "MinTimeStep" || name == "MaxTimeStep") {
    if (!(value > 0.0)) fail(ErrorKind::value, call + ": the time step must be positive");
    (name == "MinTimeStep" ? newton_.min_step : newton_.max_step) = value;
  } else if (name == "MaxIter") {
    newton_.max_iterations = count();
  } else if (name == "GoodIter") {
    newton_.good_iterations = count();
  } else if (name == "BadIter") {
    newton_.bad_iterations = count();
  } else if (name == "IncPatience") {
    newton_.patience = count();
  } else {
    fail(ErrorKind::value, "unknown Newton-Raphson parameter '" + std::string(name) + "'");
  }
}

void Session::newton_initialize(double tolerance) {
  Run& r = running("NewtonRaphson_Initialize");
  if (!r.in_step) fail(ErrorKind::order, "NewtonRaphson_Initialize outside a step (after IncrementStep)");
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    fail(ErrorKind::value, "NewtonRaphson_Initialize: the tolerance must be a positive finite number");
  newton_.initialize(tolerance);
  newton_active_ = true;
}

int Session::newton_check_convergence(double norm) {
  Run& r = running("NewtonRaphson_CheckConvergence");
  if (!r.in_step) fail(ErrorKind::order, "NewtonRaphson_CheckConvergence outside a step");
  if (!newton_active_)
    fail(ErrorKind::order, "NewtonRaphson_CheckConvergence before NewtonRaphson_Initialize");
  // An inverted element: no iterate of this step can be evaluated; LMGC90's loop would run to its
  // last iteration on non-finite norms and then redo the step: lmgc ends the loop at once.
  if (!r.inverted().empty()) {
    newton_.iterations = newton_.max_iterations;
    return NewtonRaphson::diverged;
  }
  return newton_.check(norm);
}

int Session::newton_compute_time_step() {
  Run& r = running("NewtonRaphson_ComputeTimeStep");
  if (!r.in_step || !(r.done & bit(Stage::compute_dof)))
    fail(ErrorKind::order, "NewtonRaphson_ComputeTimeStep before the step's ComputeDof");
  if (!newton_active_)
    fail(ErrorKind::order, "NewtonRaphson_ComputeTimeStep before NewtonRaphson_Initialize");
  const double h = options_.dt;
  const bool converged = newton_.iterations < newton_.max_iterations;
  NewtonRaphson::TimeStep next = newton_.compute(r.time(), h, r.step());
  if (!converged && next.state == NewtonRaphson::stop && next.final_time_reached) {
    // LMGC90 would accept this unconverged last step (its cut to the final time leaves no step to
    // redo): lmgc redoes it from the step's beginning with h/√2, as any other failed step.
    warn("step " + std::to_string(r.step()) +
         ": the Newton loop did not converge on the step that reaches the final time; lmgc redoes it with "
         "a smaller time step where LMGC90 would keep it");
    next.h = h / std::sqrt(2.0);
    next.state = next.h < newton_.min_step ? NewtonRaphson::stop : NewtonRaphson::redo;
    next.final_time_reached = false;
  }
  if (!converged && next.state == NewtonRaphson::stop) {
    const std::string what =
        "step " + std::to_string(r.step()) + " (t = " + std::to_string(r.time()) +
        "): the Newton loop did not converge in " + std::to_string(newton_.max_iterations) +
        " iterations and the time step cannot be cut below NewtonRaphson_SetMinTimeStep (" +
        std::to_string(newton_.min_step) + ")";
    abandon_step(r);
    write_last_dof();
    write_last_gpv();
    r.stopped = what;
    r.summary.fail(solver::RunFailure::not_converged, what);
    fail(ErrorKind::newton_diverged, what + "; DOF.LAST and GPV.LAST hold the last converged step");
  }
  if (next.state == NewtonRaphson::stop && !next.final_time_reached)
    warn("step " + std::to_string(r.step()) +
         ": the next time step would be below NewtonRaphson_SetMinTimeStep: "
         "the run stops after this step, as LMGC90's does");
  if (next.state == NewtonRaphson::redo) abandon_step(r);
  if (next.h > 0.0 && next.h != h) pending_time_step_ = next.h;
  return next.state;
}

double Session::residue_norm() {
  Run& r = running("mecaMAILx_ComputeResidueNorm");
  if (!r.in_step || !(r.done & bit(Stage::compute_dof)))
    fail(ErrorKind::order, "mecaMAILx_ComputeResidueNorm before the iteration's ComputeDof");
  return r.residue_norm();
}

void Session::recup_rloc(std::optional<double> tolerance) {
  if (tolerance && !(*tolerance >= 0.0))
    fail(ErrorKind::value, "RecupRloc: the tolerance must be a non-negative number");
  if (tolerance && run_ && run_->has_plplx() && !warned_recup_by_position_) {
    warned_recup_by_position_ = true;
    warn(
        "RecupRloc(tol): LMGC90 matches PLPLx reactions by position within tol; lmgc matches them by "
        "contactor (the NLGS may start from another guess; the problem solved is the same)");
  }
  stage("RecupRloc");
}

void Session::select_prox_tactors(int detection_every, int use_external, int reset) {
  if (detection_every != 1)
    fail(ErrorKind::not_implemented, "SelectProxTactors(freq_detec=" + std::to_string(detection_every) +
                                         "): lmgc detects at every step (freq_detec=1)");
  if (use_external != 0)
    fail(ErrorKind::not_implemented, "SelectProxTactors(useExt=1): no external detection");
  if (reset != 0) fail(ErrorKind::not_implemented, "SelectProxTactors(reset=1) is not offered by lmgc");
  stage("SelectProxTactors");
}

void Session::ex_solver(const std::string& storage, const std::string& norm, double tolerance, double relax,
                        long gs_it1, long gs_it2) {
  solver::NlgsOptions o = options_.nlgs;
  if (!run::parse_storage(storage, o.storage))
    fail(ErrorKind::value,
         "ExSolver: unknown solver type '" + storage + "' (Stored_Delassus_Loops or Exchange_Local_Global)");
  if (!run::parse_norm(norm, o.norm)) {
    // LMGC90's 3D NLGS keeps 'Quad ' for a norm it does not know (set_nlgs_parameter).
    if (dimension_ != 3)
      fail(ErrorKind::value, "ExSolver: unknown norm '" + norm + "' (Quad, QuaN, Maxm, QM/16)");
    o.norm = solver::NlgsNorm::quad;
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    fail(ErrorKind::value, "ExSolver: the tolerance must be a positive finite number");
  if (!(relax > 0.0 && relax <= 2.0)) fail(ErrorKind::value, "ExSolver: relax is in (0, 2]");
  if (gs_it1 < 1 || gs_it2 < 1 || gs_it1 > 1'000'000'000 || gs_it2 > 1'000'000'000)
    fail(ErrorKind::value, "ExSolver: gs_it1 and gs_it2 are at least 1");
  o.tolerance = tolerance;
  o.relax = relax;
  o.gs_it1 = static_cast<int>(gs_it1);
  o.gs_it2 = static_cast<int>(gs_it2);
  const solver::NlgsOptions previous = options_.nlgs;
  options_.nlgs = o;
  try {
    stage("ExSolver");
  } catch (...) {
    options_.nlgs = previous;
    throw;
  }
}

// Outputs ----------------------------------------------------------------------------------------

namespace {
void write_whole(const fs::path& path, const std::string& text, std::string_view call) {
  std::string error;
  if (!grammar::write_file_whole(path, text, error))
    fail(ErrorKind::output, std::string(call) + ": " + error);
}
}  // namespace

void Session::write_out_dof(long every) {
  if (every < 1) fail(ErrorKind::value, "WriteOutDof: nsteps is at least 1");
  Run& r = running("WriteOutDof");
  if (!r.started || r.step() % every != 0) return;
  write_whole(case_dir_ / "OUTBOX" / ("DOF.OUT." + std::to_string(++r.dof_written)), r.dof_text(),
              "WriteOutDof");
}

void Session::write_out_vloc_rloc(long every) {
  if (every < 1) fail(ErrorKind::value, "WriteOutVlocRloc: nsteps is at least 1");
  Run& r = running("WriteOutVlocRloc");
  if (!r.started || r.step() % every != 0) return;
  write_whole(case_dir_ / "OUTBOX" / ("Vloc_Rloc.OUT." + std::to_string(++r.vloc_rloc_written)),
              r.vloc_rloc_text(), "WriteOutVlocRloc");
}

void Session::write_last_dof() {
  Run& r = running("WriteLastDof");
  if (!r.started) return;
  fs::create_directories(case_dir_ / "OUTBOX");
  write_whole(case_dir_ / "OUTBOX" / "DOF.LAST", r.dof_text(), "WriteLastDof");
  // EXACT_STATE.LAST holds rigid bodies and interactions only: not written beside deformable bodies.
  if (!r.has_meshes())
    write_whole(case_dir_ / "OUTBOX" / "EXACT_STATE.LAST", r.exact_state_text(), "WriteLastDof");
}

void Session::write_last_vloc_rloc() {
  Run& r = running("WriteLastVlocRloc");
  if (!r.started) return;
  write_whole(case_dir_ / "OUTBOX" / "Vloc_Rloc.LAST", r.vloc_rloc_text(), "WriteLastVlocRloc");
}

void Session::write_out_gpv(long every) {
  if (every < 1) fail(ErrorKind::value, "WriteOutGPV: nsteps is at least 1");
  Run& r = running("WriteOutGPV");
  if (!r.started || !r.has_meshes() || r.step() % every != 0) return;
  write_whole(case_dir_ / "OUTBOX" / ("GPV.OUT." + std::to_string(++r.gpv_written)), r.gpv_text(),
              "WriteOutGPV");
}

void Session::write_last_gpv() {
  Run& r = running("WriteLastGPV");
  if (!r.started || !r.has_meshes()) return;
  write_whole(case_dir_ / "OUTBOX" / "GPV.LAST", r.gpv_text(), "WriteLastGPV");
}

bool Session::has_deformable_bodies() const {
  return run_ && run_->has_meshes();
}

bool Session::has_contact_laws() const {
  return run_ && run_->files.tact_behav && !run_->files.tact_behav->laws.empty();
}

void Session::set_rayleigh_damping(double alpha, double beta) {
  if (!std::isfinite(alpha) || !std::isfinite(beta) || alpha < 0.0 || beta < 0.0)
    fail(ErrorKind::value, "mecaMAILx_ComputeRayleighDamping: alpha and beta are finite and non-negative");
  require_case("mecaMAILx_ComputeRayleighDamping");
  // LMGC90 builds C from the element masses and stiffnesses computed so far (mailx-2d.md §4.2):
  // before ComputeMass the mass part is 0, before the first ComputeBulk the stiffness part.
  const double a = mass_computed_ ? alpha : 0.0, b = bulk_computed_ ? beta : 0.0;
  if ((a != alpha || b != beta) && (alpha != 0.0 || beta != 0.0))
    warn("mecaMAILx_ComputeRayleighDamping before " +
         std::string(!mass_computed_ ? "ComputeMass" : "the first ComputeBulk") +
         ": as in LMGC90, the damping built is " + std::to_string(a) + " M + " + std::to_string(b) + " K");
  run_->set_rayleigh(a, b);
}

void Session::open_display() {
  Run& r = running("OpenDisplayFiles");
  r.display_open = true;
}

void Session::write_display(long every) {
  if (every < 1) fail(ErrorKind::value, "WriteDisplayFiles: freq is at least 1");
  Run& r = running("WriteDisplayFiles");
  if (!r.display_open) fail(ErrorKind::order, "WriteDisplayFiles before OpenDisplayFiles");
  if (!r.started || r.step() % every != 0) return;
  std::string error;
  if (!r.write_display(error)) fail(ErrorKind::output, "WriteDisplayFiles: " + error);
}

void Session::close_display() {
  Run& r = running("CloseDisplayFiles");
  r.display_open = false;
}

void Session::open_postpro() {
  Run& r = running("OpenPostproFiles");
  if (r.postpro_open) fail(ErrorKind::order, "OpenPostproFiles twice");
  std::string error;
  if (r.files.postpro) write_whole(case_dir_ / "POSTPRO" / "POSTPRO.OUT", "", "OpenPostproFiles");
  if (!r.open_postpro(error)) fail(ErrorKind::output, "OpenPostproFiles: " + error);
  r.postpro_open = true;
}

void Session::write_postpro() {
  Run& r = running("WritePostproFiles");
  if (!r.postpro_open) fail(ErrorKind::order, "WritePostproFiles before OpenPostproFiles");
  if (!r.started || r.in_step) fail(ErrorKind::order, "WritePostproFiles inside a step (after UpdateStep)");
  std::string error;
  if (!r.write_postpro(error)) {
    r.stopped = error;
    fail(ErrorKind::output, "WritePostproFiles: " + error);
  }
}

void Session::close_postpro() {
  require_case("ClosePostproFiles");
  Run& r = *run_;
  if (!r.postpro_open) return;
  r.postpro_open = false;
  std::string error;
  if (!r.close_postpro(error)) fail(ErrorKind::output, "ClosePostproFiles: " + error);
}

void Session::end_run_files() {
  if (!run_) return;
  Run& r = *run_;
  std::string error;
  if (r.postpro_open) {
    r.postpro_open = false;
    r.close_postpro(error);
  }
  if (r.log) {
    r.log->close();
    r.log.reset();
  }
}

void Session::finalize() {
  if (finalized_) return;
  if (run_ && run_->started && !session_options_.quiet)
    std::fprintf(stderr,
                 "lmgc: %ld steps to t=%.6g; %ld not converged within gs_it1*gs_it2; worst natural-map "
                 "residual/|q| %.3e\n",
                 run_->summary.steps_done, run_->time(), run_->summary.steps_not_converged,
                 run_->summary.worst_residual);
  // Under lmgc-run --max-steps, a script that ends by itself ends with its .LAST files too.
  if (session_options_.max_steps >= 0 && run_ && run_->started && run_->stopped.empty()) {
    write_last_dof();
    write_last_vloc_rloc();
    write_last_gpv();
  }
  end_run_files();
  finalized_ = true;
}

// State ------------------------------------------------------------------------------------------

double Session::time() const {
  return run_ ? run_->time() : 0.0;
}

long Session::step() const {
  return run_ ? run_->step() : 0;
}

namespace {
std::size_t body_index(const Session::Run& r, long body, std::string_view call) {
  if (body < 1 || static_cast<std::size_t>(body) > r.bodies())
    throw Error(ErrorKind::index, std::string(call) + ": body " + std::to_string(body) + " is not in 1.." +
                                      std::to_string(r.bodies()));
  return static_cast<std::size_t>(body - 1);
}
std::string rbdy(int dimension) {
  return "RBDY" + std::to_string(dimension);
}
}  // namespace

std::size_t Session::body_count(int dimension) const {
  if (!run_ || run_->dimension() != dimension) return 0;
  return run_->bodies();
}

std::vector<double> Session::body_vector(int dimension, std::string_view name, long body) const {
  const std::string call = rbdy(dimension) + "_GetBodyVector";
  require_case(call);
  if (run_->dimension() != dimension)
    fail(ErrorKind::order, call + " in a " + rbdy(run_->dimension()) + " case");
  const BodyVectorName& v = body_vector_name(name, false, dimension);
  const std::size_t i = body_index(*run_, body, call);
  std::vector<double> out(static_cast<std::size_t>(run_->size_of(v.vector)));
  run_->get_into(v.vector, i, out.data());
  return out;
}

std::vector<double> Session::all_body_vectors(int dimension, std::string_view name, std::size_t& size) const {
  const std::string call = rbdy(dimension) + "_GetAllBodyVector";
  require_case(call);
  if (run_->dimension() != dimension)
    fail(ErrorKind::order, call + " in a " + rbdy(run_->dimension()) + " case");
  const BodyVectorName& v = body_vector_name(name, false, dimension);
  size = static_cast<std::size_t>(run_->size_of(v.vector));
  std::vector<double> all(size * run_->bodies());
  for (std::size_t i = 0; i < run_->bodies(); ++i) run_->get_into(v.vector, i, all.data() + i * size);
  return all;
}

void Session::put_body_vector(int dimension, std::string_view name, long body,
                              std::span<const double> value) {
  const std::string call = rbdy(dimension) + "_PutBodyVector";
  require_case(call);
  if (run_->dimension() != dimension)
    fail(ErrorKind::order, call + " in a " + rbdy(run_->dimension()) + " case");
  const BodyVectorName& v = body_vector_name(name, true, dimension);
  const std::size_t i = body_index(*run_, body, call);
  const bool position =
      v.vector == BodyVector::coor0 || v.vector == BodyVector::coor || v.vector == BodyVector::coorb;
  const std::size_t expected = position ? 3u : static_cast<std::size_t>(run_->dofs());
  if (value.size() != expected)
    fail(ErrorKind::value, call + ": '" + std::string(name) + "' has " + std::to_string(expected) +
                               " values, not " + std::to_string(value.size()));
  for (double x : value)
    if (!std::isfinite(x)) fail(ErrorKind::value, call + ": the values must be finite");
  run_->put(v.vector, i, value);
}

void Session::set_vlocy_driven_dof(int dimension, long body, int dof, double value) {
  const std::string call = rbdy(dimension) + "_SetVlocyDrivenDof";
  Run& r = running(call);
  const std::size_t i = body_index(r, body, call);
  if (dof < 1 || dof > r.dofs())
    fail(ErrorKind::index,
         call + ": dof " + std::to_string(dof) + " is not in 1.." + std::to_string(r.dofs()));
  if (!r.vlocy_driven(i, dof - 1))
    fail(ErrorKind::value, call + ": dof " + std::to_string(dof) + " of body " + std::to_string(body) +
                               " has no imposed velocity in DRV_DOF.DAT");
  if (!std::isfinite(value)) fail(ErrorKind::value, call + ": the velocity must be finite");
  if (!r.in_step) fail(ErrorKind::order, call + " outside a step (between IncrementStep and ExSolver)");
  if (r.done & bit(Stage::ex_solver)) fail(ErrorKind::order, call + " after ExSolver");
  const bool after = (r.done & bit(Stage::compute_free_velocity)) != 0;
  if (after)
    r.impose_velocity(i, dof - 1, value, true);
  else
    r.imposed.emplace_back(i, dof - 1, value);
}

double Session::body_mass(int dimension, long body) const {
  const std::string call = rbdy(dimension) + "_GetBodyMass";
  require_case(call);
  return run_->mass(body_index(*run_, body, call));
}

bool Session::body_visible(int dimension, long body) const {
  const std::string call = rbdy(dimension) + "_IsVisible";
  require_case(call);
  return run_->visible(body_index(*run_, body, call));
}

Session::Interactions Session::interactions() const {
  require_case("getInteractions");
  Interactions out;
  if (!run_->started) return out;
  const int d = run_->dimension();
  for (const grammar::VlocRlocInteraction& i : run_->vloc_rloc().interactions) {
    out.module.push_back(i.type.value);
    out.number.push_back(i.number.value);
    // The data line's fields are named by the module's title line, in order (cdbdy numbr cdtac
    // numbr behav anbdy numbr antac numbr sttus ...); interaction_catalogue.hpp has the formats.
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(i.type.value, i.xxl);
    std::vector<std::string> titles;
    for (std::size_t k = 0, e; k < i.title.size(); k = e) {
      k = i.title.find_first_not_of(' ', k);
      if (k == std::string::npos) break;
      e = i.title.find(' ', k);
      if (e == std::string::npos) e = i.title.size();
      titles.push_back(i.title.substr(k, e - k));
    }
    std::string words[5];  // cdbdy cdtac behav anbdy antac / sttus
    // The 'numbr' after cdbdy, cdtac, anbdy and antac (the one after a polygon's 'vertx' is its vertex).
    std::int64_t numbers[4] = {};
    std::string status, previous_title;
    if (kind) {
      std::size_t w = 0, n = 0, t = 0;
      for (const grammar::DataItem& item : grammar::data_items(kind->data_format)) {
        if (item.kind == 'X') continue;
        const std::string title = t < titles.size() ? titles[t] : std::string();
        ++t;
        if (item.kind == 'A') {
          const std::string value = w < i.words.size() ? i.words[w].value : std::string();
          ++w;
          if (title == "cdbdy") words[0] = value;
          if (title == "cdtac") words[1] = value;
          if (title == "behav") words[2] = value;
          if (title == "anbdy") words[3] = value;
          if (title == "antac") words[4] = value;
          if (title == "sttus") status = value;
        } else {
          const std::int64_t value = n < i.integers.size() ? i.integers[n].value : 0;
          ++n;
          if (title == "numbr") {
            if (previous_title == "cdbdy") numbers[0] = value;
            if (previous_title == "cdtac") numbers[1] = value;
            if (previous_title == "anbdy") numbers[2] = value;
            if (previous_title == "antac") numbers[3] = value;
          }
        }
        previous_title = title;
      }
    }
    out.candidate_body_type.push_back(words[0]);
    out.antagonist_body_type.push_back(words[3]);
    out.candidate_body.push_back(numbers[0]);
    out.candidate_type.push_back(words[1]);
    out.candidate_contactor.push_back(numbers[1]);
    out.law.push_back(words[2]);
    out.antagonist_body.push_back(numbers[2]);
    out.antagonist_type.push_back(words[4]);
    out.antagonist_contactor.push_back(numbers[3]);
    out.status.push_back(status);
    // Labelled values; NaN for a value the module does not write.
    const auto value = [&](std::string_view label) {
      for (const grammar::VlocRlocVector& v : i.vectors)
        for (std::size_t k = 0; k < v.labels.size() && k < v.values.size(); ++k)
          if (v.labels[k] == label) return v.values[k].value;
      return std::nan("");
    };
    const auto components = [&](std::vector<double>& into, std::initializer_list<std::string_view> labels) {
      int k = 0;
      for (std::string_view label : labels)
        if (k++ < d) into.push_back(value(label));
    };
    // Local components in (t, n, s) order, as chipy's getInteractions gives them.
    components(out.rl, {"rlt/H", "rln/H", "rls/H"});
    components(out.vl, {"vlt =", "vln =", "vls ="});
    const double gap = value("gapTT");
    out.gap.push_back(std::isnan(gap) ? value("gTT =") : gap);
    components(out.point, {"coo1=", "coo2=", "coo3="});
    components(out.frame, {"t(1)=", "t(2)=", "t(3)="});
    components(out.frame, {"n(1)=", "n(2)=", "n(3)="});
    if (d == 2) {
      // 2D files write n only; t = (n_y, −n_x) (docs/lmgc90-facts/numerics.md §2).
      double* f = out.frame.data() + out.frame.size() - 4;
      f[0] = f[3];
      f[1] = -f[2];
    }
    if (d == 3) components(out.frame, {"s(1)=", "s(2)=", "s(3)="});
  }
  return out;
}

std::vector<std::pair<long, long>> Session::contactors(std::string_view type) const {
  require_case(std::string(type) + "_GetNb" + std::string(type));
  std::vector<std::pair<long, long>> out;
  if (!run_->files.bodies) return out;
  const auto& bodies = run_->files.bodies->bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (std::size_t t = 0; t < bodies[b].contactors.size(); ++t)
      if (bodies[b].contactors[t].type.value == type)
        out.emplace_back(static_cast<long>(b + 1), static_cast<long>(t + 1));
  return out;
}

}  // namespace lmgc::chipy
