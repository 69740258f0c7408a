#pragma once
// One driven dof of DRV_DOF.DAT: an imposed velocity or force, by its coefficients or an evolution
// file (docs/lmgc90-facts/datbox-inputs.md §5).
#include <array>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

// v(t) = (CT + AMP cos(OMEGA t + PHI)) min(1, RAMPI + RAMP t), or an evolution table
// (linear interpolation and extrapolation). docs/lmgc90-facts/datbox-inputs.md §5.
struct DrivenDof2D {
  std::int32_t body = 0;
  std::int32_t dof = 0;   // 0, 1, 2
  bool is_force = false;  // 'force' instead of 'vlocy'
  std::array<double, 6> coefficients{};
  std::vector<std::array<double, 2>> evolution;  // (t, v) pairs when given by a file
  double value(double t) const;
};

}  // namespace lmgc::solver
