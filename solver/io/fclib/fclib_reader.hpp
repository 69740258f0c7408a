#pragma once
// Reader of FCLIB frictional contact problems (HDF5, fc3d/FORMAT.md §2): the local form
// `/fclib_local` (W, q, mu) with its optional `/solution` and `/guesses`. Whatever storage W uses
// (compressed rows, compressed columns or triplets) comes out as compressed rows, duplicates summed.
// Kept out of lmgc_solver so that only the programs that read FCLIB link libhdf5.
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lmgc::solver {

struct FclibError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FclibLocalProblem {
  int space_dimension = 3;       // 2 or 3
  int size = 0;                  // rows (= columns) of W
  std::vector<int> row_pointer;  // size + 1
  std::vector<int> column_index;
  std::vector<double> value;
  Eigen::VectorXd q, mu;
  std::optional<Eigen::VectorXd> solution_r, solution_u;
  std::vector<Eigen::VectorXd> guesses_r;
};

// Throws FclibError naming the file and the missing or malformed dataset.
FclibLocalProblem read_fclib_local(const std::filesystem::path& file);

}  // namespace lmgc::solver
