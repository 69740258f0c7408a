#include "bench/scenes/disk_box_2d.hpp"

#include <cmath>
#include <string>

#include "bench/scenes/at_rest.hpp"

namespace lmgc::bench {

solver::Scene2D disk_box_2d(int disks, int rows) {
  solver::SceneBuilder2D b;
  // Disks per row: a square box, or `rows` rows.
  const int side = rows > 0 ? (disks + rows - 1) / rows
                            : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(disks))));
  const double pitch = 2.002e-3;  // disks nearly touching: a square packing that carries itself
  for (int k = 0; k < disks; ++k) {
    const double r = 1e-3 * (0.995 + 0.005 * static_cast<double>((k * 7919) % 101) / 100.0);
    b.add_disk(pitch * (k % side) + pitch, pitch * (k / side) + pitch, r, 2000.0);
  }
  const double width = pitch * (side + 1);
  const double height = pitch * (disks / side + 2);
  b.add_fixed_joncx(0.5 * width, -5e-4, 0.0, 0.5 * width + 1e-3, 5e-4);
  b.add_fixed_joncx(-5e-4, 0.5 * height, M_PI / 2, 0.5 * height + 1e-3, 5e-4);
  b.add_fixed_joncx(width + 5e-4, 0.5 * height, M_PI / 2, 0.5 * height + 1e-3, 5e-4);
  b.add_law("iqsc0", solver::IqsClb{0.3});
  b.see("DISKx", "BLEUx", "iqsc0", "DISKx", "BLEUx", 1e-4);
  b.see("DISKx", "BLEUx", "iqsc0", "JONCx", "WALLx", 1e-4);
  return b.build();
}

solver::NlgsOptions fixed_work_options() {
  solver::NlgsOptions options;
  options.tolerance = 1e-12;
  options.gs_it1 = 25;
  options.gs_it2 = 2;
  return options;
}

SettledDiskBox2D settled_disk_box_2d(int disks, int rows, const solver::NlgsOptions& options,
                                     DiskBoxState state) {
  SettledDiskBox2D s{disk_box_2d(disks, rows), {}, 0};
  s.run.h = 2e-4;
  s.run.visibility = solver::build_visibility_index(s.scene);
  if (state == DiskBoxState::landing) {
    for (; s.settling_steps < 100; ++s.settling_steps) solver::step_2d(s.scene, s.run, options);
    return s;
  }
  s.settling_steps = step_until_at_rest(disks, "disk box of " + std::to_string(disks) + " disks",
                                        [&] { return solver::step_2d(s.scene, s.run, options); });
  return s;
}

}  // namespace lmgc::bench
