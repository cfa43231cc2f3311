#include "pfdm/io/point_source.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(PointSourceTest, ChoosesTheReaderByTheFilesKind) {
  const std::string dir = ScratchDirectory("source");
  WriteText(dir + "/tags.csv", "frame,id,x,y,z\n0,7,1,2,3\n");
  EXPECT_EQ(
      ReadPoints(dir + "/tags.csv", "auto", "lv-endo").frames[0].points[0].id,
      7);
  WriteText(dir + "/GPFile_000.txt",
            "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n"
            "1\t2\t3\tSAX_LV_ENDOCARDIAL\t1\t1.0\t0\n"
            "4\t5\t6\tSAX_RV_FREEWALL\t1\t1.0\t0\n");
  const PointSequence gp =
      ReadPoints(dir + "/GPFile_000.txt", "auto", "lv-endo");
  ASSERT_EQ(gp.frames[0].points.size(), 1u);
  EXPECT_EQ(gp.frames[0].points[0].position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(
      ReadPoints(dir + "/GPFile_000.txt", "gpfile", "").frames[0].points.size(),
      2u);
  EXPECT_THROW(ReadPoints(dir + "/tags.csv", "xml", ""), InputError);
}

TEST(PointSourceTest, TheFormatIsTheFlagsOrByName) {
  const std::string dir = ScratchDirectory("format");
  EXPECT_EQ(PointFormatOf(dir, "auto"), PointFormat::kGpFile);
  EXPECT_EQ(PointFormatOf(dir + "/GPFile_003.txt", "auto"),
            PointFormat::kGpFile);
  EXPECT_EQ(PointFormatOf(dir + "/case.txt", "auto"), PointFormat::kCsv);
  EXPECT_EQ(PointFormatOf(dir + "/case.txt", "gpfile"), PointFormat::kGpFile);
  EXPECT_EQ(PointFormatOf(dir + "/GPFile_003.txt", "csv"), PointFormat::kCsv);
  try {
    PointFormatOf(dir, "xml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "unknown --format 'xml' (expected csv, gpfile or auto)");
  }
}

}  // namespace
}  // namespace pfdm
