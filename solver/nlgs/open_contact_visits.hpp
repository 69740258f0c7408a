#pragma once
// The NLGS sweeps' treatment of contacts without reaction (2D and 3D): most candidates of a
// granular step stay open, so one that returned no reaction is solved again only at its 1st, 3rd,
// 6th, 10th... sweep without reaction; a reaction, or the next convergence check (which solves every
// contact), restarts the count. Not LMGC90's (it solves every contact each sweep); the check keeps a
// skipped contact that closes meanwhile from passing as converged.
//
// The schedule is kept as the sweep at which the contact is solved next, so that a sweep that passes
// a contact by reads it and writes nothing. Counting the passes instead (the schedule's first form,
// kept in its unit test as the reference) wrote every record at every sweep: on a 64k-disk layer,
// whose contacts are mostly open, the whole 3 MB reaction array (layer sweeps at 64k: 42-46 -> 33-37
// ms per step; siloDK_hoperJC 800 steps: 7.02-7.11 -> 6.62-6.80 s).
#include <cstdint>

namespace lmgc::solver {

struct OpenContactSchedule {
  // `sweep` numbers the sweeps, one more at each (2D: within the step; 3D: within the block); a
  // restart makes the next sweep solve the contact whatever its number.
  std::int32_t next = 0;       // the sweep at which the contact is solved next
  std::int32_t threshold = 1;  // solves since the restart, plus one: the gap to the next solve
  // What skip(sweep) will answer, without counting the visit.
  bool passes_by(std::int32_t sweep) const { return sweep < next; }
  // Called for a contact without reaction at sweep `sweep`: true when this sweep passes it by.
  bool skip(std::int32_t sweep) {
    if (sweep < next) return true;
    count_solve(sweep);
    return false;
  }
  // A contact without reaction solved at `sweep` (not passed by): its next solve is further off.
  void count_solve(std::int32_t sweep) {
    ++threshold;
    next = sweep + threshold;
  }
  // The next sweep solves the contact.
  void restart() {
    next = 0;
    threshold = 1;
  }
  // restart() when `condition`, without a branch (the sweeps' test of a new reaction is unpredictable).
  void restart_if(bool condition) {
    next = condition ? 0 : next;
    threshold = condition ? 1 : threshold;
  }
};

}  // namespace lmgc::solver
