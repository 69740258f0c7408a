// Input files that are not files are refused, never read: no block on a FIFO, no unbounded read of
// a device, no exception on a symbolic link loop.
#include "grammar/common/input_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace lmgc::grammar {
namespace {

namespace fs = std::filesystem;

class InputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lmgc_input_file_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(InputFileTest, ReadsARegularFileWhole) {
  std::ofstream(dir_ / "BODIES.DAT") << "abc\ndef\n";
  const InputFile f = read_input_file(dir_ / "BODIES.DAT");
  EXPECT_EQ(f.status, InputFileStatus::read);
  EXPECT_EQ(f.text, "abc\ndef\n");
}

TEST_F(InputFileTest, NothingAtThePathIsMissing) {
  EXPECT_EQ(read_input_file(dir_ / "absent").status, InputFileStatus::missing);
}

TEST_F(InputFileTest, FifoIsRefusedWithoutWaitingForAWriter) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  const InputFile f = read_input_file(dir_ / "fifo");
  EXPECT_EQ(f.status, InputFileStatus::refused);
  EXPECT_NE(f.error.find("FIFO"), std::string::npos) << f.error;
}

TEST_F(InputFileTest, DeviceIsRefused) {
  fs::create_symlink("/dev/zero", dir_ / "zero");
  const InputFile f = read_input_file(dir_ / "zero");
  EXPECT_EQ(f.status, InputFileStatus::refused);
  EXPECT_NE(f.error.find("device"), std::string::npos) << f.error;
}

TEST_F(InputFileTest, SymbolicLinkLoopAndDanglingLinkAreRefused) {
  fs::create_symlink(dir_ / "b", dir_ / "a");
  fs::create_symlink(dir_ / "a", dir_ / "b");
  fs::create_symlink(dir_ / "nowhere", dir_ / "dangling");
  EXPECT_EQ(read_input_file(dir_ / "a").status, InputFileStatus::refused);
  EXPECT_EQ(read_input_file(dir_ / "a").error, "symbolic link loop");
  EXPECT_EQ(read_input_file(dir_ / "dangling").status, InputFileStatus::refused);
}

TEST_F(InputFileTest, FolderAndOversizedFileAreRefused) {
  fs::create_directories(dir_ / "folder");
  EXPECT_EQ(read_input_file(dir_ / "folder").status, InputFileStatus::refused);
  std::ofstream(dir_ / "big") << std::string(100, 'x');
  EXPECT_EQ(read_input_file(dir_ / "big", 99).status, InputFileStatus::refused);
  EXPECT_EQ(read_input_file(dir_ / "big", 100).status, InputFileStatus::read);
}

}  // namespace
}  // namespace lmgc::grammar
