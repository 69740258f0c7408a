#pragma once
// POSTPRO time series of a rigid 3D run, in LMGC90's file names and line formats: BODY TRACKING and
// SOLVER INFORMATIONS; the other commands of POSTPRO.DAT are skipped (no file is written for them).
// docs/lmgc90-facts/state-and-outputs.md §4 (mod_postpro_3D.f90).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "solver/io/postpro_2d.hpp"  // PostproCommand2D, PostproKind2D: the same commands in 3D
#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"
#include "solver/nlgs/nlgs_check.hpp"

namespace lmgc::solver {

class Postpro3D {
 public:
  // Creates POSTPRO/ and truncates every file the provided commands write (and POSTPRO.OUT).
  bool open(const std::filesystem::path& postpro_dir, std::vector<PostproCommand2D> commands,
            std::string& error);
  // One line per active command, after the step (end-of-step state and the step's solver result).
  // False, with `error`, when a file could not be written (disk full, ...): the run stops then.
  bool write(const Scene3D& scene, const RunState3D& state, const NlgsResult& solver, std::string& error);
  // Flushes and closes every file; false, with `error`, when the last lines could not be written.
  bool close(std::string& error);

  // True when the 3D post-processor writes this command (the others are skipped).
  static bool provides(PostproKind2D kind);

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
  NlgsNorms last_norms_;  // kept when a step has no contact (as LMGC90 does)
  PostproFlushClock flush_clock_;
};

}  // namespace lmgc::solver
