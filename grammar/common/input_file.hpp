#pragma once
// Reading an input file whole, refusing what is not one: a path that does not resolve (a symlink
// loop, a dangling link), a FIFO, a device such as /dev/zero, a folder, or a file larger than any
// case LMGC90 could read in memory. Never blocks and never throws.
#include <cstdint>
#include <filesystem>
#include <string>

namespace lmgc::grammar {

// Input files above this are refused (a 10^7-body BODIES.DAT is about 2 GB).
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{4} << 30;

enum class InputFileStatus { read, missing, refused };

struct InputFile {
  InputFileStatus status = InputFileStatus::missing;
  std::string text;   // the bytes, when read
  std::string error;  // why not, when refused: "is a FIFO", "symbolic link loop", ...
};

// `missing` only when nothing (not even a dangling link) exists at the path.
InputFile read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace lmgc::grammar
