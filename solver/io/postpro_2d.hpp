#pragma once
// POSTPRO time series of a rigid 2D run, in LMGC90's file names and line formats.
// docs/lmgc90-facts/state-and-outputs.md §4; docs/lmgc90-facts/rigid-2d.md §8.
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "solver/integrator/step_2d.hpp"

namespace lmgc::solver {

enum class PostproKind2D {
  solver_informations,
  violation_evolution,
  kinetic_energy,
  dissipated_energy,
  body_tracking,
  torque_evolution,
  coordination_number,
  average_velocity_evolution,
  new_meca_sets,       // NEW MECAx SETS: node sets of deformable bodies, for the two below
  dep_evolution,       // Dep EVOLUTION: mean displacement and velocity of each set's nodes
  fint_evolution,      // Fint EVOLUTION: summed reaction, internal, inertial, external forces, residue
  dry_contact_nature,  // DRY CONTACT NATURE: hovering, sticking, sliding contacts of the last check
  wet_contact_nature,  // WET CONTACT NATURE: wet sticking, sliding, not touching contacts
};

struct PostproCommand2D {
  PostproKind2D kind;
  int period = 1;                    // the command runs when Nstep mod period == 0
  std::vector<std::int64_t> bodies;  // BODY TRACKING, TORQUE EVOLUTION: body ranks (1-based)
  std::string color;                 // AVERAGE VELOCITY EVOLUTION
  // NEW MECAx SETS: per set, its (mecaMAILx body, node) entries, both 1-based (a node listed twice
  // counts twice). docs/lmgc90-facts/mailx-2d.md §8.
  std::vector<std::vector<std::pair<std::int64_t, std::int64_t>>> sets;
};

// The command of a POSTPRO.DAT name, or false when the 2D post-processor does not provide it.
bool postpro_kind_of(std::string_view name, PostproKind2D& kind);

// When the POSTPRO files are next flushed: at most kSeconds apart, so that an interrupted run keeps
// nearly all it wrote without a write system call per line and step.
class PostproFlushClock {
 public:
  static constexpr double kSeconds = 0.25;
  bool due() {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_).count() < kSeconds) return false;
    last_ = now;
    return true;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

class Postpro2D {
 public:
  // Creates POSTPRO/ and truncates every file the commands write (and POSTPRO.OUT).
  bool open(const std::filesystem::path& postpro_dir, std::vector<PostproCommand2D> commands,
            std::string& error);
  // One line per active command, after the step (end-of-step state and the step's solver result).
  // False, with `error`, when a file could not be written (disk full, ...): the run stops then.
  bool write(const Scene2D& scene, const RunState2D& state, const NlgsResult& solver, std::string& error);
  // Flushes and closes every file; false, with `error`, when the last lines could not be written.
  bool close(std::string& error);

 private:
  struct Stream {
    std::size_t command;
    std::int64_t body = 0;
    std::unique_ptr<std::ofstream> file;
    std::filesystem::path path;
  };
  bool streams_good(std::string& error) const;
  std::vector<PostproCommand2D> commands_;
  std::vector<Stream> streams_;
  using NodeSet = std::vector<std::pair<std::int64_t, std::int64_t>>;
  std::vector<NodeSet> sets_;         // the last NEW MECAx SETS read
  std::vector<NodeSet> stream_sets_;  // per stream: its set (Dep, Fint EVOLUTION), else empty
  double dissipated_ = 0.0;           // cumulated dissipated energy
  double external_work_ = 0.0;        // cumulated work of reactions and external forces
  NlgsNorms last_norms_;
  std::array<std::size_t, 3> last_nature_{};  // hover, stick, slide: kept like the norms              // kept
                                              // when a step has no contact (as LMGC90 does)
  PostproFlushClock flush_clock_;
};

// One SOLVER_INFORMATIONS.DAT row, (ES15.8,1X,I8,3(1X,ES14.7),1X,I8): time, iterations (0 without
// contacts), MeanDVoR, QuadDV, QuadDVR of the last solve with contacts, number of contacts.
std::string solver_informations_line(double time, int iterations, const NlgsNorms& norms,
                                     std::size_t contacts);

}  // namespace lmgc::solver
