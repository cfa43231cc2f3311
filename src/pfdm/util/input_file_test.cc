#include "pfdm/util/input_file.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/atomic_file.h"

namespace pfdm {
namespace {

// The file's bytes exactly, whatever their size: empty, one byte, and past
// the reader's first guesses (a megabyte of every byte value but NUL).
TEST(InputFileTest, ReadsTheWholeFileExactly) {
  const std::string dir = ScratchDirectory("input_file");
  std::string large;
  for (int i = 0; i < (1 << 20) + 7; ++i)
    large += static_cast<char>(1 + i % 255);
  for (const std::string& contents :
       {std::string(), std::string("x"), std::string("a,b\r\n1,2"), large}) {
    WriteFileAtomically(dir + "/f.txt", contents);
    EXPECT_EQ(ReadInputFile(dir + "/f.txt"), contents) << contents.size();
  }
}

TEST(InputFileTest, RefusesWhatIsNotARegularTextFile) {
  const std::string dir = ScratchDirectory("input_file_bad");
  EXPECT_EQ(InputErrorOf([&] { ReadInputFile(dir + "/missing.txt"); }),
            dir + "/missing.txt: cannot open the file");
  EXPECT_EQ(InputErrorOf([&] { ReadInputFile(dir); }),
            dir + ": is a folder, not a file");
  WriteFileAtomically(dir + "/nul.txt", std::string("a\nb\nc\0d\n", 8));
  EXPECT_EQ(InputErrorOf([&] { ReadInputFile(dir + "/nul.txt"); }),
            dir + "/nul.txt:3: contains a NUL byte (not a text file?)");
}

// Binary formats take every byte, NUL included, with the same refusals.
TEST(InputFileTest, BytesKeepNulAndRefuseWhatIsNotARegularFile) {
  const std::string dir = ScratchDirectory("input_bytes");
  const std::string bytes("\0\x01\n\xff\0", 5);
  WriteFileAtomically(dir + "/b.bin", bytes);
  EXPECT_EQ(ReadInputBytes(dir + "/b.bin"), bytes);
  EXPECT_EQ(InputErrorOf([&] { ReadInputBytes(dir); }),
            dir + ": is a folder, not a file");
}

}  // namespace
}  // namespace pfdm
