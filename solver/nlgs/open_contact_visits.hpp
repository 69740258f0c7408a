#pragma once
// The NLGS sweeps' treatment of contacts without reaction (2D and 3D): most candidates of a
// granular step stay open, so one that returned no reaction is solved again only at its 1st, 3rd,
// 6th, 10th... sweep without reaction; a reaction, or the next convergence check (which solves every
// contact), restarts the count. Not LMGC90's (it solves every contact each sweep); the check keeps a
// skipped contact that closes meanwhile from passing as converged.
//
// The schedule is kept as the sweep at which the contact is solved next, so that a sweep that passes
// a contact by reads it and writes nothing. Counting the passes instead (kept in its unit test as
// the reference) would write every record at every sweep: in a packing, whose contacts are mostly
// open, the whole reaction array.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

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

// The contacts each sweep of a block visits, by execution position, kept ahead as one bitmap per
// coming sweep: a visit files the contact under the sweep at which its schedule next solves it (the
// following one while it has a reaction). A sweep walks the set bits of its own bitmap, in execution
// order, and neither reads the records of the contacts it passes by nor branches on them.
// The bitmaps form a ring indexed by sweep number: a visit files a contact at most `largest_gap`
// sweeps ahead (the schedule's gaps grow by one at each solve, from a restart at the latest), so a
// ring longer than that never holds two sweeps in one bitmap.
class DueVisits {
 public:
  // The largest gap a visit of a block of `sweeps` sweeps can file a contact at, within the block.
  static std::int32_t largest_gap(std::int32_t sweeps) {
    OpenContactSchedule s;
    std::int32_t sweep = 0, gap = 1;
    while (true) {
      s.count_solve(sweep);
      if (s.next >= sweeps) return gap;
      gap = s.next - sweep;
      sweep = s.next;
    }
  }
  // The sweep at which a contact visited at `sweep` is visited next, from its schedule after the
  // visit: the following one while it has a reaction (next 0), else the one its schedule names.
  static std::int32_t due_at(const OpenContactSchedule& after, std::int32_t sweep) {
    return after.next > sweep ? after.next : sweep + 1;
  }
  // Bitmaps for blocks of `sweeps` sweeps (the ring's length: the power of two above the largest gap).
  static std::size_t ring_length(std::int32_t sweeps) {
    return std::bit_ceil(static_cast<std::size_t>(largest_gap(sweeps)) + 1);
  }

  // A block of `sweeps` sweeps over `count` contacts, from sweep `first`: its first sweep visits every
  // contact (the check before it, or the set-up, restarted every schedule).
  void start_block(std::size_t count, std::int32_t first, std::int32_t sweeps) {
    words_ = (count + 63) / 64;
    mask_ = ring_length(sweeps) - 1;
    end_ = first + sweeps;
    bits_.assign(words_ * (mask_ + 1), 0);
    std::uint64_t* due = row(first);
    for (std::size_t w = 0; w < words_; ++w) due[w] = ~std::uint64_t{0};
    if (count % 64 != 0) due[words_ - 1] = (std::uint64_t{1} << (count % 64)) - 1;
  }

  // Sweep `sweep`: visit(position) for every contact due, in execution order; visit returns the
  // contact's schedule after the visit, which files it for its next one. ahead(position) is called
  // `lookahead` visits before visit(position), so that the caller can prefetch what that visit will
  // read: in a long list the due contacts' records are beyond the caches, and each visit waited for
  // its own. Inlined into the caller's sweep, whose arrays then stay in registers.
  static constexpr int lookahead = 8;
  template <typename Visit, typename Ahead>
  [[gnu::always_inline]] void sweep(std::int32_t sweep, Visit&& visit, Ahead&& ahead) {
    std::uint64_t* const due = row(sweep);
    std::uint64_t* const following = sweep + 1 < end_ ? row(sweep + 1) : nullptr;
    // A second cursor over this sweep's bits, `lookahead` visits on. It enters each word before the
    // visits do, so it reads the word's bits before they are cleared; the visits set bits of later
    // sweeps only.
    std::size_t ahead_word = 0;
    std::uint64_t ahead_bits = words_ > 0 ? due[0] : 0;
    const auto step_ahead = [&] {
      while (ahead_bits == 0 && ahead_word + 1 < words_) ahead_bits = due[++ahead_word];
      if (ahead_bits == 0) return;
      ahead(64 * ahead_word + static_cast<unsigned>(std::countr_zero(ahead_bits)));
      ahead_bits &= ahead_bits - 1;
    };
    for (int k = 0; k < lookahead; ++k) step_ahead();
    for (std::size_t w = 0; w < words_; ++w) {
      std::uint64_t word = due[w];
      if (word == 0) continue;
      due[w] = 0;
      // The word's contacts due at the next sweep (those with a reaction), and at one later sweep
      // (the open ones solved here, whose schedules mostly agree), gathered in registers: a store per
      // visit made each visit wait for the previous one's.
      std::uint64_t next_bits = 0, later_bits = 0;
      std::int32_t later = -1;
      while (word != 0) {
        const auto bit = static_cast<unsigned>(std::countr_zero(word));
        word &= word - 1;
        const std::size_t position = 64 * w + bit;
        step_ahead();
        const std::int32_t next = due_at(visit(position), sweep);
        const std::uint64_t mask = std::uint64_t{1} << bit;
        if (next == sweep + 1) {
          next_bits |= mask;
        } else if (next < end_) {
          if (later < 0) later = next;
          if (next == later)
            later_bits |= mask;
          else
            row(next)[w] |= mask;
        }
      }
      if (following != nullptr) following[w] |= next_bits;
      if (later >= 0) row(later)[w] |= later_bits;
    }
  }

 private:
  std::uint64_t* row(std::int32_t sweep) {
    return bits_.data() + words_ * (static_cast<std::size_t>(sweep) & mask_);
  }
  std::vector<std::uint64_t> bits_;
  std::size_t words_ = 0, mask_ = 0;
  std::int32_t end_ = 0;
};

}  // namespace lmgc::solver
