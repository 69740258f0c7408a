#pragma once
// ParaView output of a rigid 2D run: per display step, DISPLAY/bodies_<k>.vtu (every contactor
// outline as a polygon cell, with its body's fields) and DISPLAY/contacts_<k>.vtu (one vertex per
// interaction: normal, reaction, status...), collected by DISPLAY/lmgc90.pvd.
#include <filesystem>
#include <string>
#include <vector>

#include "solver/integrator/step_2d.hpp"

namespace lmgc::solver {

class DisplayWriter2D {
 public:
  explicit DisplayWriter2D(std::filesystem::path display_dir) : dir_(std::move(display_dir)) {}
  // Writes one display step; returns false with `error` set when a file cannot be written.
  bool write(const Scene2D& scene, const RunState2D& state, std::string& error);
  std::size_t count() const { return times_.size(); }

 private:
  std::filesystem::path dir_;
  std::vector<double> times_;
};

// The two .vtu documents of one step (exposed for tests).
std::string bodies_vtu_2d(const Scene2D& scene);
std::string contacts_vtu_2d(const Scene2D& scene, const RunState2D& state);
// The deformable bodies' meshes (LMGC90's 'mecafe' block): nodes at reference + X, elements as VTK
// cells; point fields Ids, Node Id, Disp, Velocy, E and S (3 × 3 tensors: the mean over the Gauss
// points of the elements around the node), Svm (von Mises of S), Fext; cell field Element Id.
std::string meshes_vtu_2d(const Scene2D& scene);

}  // namespace lmgc::solver
