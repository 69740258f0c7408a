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

// The same schedule kept as the sweep at which the contact is solved next (2D sweeps): a sweep that
// passes a contact by writes nothing, where OpenContactVisits counts the visit. On a 64k-disk
// layer, whose contacts are mostly open, every sweep otherwise wrote back the whole 3 MB reaction
// array. `sweep` counts the sweeps of the step; a restart (a reaction, or a check) makes the next
// sweep solve the contact. The solved visits are OpenContactVisits' (unit test): the 1st, 3rd,
// 6th, 10th... sweep without reaction since the restart.
struct OpenContactSchedule {
  std::int32_t next = 0, threshold = 1;
  // Called for a contact without reaction at sweep `sweep`: true when this sweep passes it by.
  bool skip(std::int32_t sweep) {
    if (sweep < next) return true;
    ++threshold;
    next = sweep + threshold;
    return false;
  }
  void restart() {
    next = 0;
    threshold = 1;
  }
  // restart() when `condition`, without a branch.
  void restart_if(bool condition) {
    next = condition ? 0 : next;
    threshold = condition ? 1 : threshold;
  }
};

}  // namespace lmgc::solver
