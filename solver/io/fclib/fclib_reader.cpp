#include "solver/io/fclib/fclib_reader.hpp"

#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>

namespace lmgc::solver {

namespace {

// Owns one HDF5 identifier.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

class File {
 public:
  explicit File(const std::filesystem::path& path) : path_(path.string()), file_(open(path), H5Fclose) {
    if (!file_.valid()) throw FclibError(path_ + ": not an HDF5 file, or it cannot be opened");
    std::error_code ec;
    file_bytes_ = std::filesystem::file_size(path, ec);
    if (ec) throw FclibError(path_ + ": " + ec.message());
  }

  // A regular file only: HDF5 would wait on a FIFO and read a device without end.
  static hid_t open(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec) throw FclibError(path.string() + ": " + ec.message());
    if (!std::filesystem::is_regular_file(status)) throw FclibError(path.string() + ": not a regular file");
    return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  }

  // True when every component of the absolute path exists.
  bool has(const std::string& name) const {
    std::size_t position = 0;
    while ((position = name.find('/', position + 1)) != std::string::npos)
      if (H5Lexists(file_.get(), name.substr(0, position).c_str(), H5P_DEFAULT) <= 0) return false;
    return H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT) > 0;
  }

  template <typename T>
  std::vector<T> read(const std::string& name) const {
    if (!has(name)) throw FclibError(path_ + ": dataset " + name + " is missing");
    Handle dataset(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) throw FclibError(path_ + ": dataset " + name + " cannot be opened");
    Handle space(H5Dget_space(dataset.get()), H5Sclose);
    const hssize_t count = H5Sget_simple_extent_npoints(space.get());
    if (count < 0) throw FclibError(path_ + ": dataset " + name + " has no size");
    // A damaged header may claim any extent: more values than the file could hold, even compressed
    // 64 to 1, is a damaged file, refused before the memory is asked for.
    if (static_cast<std::uintmax_t>(count) > (64 * file_bytes_ + (std::uintmax_t{1} << 20)) / sizeof(T))
      throw FclibError(path_ + ": dataset " + name + " claims " + std::to_string(count) +
                       " values, more than the file can hold");
    std::vector<T> values(static_cast<std::size_t>(count));
    const hid_t memory_type = std::is_same_v<T, int> ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE;
    if (count > 0 && H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      throw FclibError(path_ + ": dataset " + name + " cannot be read as " +
                       (std::is_same_v<T, int> ? "integers" : "numbers"));
    return values;
  }

  int scalar(const std::string& name) const {
    const std::vector<int> values = read<int>(name);
    if (values.size() != 1) throw FclibError(path_ + ": " + name + " is not a scalar");
    return values[0];
  }

  Eigen::VectorXd vector(const std::string& name) const {
    const std::vector<double> values = read<double>(name);
    return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  Handle file_;
  std::uintmax_t file_bytes_ = 0;
};

// Compressed rows from (row, column, value) triplets; duplicates are kept (the block builder sums them).
void rows_from_triplets(int rows, const std::vector<int>& row, const std::vector<int>& column,
                        const std::vector<double>& value, FclibLocalProblem& problem,
                        const std::string& path) {
  problem.row_pointer.assign(rows + 1, 0);
  for (int i : row) {
    if (i < 0 || i >= rows) throw FclibError(path + ": W has a row index out of range");
    ++problem.row_pointer[i + 1];
  }
  std::partial_sum(problem.row_pointer.begin(), problem.row_pointer.end(), problem.row_pointer.begin());
  std::vector<int> next(problem.row_pointer.begin(), problem.row_pointer.end() - 1);
  problem.column_index.assign(value.size(), 0);
  problem.value.assign(value.size(), 0.0);
  for (std::size_t k = 0; k < value.size(); ++k) {
    const int slot = next[row[k]]++;
    problem.column_index[slot] = column[k];
    problem.value[slot] = value[k];
  }
}

}  // namespace

static FclibLocalProblem read_in_this_process(const std::filesystem::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our messages replace HDF5's stack dumps
  const File file(path);
  if (!file.has("/fclib_local")) {
    if (file.has("/fclib_global"))
      throw FclibError(file.path() + ": a global problem (/fclib_global); reduce it to local form first");
    throw FclibError(file.path() + ": no /fclib_local group");
  }
  FclibLocalProblem problem;
  problem.space_dimension = file.scalar("/fclib_local/spacedim");
  if (problem.space_dimension != 2 && problem.space_dimension != 3)
    throw FclibError(file.path() + ": spacedim must be 2 or 3");
  const int rows = file.scalar("/fclib_local/W/m");
  const int columns = file.scalar("/fclib_local/W/n");
  const int storage = file.scalar("/fclib_local/W/nz");
  if (rows != columns || rows < 0) throw FclibError(file.path() + ": W is not square");
  problem.size = rows;
  const std::vector<int> p = file.read<int>("/fclib_local/W/p");
  const std::vector<int> i = file.read<int>("/fclib_local/W/i");
  const std::vector<double> x = file.read<double>("/fclib_local/W/x");
  if (storage == -2) {  // compressed rows: p = row pointers, i = columns
    if (p.size() != static_cast<std::size_t>(rows) + 1)
      throw FclibError(file.path() + ": W/p has the wrong length");
    const std::size_t entries = static_cast<std::size_t>(p.back());
    if (entries > i.size() || entries > x.size())
      throw FclibError(file.path() + ": W/p points past W/i or W/x");
    problem.row_pointer = p;
    problem.column_index.assign(i.begin(), i.begin() + static_cast<std::ptrdiff_t>(entries));
    problem.value.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(entries));
  } else if (storage == -1) {  // compressed columns: p = column pointers, i = rows
    if (p.size() != static_cast<std::size_t>(columns) + 1)
      throw FclibError(file.path() + ": W/p has the wrong length");
    const std::size_t entries = static_cast<std::size_t>(p.back());
    if (entries > i.size() || entries > x.size())
      throw FclibError(file.path() + ": W/p points past W/i or W/x");
    std::vector<int> column(entries);
    for (int j = 0; j < columns; ++j)
      for (int k = p[j]; k < p[j + 1]; ++k) column[k] = j;
    rows_from_triplets(rows, std::vector<int>(i.begin(), i.begin() + static_cast<std::ptrdiff_t>(entries)),
                       column,
                       std::vector<double>(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(entries)),
                       problem, file.path());
  } else if (storage >= 0) {  // triplets: i = rows, p = columns (CSparse orientation, FORMAT.md §2)
    const std::size_t entries = static_cast<std::size_t>(storage);
    if (entries > i.size() || entries > p.size() || entries > x.size())
      throw FclibError(file.path() + ": W/nz exceeds the stored entries");
    rows_from_triplets(rows, std::vector<int>(i.begin(), i.begin() + static_cast<std::ptrdiff_t>(entries)),
                       std::vector<int>(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(entries)),
                       std::vector<double>(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(entries)),
                       problem, file.path());
  } else {
    throw FclibError(file.path() + ": W/nz has an unknown storage code");
  }
  problem.q = file.vector("/fclib_local/vectors/q");
  problem.mu = file.vector("/fclib_local/vectors/mu");
  if (problem.q.size() != rows) throw FclibError(file.path() + ": q does not match the size of W");
  if (problem.mu.size() * problem.space_dimension != rows)
    throw FclibError(file.path() + ": mu does not have one value per contact");
  // Values a solve can take: finite, and small enough that |q| and W r do not overflow (the error
  // measure divides by |q|: an infinite |q| would report any r as solved).
  constexpr double kLargest = 1e100;
  const auto sane = [&](const auto& values, const char* what) {
    for (const double v : values)
      if (!std::isfinite(v) || std::abs(v) > kLargest)
        throw FclibError(file.path() + ": " + what + " holds " + std::to_string(v) +
                         " (not finite, or beyond 1e100: the solve's sums would overflow)");
  };
  sane(problem.value, "W");
  sane(problem.q, "q");
  sane(problem.mu, "mu");
  for (const double m : problem.mu)
    if (m < 0.0)
      throw FclibError(file.path() + ": mu holds a negative friction coefficient " + std::to_string(m));
  if (file.has("/solution/r")) {
    problem.solution_r = file.vector("/solution/r");
    if (file.has("/solution/u")) problem.solution_u = file.vector("/solution/u");
  }
  if (file.has("/guesses/number_of_guesses")) {
    const int guesses = file.scalar("/guesses/number_of_guesses");
    // A damaged count must not walk two billion names.
    if (guesses < 0 || guesses > 100000)
      throw FclibError(file.path() + ": /guesses/number_of_guesses is " + std::to_string(guesses));
    for (int g = 1; g <= guesses; ++g) {
      const std::string name = "/guesses/" + std::to_string(g) + "/r";
      if (file.has(name)) problem.guesses_r.push_back(file.vector(name));
    }
  }
  return problem;
}

namespace {

// The problem as bytes through a pipe: each vector as its length and its values.
void put(std::string& out, const void* data, std::size_t bytes) {
  out.append(static_cast<const char*>(data), bytes);
}
template <class T>
void put_vector(std::string& out, const T* data, std::size_t count) {
  const std::uint64_t n = count;
  put(out, &n, sizeof n);
  put(out, data, count * sizeof(T));
}
std::string serialised(const FclibLocalProblem& p) {
  std::string out;
  put(out, &p.space_dimension, sizeof p.space_dimension);
  put(out, &p.size, sizeof p.size);
  put_vector(out, p.row_pointer.data(), p.row_pointer.size());
  put_vector(out, p.column_index.data(), p.column_index.size());
  put_vector(out, p.value.data(), p.value.size());
  put_vector(out, p.q.data(), static_cast<std::size_t>(p.q.size()));
  put_vector(out, p.mu.data(), static_cast<std::size_t>(p.mu.size()));
  const char has_r = p.solution_r.has_value(), has_u = p.solution_u.has_value();
  put(out, &has_r, 1);
  if (has_r) put_vector(out, p.solution_r->data(), static_cast<std::size_t>(p.solution_r->size()));
  put(out, &has_u, 1);
  if (has_u) put_vector(out, p.solution_u->data(), static_cast<std::size_t>(p.solution_u->size()));
  const std::uint64_t guesses = p.guesses_r.size();
  put(out, &guesses, sizeof guesses);
  for (const Eigen::VectorXd& g : p.guesses_r) put_vector(out, g.data(), static_cast<std::size_t>(g.size()));
  return out;
}

struct Reader {
  const std::string& bytes;
  std::size_t at = 0;
  void get(void* data, std::size_t n) {
    if (at + n > bytes.size()) throw FclibError("the FCLIB reader's output is cut short");
    std::memcpy(data, bytes.data() + at, n);
    at += n;
  }
  template <class T>
  std::vector<T> vector() {
    std::uint64_t n = 0;
    get(&n, sizeof n);
    if (n > (bytes.size() - at) / sizeof(T)) throw FclibError("the FCLIB reader's output is cut short");
    std::vector<T> out(static_cast<std::size_t>(n));
    get(out.data(), out.size() * sizeof(T));
    return out;
  }
  Eigen::VectorXd eigen() {
    const std::vector<double> v = vector<double>();
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
  }
};

FclibLocalProblem deserialised(const std::string& bytes) {
  Reader r{bytes};
  FclibLocalProblem p;
  r.get(&p.space_dimension, sizeof p.space_dimension);
  r.get(&p.size, sizeof p.size);
  p.row_pointer = r.vector<int>();
  p.column_index = r.vector<int>();
  p.value = r.vector<double>();
  p.q = r.eigen();
  p.mu = r.eigen();
  char has = 0;
  r.get(&has, 1);
  if (has) p.solution_r = r.eigen();
  r.get(&has, 1);
  if (has) p.solution_u = r.eigen();
  std::uint64_t guesses = 0;
  r.get(&guesses, sizeof guesses);
  for (std::uint64_t k = 0; k < guesses; ++k) p.guesses_r.push_back(r.eigen());
  return p;
}

}  // namespace

FclibLocalProblem read_fclib_local(const std::filesystem::path& path) {
  // libhdf5 can crash on a damaged file (fuzzing found a read through a damaged symbol table that
  // dereferences null inside the library): the file is read in a child process, and a child that
  // does not end normally makes the file refused, as damaged, instead of taking the program down.
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw FclibError(path.string() + ": cannot open a pipe to read it");
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0) {
    close(pipe_ends[0]);
    close(pipe_ends[1]);
    throw FclibError(path.string() + ": cannot start the process that reads it");
  }
  if (child == 0) {
    close(pipe_ends[0]);
    // A fault ends the child plainly: handlers inherited from the program (a sanitizer's, a fuzzer's)
    // would report the library's crash as the program's.
    for (const int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
      std::signal(signal_number, SIG_DFL);
    std::string message;
    try {
      message = "P" + serialised(read_in_this_process(path));
    } catch (const std::exception& e) {
      message = std::string("E") + e.what();
    }
    for (std::size_t written = 0; written < message.size();) {
      const ssize_t n = write(pipe_ends[1], message.data() + written, message.size() - written);
      if (n <= 0) _exit(2);
      written += static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  close(pipe_ends[1]);
  std::string message;
  char buffer[65536];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    message.append(buffer, static_cast<std::size_t>(n));
  }
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || message.empty())
    throw FclibError(path.string() + ": a damaged HDF5 file (the HDF5 library failed while reading it" +
                     (WIFSIGNALED(status) ? ", signal " + std::to_string(WTERMSIG(status)) : std::string()) +
                     ")");
  if (message[0] == 'E') throw FclibError(message.substr(1));
  return deserialised(message.substr(1));
}

}  // namespace lmgc::solver
