#pragma once
// ParaView output of a rigid 3D run: per display step, DISPLAY/bodies_<k>.vtu (one vertex per
// SPHER/SPHEb contactor, to be drawn with a sphere glyph scaled by its `radius` point array, and
// one hexahedron per PLANx box) and DISPLAY/contacts_<k>.vtu (one vertex per interaction: normal,
// reaction, gap, status...), collected by DISPLAY/lmgc90.pvd. The 3D twin of display_2d.
#include <filesystem>
#include <string>
#include <vector>

#include "solver/model/run_state_3d.hpp"
#include "solver/model/scene_3d.hpp"

namespace lmgc::solver {

class DisplayWriter3D {
 public:
  explicit DisplayWriter3D(std::filesystem::path display_dir) : dir_(std::move(display_dir)) {}
  // Writes one display step; returns false with `error` set when a file cannot be written.
  bool write(const Scene3D& scene, const RunState3D& state, std::string& error);
  std::size_t count() const { return times_.size(); }

 private:
  std::filesystem::path dir_;
  std::vector<double> times_;
};

// The two .vtu documents of one step (exposed for tests).
std::string bodies_vtu_3d(const Scene3D& scene);
std::string contacts_vtu_3d(const Scene3D& scene, const RunState3D& state);

}  // namespace lmgc::solver
