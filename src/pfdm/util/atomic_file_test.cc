#include "pfdm/util/atomic_file.h"

#include <filesystem>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(AtomicFileTest, WritesAndReplacesWholeFilesLeavingNoTemporary) {
  const std::string dir = ScratchDirectory("atomic");
  WriteFileAtomically(dir + "/a.txt", "first");
  WriteFileAtomically(dir + "/a.txt", "second");
  EXPECT_EQ(ReadText(dir + "/a.txt"), "second");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(AtomicFileTest, UnwritablePlaceIsAnInputError) {
  try {
    WriteFileAtomically("/nonexistent/dir/a.txt", "x");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(
        std::string(error.what()),
        "/nonexistent/dir/a.txt: cannot write: No such file or directory");
  }
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir"));
}

TEST(AtomicFileTest, FailedRenameKeepsTheTargetAndRemovesTheTemporary) {
  const std::string dir = ScratchDirectory("atomic_rename");
  // A non-empty folder cannot be replaced by a file.
  std::filesystem::create_directories(dir + "/out/inner");
  try {
    WriteFileAtomically(dir + "/out", "x");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/out: cannot write: Is a directory");
  }
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/out/inner"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(AtomicFileTest, WritesBinaryContentsByteForByte) {
  const std::string dir = ScratchDirectory("atomic_binary");
  const std::string contents("a\0b\r\n\xff", 6);
  WriteFileAtomically(dir + "/b.bin", contents);
  EXPECT_EQ(ReadText(dir + "/b.bin"), contents);
  WriteFileAtomically(dir + "/empty", "");
  EXPECT_EQ(std::filesystem::file_size(dir + "/empty"), 0u);
}

TEST(AtomicFileTest, EnsureDirectoryCreatesParentsAndRejectsFiles) {
  const std::string dir = ScratchDirectory("ensure");
  EnsureDirectory(dir + "/a/b");
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/a/b"));
  EnsureDirectory(dir + "/a/b");  // Already there: fine.
  WriteText(dir + "/file", "x");
  try {
    EnsureDirectory(dir + "/file");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/file: cannot create folder: Not a directory");
  }
}

}  // namespace
}  // namespace pfdm
