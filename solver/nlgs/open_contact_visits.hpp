#pragma once
// The NLGS sweeps' treatment of contacts without reaction (2D and 3D): most candidates of a
// granular step stay open, so one that returned no reaction is visited again only on its 1st, 3rd,
// 6th, 10th... zero visits; a reaction, or the next convergence check (which solves every contact),
// restarts the count. Not LMGC90's (it solves every contact each sweep); the check keeps a skipped
// contact that closes meanwhile from passing as converged.
#include <cstdint>

namespace lmgc::solver {

struct OpenContactVisits {
  std::int32_t count = 0, threshold = 1;
  // What the next skip() will answer, without counting the visit.
  bool skips_next() const { return count + 1 < threshold * (threshold + 1) / 2; }
  // Called for a contact without reaction at each sweep: true when this sweep passes it by.
  bool skip() {
    const bool passes = skips_next();
    ++count;
    if (!passes) ++threshold;
    return passes;
  }
  void restart() {
    count = 0;
    threshold = 1;
  }
  // restart() when `condition`, without a branch (the sweeps' test of a new reaction is unpredictable).
  void restart_if(bool condition) {
    count = condition ? 0 : count;
    threshold = condition ? 1 : threshold;
  }
};

}  // namespace lmgc::solver
