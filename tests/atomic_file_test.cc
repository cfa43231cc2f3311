#include "pfdm/atomic_file.h"

#include <filesystem>

#include "gtest/gtest.h"
#include "pfdm/error.h"
#include "test_util.h"

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
    EXPECT_EQ(std::string(error.what()),
              "/nonexistent/dir/a.txt: cannot write: No such file or directory");
  }
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir"));
}

TEST(AtomicFileTest, EnsureDirectoryCreatesParentsAndRejectsFiles) {
  const std::string dir = ScratchDirectory("ensure");
  EnsureDirectory(dir + "/a/b");
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/a/b"));
  WriteText(dir + "/file", "x");
  EXPECT_THROW(EnsureDirectory(dir + "/file"), InputError);
}

}  // namespace
}  // namespace pfdm
