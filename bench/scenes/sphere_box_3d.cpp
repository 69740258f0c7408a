#include "bench/scenes/sphere_box_3d.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "bench/scenes/at_rest.hpp"

namespace lmgc::bench {

using Eigen::Matrix3d;
using Eigen::Vector3d;

solver::Scene3D sphere_box_3d(int spheres) {
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(spheres))));
  const double r = 0.005, spacing = 2.0 * r, width = side * spacing;
  solver::SceneBuilder3D b;
  int placed = 0;
  for (int k = 0; k < side && placed < spheres; ++k)
    for (int j = 0; j < side && placed < spheres; ++j)
      for (int i = 0; i < side && placed < spheres; ++i, ++placed)
        b.add_sphere(Vector3d(r + i * spacing, r + j * spacing, r + k * spacing),
                     r * (1.0 - 0.02 * ((i + j + k) % 3)), 2600.0);
  const double thick = 0.01, half = 0.5 * width + thick;
  b.add_fixed_plane(Vector3d(0.5 * width, 0.5 * width, -thick), Matrix3d::Identity(),
                    Vector3d(half, half, thick), "WALLx");
  // Walls: PLANx frames whose third axis points into the box.
  const auto wall = [&](const Vector3d& centre, const Vector3d& inward) {
    Matrix3d frame;
    const Vector3d up(0.0, 0.0, 1.0);
    frame.col(2) = inward;
    frame.col(0) = up.cross(inward);
    frame.col(1) = inward.cross(frame.col(0));
    b.add_fixed_plane(centre, frame, Vector3d(half, half, thick), "WALLx");
  };
  const double h = 0.5 * side * spacing;
  wall(Vector3d(-thick, 0.5 * width, h), Vector3d(1, 0, 0));
  wall(Vector3d(width + thick, 0.5 * width, h), Vector3d(-1, 0, 0));
  wall(Vector3d(0.5 * width, -thick, h), Vector3d(0, 1, 0));
  wall(Vector3d(0.5 * width, width + thick, h), Vector3d(0, -1, 0));
  b.add_law("iqsc0", solver::IqsClb{0.4});
  b.see("SPHER", "BLEUx", "iqsc0", "SPHER", "BLEUx", 0.1 * r);
  b.see("SPHER", "BLEUx", "iqsc0", "PLANx", "WALLx", 0.1 * r);
  return b.build();
}

SettledSphereBox3D settled_sphere_box_3d(int spheres, const solver::NlgsOptions& options,
                                         SphereBoxState state) {
  SettledSphereBox3D s{sphere_box_3d(spheres), {}, 0};
  s.run.h = 2e-4;
  if (state == SphereBoxState::compacting) {
    for (; s.settling_steps < 50; ++s.settling_steps) solver::step_3d(s.scene, s.run, options);
    return s;
  }
  s.settling_steps = step_until_at_rest(spheres, "sphere box of " + std::to_string(spheres) + " spheres",
                                        [&] { return solver::step_3d(s.scene, s.run, options); });
  return s;
}

}  // namespace lmgc::bench
