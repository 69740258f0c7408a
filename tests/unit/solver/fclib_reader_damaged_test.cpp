// FCLIB files with values no solve can take are refused with a message naming the file, never
// solved: an infinite or huge q (|q| would overflow and any r would look solved), NaN or negative
// friction, a damaged count of guesses (it must not walk two billion names), a FIFO.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "solver/io/fclib/fclib_reader.hpp"
#include "tests/support/run_tool.hpp"

namespace lmgc::solver {
namespace {

namespace fs = std::filesystem;

void write_ints(hid_t file, const char* name, const std::vector<int>& values) {
  const hsize_t n = values.size();
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t set = H5Dcreate2(file, name, H5T_NATIVE_INT, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(set);
  H5Sclose(space);
}

void write_doubles(hid_t file, const char* name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t set = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(set);
  H5Sclose(space);
}

// One 3D contact: W the identity (triplets), q and mu as given.
fs::path one_contact(const std::string& name, const std::vector<double>& q, double mu, int guesses = -1) {
  // A folder per file: the tests run in parallel, and a scratch folder is emptied when it is made.
  const fs::path path = test::scratch_dir("fclib_damaged_" + name) / name;
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  for (const char* group : {"/fclib_local", "/fclib_local/W", "/fclib_local/vectors"})
    H5Gclose(H5Gcreate2(file, group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  write_ints(file, "/fclib_local/spacedim", {3});
  write_ints(file, "/fclib_local/W/m", {3});
  write_ints(file, "/fclib_local/W/n", {3});
  write_ints(file, "/fclib_local/W/nz", {3});
  write_ints(file, "/fclib_local/W/i", {0, 1, 2});
  write_ints(file, "/fclib_local/W/p", {0, 1, 2});
  write_doubles(file, "/fclib_local/W/x", {1.0, 1.0, 1.0});
  write_doubles(file, "/fclib_local/vectors/q", q);
  write_doubles(file, "/fclib_local/vectors/mu", {mu});
  if (guesses >= 0) {
    H5Gclose(H5Gcreate2(file, "/guesses", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    write_ints(file, "/guesses/number_of_guesses", {guesses});
  }
  H5Fclose(file);
  return path;
}

TEST(FclibReader, AWellFormedOneContactProblemReads) {
  const FclibLocalProblem p = read_fclib_local(one_contact("good.hdf5", {0.0, -1.0, 0.0}, 0.3, 1));
  EXPECT_EQ(p.size, 3);
  EXPECT_DOUBLE_EQ(p.mu[0], 0.3);
}

TEST(FclibReader, ValuesNoSolveCanTakeAreRefused) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(read_fclib_local(one_contact("q_inf.hdf5", {0.0, -inf, 0.0}, 0.3)), FclibError);
  EXPECT_THROW(read_fclib_local(one_contact("q_huge.hdf5", {0.0, -1e300, 0.0}, 0.3)), FclibError);
  EXPECT_THROW(read_fclib_local(one_contact("mu_nan.hdf5", {0.0, -1.0, 0.0}, nan)), FclibError);
  EXPECT_THROW(read_fclib_local(one_contact("mu_negative.hdf5", {0.0, -1.0, 0.0}, -0.1)), FclibError);
  EXPECT_THROW(read_fclib_local(one_contact("guesses.hdf5", {0.0, -1.0, 0.0}, 0.3, 2000000000)), FclibError);
}

// A dataset whose header claims far more values than the file holds (a chunked extent of 2^40 with
// no chunk written: the file stays small): refused before memory is asked for (a fuzz finding: a
// damaged header made the reader ask for 2 TB).
TEST(FclibReader, ADatasetClaimingMoreValuesThanTheFileHoldsIsRefused) {
  const fs::path path = test::scratch_dir("fclib_huge_extent") / "huge_extent.hdf5";
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Gclose(H5Gcreate2(file, "/fclib_local", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  const hsize_t extent = hsize_t{1} << 40, chunk = 1024;
  const hid_t space = H5Screate_simple(1, &extent, nullptr);
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(properties, 1, &chunk);
  const hid_t set =
      H5Dcreate2(file, "/fclib_local/spacedim", H5T_NATIVE_INT, space, H5P_DEFAULT, properties, H5P_DEFAULT);
  H5Dclose(set);
  H5Pclose(properties);
  H5Sclose(space);
  H5Fclose(file);
  try {
    read_fclib_local(path);
    ADD_FAILURE() << "read";
  } catch (const FclibError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the file can hold"), std::string::npos) << e.what();
  }
}

// A file whose damaged symbol table makes libhdf5 itself crash (a fuzz finding: a null read inside
// H5G__stab_lookup): the read runs in a child process, so the file is refused as damaged.
TEST(FclibReader, AFileThatCrashesTheHdf5LibraryIsRefusedAsDamaged) {
  const fs::path seed =
      fs::path(LMGC_SOURCE_DIR) / "fuzz" / "seeds" / "fclib" / "damaged_symbol_table_crashing_libhdf5";
  try {
    read_fclib_local(seed);
    ADD_FAILURE() << "read";
  } catch (const FclibError& e) {
    EXPECT_NE(std::string(e.what()).find("damaged HDF5 file"), std::string::npos) << e.what();
  }
}

TEST(FclibReader, AFifoIsRefusedWithoutWaiting) {
  const fs::path fifo = test::scratch_dir("fclib_fifo") / "problem.hdf5";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(read_fclib_local(fifo), FclibError);
}

// Through the tool: a refused file is a read failure (exit 1), never "solved with error 0".
TEST(LmgcFc3dCli, AnInfiniteQIsAReadFailureNotASolvedProblem) {
  const fs::path path =
      one_contact("q_inf_tool.hdf5", {0.0, -std::numeric_limits<double>::infinity(), 0.0}, 0.3);
  const test::ToolRun run = test::run_tool("lmgc-fc3d", "'" + path.string() + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.output.find("solved 1/1"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace lmgc::solver
