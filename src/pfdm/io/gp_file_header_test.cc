#include "pfdm/io/gp_file_header.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

const char kHeader[] = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";

TEST(GpFileHeaderTest, AFileWithItsHeaderComesBackAsItIs) {
  const std::string text =
      std::string(kHeader) + "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n";
  bool headerless = true;
  EXPECT_EQ(WithGpFileHeader("GPFile_000.txt", text, &headerless), text);
  EXPECT_FALSE(headerless);
  // Another header (older biv-me files name frameID sliceID) is a header.
  const std::string older = "x\ty\tz\tcontour type\tsliceID\n1\t2\t3\tA\t1\n";
  EXPECT_EQ(WithGpFileHeader("GPFile_03.txt", older, &headerless), older);
  EXPECT_FALSE(headerless);
}

// The first row is data: biv-me's header goes before it, as many columns as
// the row has, and no row is dropped (biv-me drops the first).
TEST(GpFileHeaderTest, AFirstRowOfNumbersGetsBivMesHeader) {
  const std::string rows =
      "-42.09469\t-25.37305\t-29.46908\tSAX_RV_FREEWALL\t2\t1.0\t0\n"
      "-43.79126\t-24.26829\t-31.87508\tSAX_RV_FREEWALL\t2\t1.0\t0\n";
  bool headerless = false;
  EXPECT_EQ(WithGpFileHeader("GPFile_000.txt", rows, &headerless),
            kHeader + rows);
  EXPECT_TRUE(headerless);
  // Four fields: x, y, z and contour type; a blank line first is skipped;
  // a leading sign and spaces still read as a number.
  const std::string four = "\n +1.5\t2\t3\tAPEX_POINT\n";
  EXPECT_EQ(WithGpFileHeader("f", four, &headerless),
            "x\ty\tz\tcontour type\n" + four);
  EXPECT_TRUE(headerless);
  const std::string nine = "1\t2\t3\tA\t1\t1.0\t0\t7\t8\n";
  EXPECT_EQ(WithGpFileHeader("f", nine, &headerless),
            std::string(kHeader, sizeof(kHeader) - 2) +
                "\tcolumn 8\tcolumn 9\n" + nine);
}

TEST(GpFileHeaderTest, AHeaderlessRowOfTooFewFieldsIsNamedByItsLine) {
  bool headerless = false;
  EXPECT_EQ(InputErrorOf([&] {
              WithGpFileHeader("GPFile_001.txt", "\n1\t2\t3\n", &headerless);
            }),
            "GPFile_001.txt:2: a GPFile row without a header line needs x, y, "
            "z and contour type (biv-me's column order), got 3 fields");
  // Empty and blank files are left to the reader ("empty file, no header").
  EXPECT_EQ(WithGpFileHeader("f", "", &headerless), "");
  EXPECT_EQ(WithGpFileHeader("f", " \n\n", &headerless), " \n\n");
  EXPECT_FALSE(headerless);
}

}  // namespace
}  // namespace pfdm
