// Pinned iterates: the full-precision state after a fixed run of one 2D and one 3D case hashes to a
// committed value, so that a change of iterates (an optimisation that reorders a sum, a changed
// sweep order) fails here and is made deliberately: the hash is then updated in the same commit, with
// the reason. The state hashed is OUTBOX/EXACT_STATE.LAST (bodies, stored interactions with their
// reactions, the scramble's random stream): its record layouts are part of it, so a change of
// layout also updates the hash. Two runs of one build are byte-identical (checked here too).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

std::string state_after(const std::string& shipped, const std::string& tag, const std::string& flags) {
  const fs::path dir = scratch_dir("pinned_" + tag);
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / shipped / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  EXPECT_EQ(run_tool("lmgc-solve", "'" + dir.string() + "' --quiet --no-command-dat --write-every 0 " + flags)
                .exit_code,
            0);
  return read_file(dir / "OUTBOX" / "EXACT_STATE.LAST");
}

std::string hex(std::uint64_t h) {
  char text[32];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// A column of 20 disks settling on a wall, scrambled sweeps, 300 steps.
TEST(PinnedIterates, Rigid2DColumnOfDisks) {
  const std::string flags =
      "--steps 300 --dt 1e-3 --quick-scramble --scramble-seed 7 --tol 1e-6 --gs-it1 10 --gs-it2 50";
  const std::string a = state_after("disk_column_20", "2d_a", flags),
                    b = state_after("disk_column_20", "2d_b", flags);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "two runs differ";
  EXPECT_EQ(hex(fnv1a(a)), "3ac1427e45ad1a0b");
}

// A stack of 10 cubes (polyhedra, Cundall's common plane) on a plane, scrambled sweeps, 100 steps
// (20 under the sanitizers, whose build runs them 20-50x slower: a hash of its own).
TEST(PinnedIterates, Rigid3DStackOfCubes) {
#ifdef LMGC_SANITIZED_BUILD
  constexpr const char* kSteps = "20";
  constexpr const char* kExpected = "0430def5eb3ec01b";
#else
  constexpr const char* kSteps = "100";
  constexpr const char* kExpected = "6eb8f6434f9b8ed6";
#endif
  const std::string flags =
      std::string("--steps ") + kSteps +
      " --dt 1e-3 --quick-scramble --scramble-seed 7 --tol 1e-6 --gs-it1 10 --gs-it2 50";
  const std::string a = state_after("cube_stack_10_3d", "3d_a", flags),
                    b = state_after("cube_stack_10_3d", "3d_b", flags);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "two runs differ";
  EXPECT_EQ(hex(fnv1a(a)), kExpected);
}

}  // namespace
}  // namespace lmgc::test
