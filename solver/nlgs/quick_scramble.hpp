#pragma once
// LMGC90's quick scramble of the NLGS sweep order (nlgs_SetWithQuickScramble,
// nlgs_3D_SetWithQuickScramble; mod_nlgs.f90 and mod_nlgs_3D.f90, prep_nlgs and
// quick_scramble_nlgs): each solve starts from the detection order and draws a random list of
// n indices, l_i uniform in 1..n; before each block of gs_it1 sweeps, the order is scrambled in
// place by swapping entry i with entry l_i for i = 1..n, the same list for every block of the
// solve, so the blocks' orders differ.
//
// LMGC90 draws the list with Fortran's RANDOM_NUMBER and never calls RANDOM_SEED; gfortran (since
// version 7) then seeds from the operating system, so two LMGC90 runs of one case sweep in different
// orders. Here the generator is seeded (--scramble-seed) and its stream continues from step to step:
// a run repeats exactly, and other seeds show how much a case depends on the order.
#include <cstdint>
#include <istream>
#include <ostream>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace lmgc::solver {

class QuickScramble {
 public:
  QuickScramble() = default;
  explicit QuickScramble(std::uint64_t seed) : random_(seed) {}

  // prep_nlgs: a new random list for a solve over n contacts.
  void prepare(std::size_t n) {
    random_list_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      // LMGC90's RA in [0, 1), here with 53 random bits; IAL1 = int(RA n) + 1, clamped to 1..n
      // (0-based here).
      const double uniform = static_cast<double>(random_() >> 11) * 0x1.0p-53;
      const auto drawn = static_cast<std::size_t>(uniform * static_cast<double>(n));
      random_list_[i] = drawn < n ? drawn : n - 1;
    }
  }

  // The list of the last prepare(), 0-based.
  const std::vector<std::size_t>& random_list() const { return random_list_; }

  // quick_scramble_nlgs: swaps entry i of `order` with entry l_i, i = 0..n-1, in place. `order` must
  // have the n entries of the last prepare(n).
  // The generator's state and the last list, as text (the exact restart state).
  friend std::ostream& operator<<(std::ostream& out, const QuickScramble& s) {
    out << s.random_ << ' ' << s.random_list_.size();
    for (std::size_t l : s.random_list_) out << ' ' << l;
    return out;
  }
  friend std::istream& operator>>(std::istream& in, QuickScramble& s) {
    std::size_t n = 0;
    in >> s.random_ >> n;
    s.random_list_.clear();
    for (std::size_t k = 0, l = 0; k < n && in >> l; ++k) s.random_list_.push_back(l);  // as many as written
    return in;
  }

  template <typename Index>
  void scramble(std::vector<Index>& order) const {
    if (order.size() != random_list_.size())
      throw std::logic_error("QuickScramble: order size differs from the prepared list");
    for (std::size_t i = 0; i < order.size(); ++i) std::swap(order[i], order[random_list_[i]]);
  }

 private:
  std::mt19937_64 random_{1};
  std::vector<std::size_t> random_list_;
};

}  // namespace lmgc::solver
