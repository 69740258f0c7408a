#include "grammar/common/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

namespace lmgc::grammar {

namespace {

std::string kind_of(const struct stat& info) {
  if (S_ISDIR(info.st_mode)) return "is a folder";
  if (S_ISFIFO(info.st_mode)) return "is a FIFO (named pipe)";
  if (S_ISCHR(info.st_mode)) return "is a character device";
  if (S_ISBLK(info.st_mode)) return "is a block device";
  if (S_ISSOCK(info.st_mode)) return "is a socket";
  return "is not a regular file";
}

InputFile refused(std::string why) {
  InputFile f;
  f.status = InputFileStatus::refused;
  f.error = std::move(why);
  return f;
}

}  // namespace

InputFile read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  struct stat link_info {};
  if (::lstat(path.c_str(), &link_info) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return {};
    return refused(std::strerror(errno));
  }
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused below anyway).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ELOOP) return refused("symbolic link loop");
    if (errno == ENOENT) return refused("dangling symbolic link");
    return refused(std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int e = errno;
    ::close(fd);
    return refused(std::strerror(e));
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    return refused(kind_of(info));
  }
  const auto size = static_cast<std::uintmax_t>(info.st_size);
  if (size > max_bytes) {
    ::close(fd);
    return refused("is " + std::to_string(size) + " bytes, above the " + std::to_string(max_bytes) +
                   " bytes an input file may have");
  }
  InputFile f;
  f.text.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  // Reads to the end even if the file grows meanwhile, up to the limit.
  for (;;) {
    if (done == f.text.size()) {
      if (f.text.size() >= max_bytes) break;
      f.text.resize(std::min<std::uintmax_t>(max_bytes, f.text.size() + 65536));
    }
    const ssize_t n = ::read(fd, f.text.data() + done, f.text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int e = errno;
      ::close(fd);
      return refused(std::strerror(e));
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  f.text.resize(done);
  f.status = InputFileStatus::read;
  return f;
}

}  // namespace lmgc::grammar
