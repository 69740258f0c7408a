#pragma once
// What LMGC90's chipy keeps between the calls of a command.py: the dimension, the run parameters
// its set-up calls give, the case read by ReadDatbox, the state of the step in progress and the
// open output files. Each public function is one chipy call (or a family of them) with LMGC90's
// meaning, on lmgc's solver: the stages of solver/integrator (step_stages_2d, step_stages_3d) and
// the writers of solver/io. The calls are checked as they come: order within a step, files read
// twice, body and dof indices, vector names and sizes; a call that does not fit raises an Error
// whose kind the Python module maps to an exception. python/chipy_module.cpp binds it;
// docs/chipy.md lists the calls.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "chipy/newton_raphson.hpp"
#include "run/run_options.hpp"

namespace lmgc::chipy {

enum class ErrorKind {
  order,            // a call out of sequence (RuntimeError)
  index,            // a body, dof or file index out of range (IndexError)
  value,            // an argument of the wrong value (ValueError)
  not_implemented,  // what lmgc does not do (NotImplementedError)
  data,             // the case's data are invalid or refused (RuntimeError, with the diagnostics)
  non_finite,       // the state became NaN or infinite (FloatingPointError)
  output,           // an output file could not be written (OSError)
  step_limit,       // --max-steps reached: .LAST written, the script ends (SystemExit 0)
  newton_diverged,  // the Newton loop failed at the smallest time step: .LAST of the last good step
                    // written, the script ends (SystemExit kNewtonDivergedExit)
};

// lmgc-run's exit code when the Newton loop of a step does not converge (lmgc-solve passes it on).
inline constexpr int kNewtonDivergedExit = 7;

struct Error : std::runtime_error {
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind(kind) {}
  ErrorKind kind;
};

// The DATBOX readings of chipy (ReadDatbox does them all, in this order).
enum class Reading : std::uint8_t {
  behaviours,       // ReadBehaviours: BULK_BEHAV.DAT, TACT_BEHAV.DAT
  bodies,           // ReadBodies: BODIES.DAT
  load_behaviours,  // LoadBehaviours
  ini_dof,          // ReadIniDof: DOF.INI
  driven_dof,       // ReadDrivenDof: DRV_DOF.DAT
  tactors,          // LoadTactors
  ini_vloc_rloc,    // ReadIniVlocRloc: Vloc_Rloc.INI
  count
};

// Where a session writes and what it tells: lmgc-run's options.
struct SessionOptions {
  long max_steps = -1;  // end the script after this many steps (.LAST written); -1: no limit
  bool quiet = false;   // no warnings, no summary line
};

class Session {
 public:
  Session(std::filesystem::path case_dir, SessionOptions options);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Set-up (before the first step).
  void set_dimension(int dimension, int mode);
  int dimension() const { return dimension_; }
  void set_time_step(double dt);
  void init_theta(double theta);
  void set_quick_scramble(int dimension);  // nlgs_SetWithQuickScramble / nlgs_3D_SetWithQuickScramble
  void set_diagonal_resolution();          // nlgs_3D_DiagonalResolution
  void set_periodic(std::optional<double> x_period, std::optional<double> y_period);
  // RBDY2_Set{X,Y}{min,max}Boundary: axis 'x' or 'y'.
  void set_boundary(char axis, bool maximum, double value);
  void new_rotation_scheme();
  void set_source_point(long first, double radius, double x, double y, double z, bool absolute);
  void set_cundall_iterations(int iterations);
  void ptpt3_load_network();
  void ptpt3_use_current_nonuc0(int use);
  // mecaMAILx_ComputeRayleighDamping(alpha, beta): C = αM + βK on every deformable body.
  void set_rayleigh_damping(double alpha, double beta);

  // NewtonRaphson_SetFinalTime, SetMinTimeStep, SetMaxTimeStep, SetMaxIter, SetGoodIter, SetBadIter,
  // SetIncPatience: `name` is the part after 'NewtonRaphson_Set'.
  void set_newton_parameter(std::string_view name, double value);
  // NewtonRaphson_Initialize(tol), CheckConvergence(norm) (0 converged, 1 iterate, 2 diverged),
  // ComputeTimeStep (0 go on, 1 redo the step, 2 stop), mecaMAILx_ComputeResidueNorm.
  void newton_initialize(double tolerance);
  int newton_check_convergence(double norm);
  int newton_compute_time_step();
  double residue_norm();

  // DATBOX. The first reading reads and checks the whole case (errors raise with the diagnostics).
  void read(Reading what);
  // WriteBodies, WriteBehaviours, WriteDrivenDof: the echo files LMGC90 writes.
  void write_echo(std::string_view call);
  void compute_mass();

  // One stage of the step, by its chipy name (IncrementStep ... UpdateStep, ComputeBulk,
  // UpdateTactBehav, StockRloc).
  void stage(std::string_view name);
  void recup_rloc(std::optional<double> tolerance);
  void select_prox_tactors(int detection_every, int use_external, int reset);
  void ex_solver(const std::string& storage, const std::string& norm, double tolerance, double relax,
                 long gs_it1, long gs_it2);

  // Outputs. `every`: a file when the step is a multiple of it (LMGC90's nsteps, freq).
  void write_out_dof(long every);
  void write_out_vloc_rloc(long every);
  void write_last_dof();
  void write_last_vloc_rloc();
  void write_out_gpv(long every);  // WriteOutGPV: the deformable bodies' Gauss-point values
  void write_last_gpv();
  bool has_deformable_bodies() const;
  bool has_contact_laws() const;  // TACT_BEHAV.DAT defines a law (WriteOut's Vloc_Rloc condition)
  void open_display();
  void write_display(long every);
  void close_display();
  void open_postpro();
  void write_postpro();
  void close_postpro();
  void finalize();

  // State. Bodies are numbered from 1, as in chipy.
  double time() const;
  long step() const;
  double time_step() const { return options_.dt; }
  std::size_t body_count(int dimension) const;
  std::vector<double> body_vector(int dimension, std::string_view name, long body) const;
  // Every body's vector, row after row (bodies × size).
  std::vector<double> all_body_vectors(int dimension, std::string_view name, std::size_t& size) const;
  void put_body_vector(int dimension, std::string_view name, long body, std::span<const double> value);
  void set_vlocy_driven_dof(int dimension, long body, int dof, double value);
  double body_mass(int dimension, long body) const;
  bool body_visible(int dimension, long body) const;
  // The interactions of the step as rows: the Vloc_Rloc records (module, bodies, contactors, law,
  // status, point, frame, rl, vl, gap) in LMGC90's order.
  struct Interactions {
    std::vector<std::string> module, candidate_type, antagonist_type, law, status;
    std::vector<std::string> candidate_body_type, antagonist_body_type;  // RBDY2, RBDY3, MAILx
    std::vector<std::int64_t> number, candidate_body, antagonist_body, candidate_contactor,
        antagonist_contactor;
    std::vector<double> point, frame, rl, vl, gap;  // rows of dimension, dimension², dimension, dimension, 1
  };
  Interactions interactions() const;
  // The contactors of a type (DISKx, SPHER, ...) in BODIES.DAT's order: (body, rank within the
  // body), both from 1, as LMGC90's <type>2BDYTY tables.
  std::vector<std::pair<long, long>> contactors(std::string_view type) const;

  // Steps ended (UpdateStep) by this session.
  long steps_done() const { return steps_done_; }
  const run::RunOptions& run_options() const { return options_; }

  struct Run;  // the dimension's scene, state and writers (session.cpp)

 private:
  void require_case(std::string_view call) const;
  Run& running(std::string_view call);
  void start_run();
  // An element inverted in the step's last evaluation: a warning inside a Newton loop (the loop
  // diverges and the step is redone), otherwise the run stops naming it.
  void report_inverted(Run& r);
  // The step in progress ends without UpdateStep (redone, or the run stops): back to its beginning.
  void abandon_step(Run& r);
  void end_run_files();
  void warn(const std::string& message) const;

  std::filesystem::path case_dir_;
  SessionOptions session_options_;
  run::RunOptions options_;
  int dimension_ = 0;
  int mode_ = 1;  // SetDimension's mod: 1 plane strain, 2 plane stress, 3 axisymmetric
  bool quick_scramble_2d_ = false, quick_scramble_3d_ = false;
  bool finalized_ = false;
  bool mass_computed_ = false,
       bulk_computed_ = false;  // ComputeMass, a ComputeBulk: what C can be built from
  bool read_[static_cast<int>(Reading::count)] = {};
  long steps_done_ = 0;
  mutable bool warned_recup_by_position_ = false;
  NewtonRaphson newton_;
  bool newton_active_ = false;      // the script runs a Newton loop (NewtonRaphson_Initialize was called)
  double pending_time_step_ = 0.0;  // h for the next IncrementStep, chosen by ComputeTimeStep
  std::unique_ptr<Run> run_;
};

}  // namespace lmgc::chipy
