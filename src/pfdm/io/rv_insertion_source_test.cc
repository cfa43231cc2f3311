#include "pfdm/io/rv_insertion_source.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

const char kHeader[] = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";

TEST(RvInsertionSourceTest, FlagGivesTheAnteriorAndTheInferior) {
  EXPECT_FALSE(ParseRvInsertion("").has_value());
  const std::optional<RvInsertion> one = ParseRvInsertion("1,-2.5,3e1");
  ASSERT_TRUE(one.has_value());
  EXPECT_EQ(one->source, "--rv_insertion");
  ASSERT_EQ(one->anterior.size(), 1u);
  EXPECT_TRUE(one->anterior[0].isApprox(Eigen::Vector3d(1, -2.5, 30)));
  EXPECT_TRUE(one->inferior.empty());
  const std::optional<RvInsertion> two = ParseRvInsertion("1,2,3,4,5,6");
  ASSERT_EQ(two->inferior.size(), 1u);
  EXPECT_TRUE(two->inferior[0].isApprox(Eigen::Vector3d(4, 5, 6)));
  for (const char* bad : {"1,2", "1,2,3,4", "1,2,x", "1,,3", "1,2,3,",
                          "nan,1,2", "1,2,1e9", "1,2,3,1,2,3.5"}) {
    EXPECT_NE(
        InputErrorOf([&] { ParseRvInsertion(bad); }).find("--rv_insertion"),
        std::string::npos)
        << bad;
  }
}

TEST(RvInsertionSourceTest, GuidePointsGiveFrameZerosRvInsertPoints) {
  const std::string dir = ScratchDirectory("gp");
  WriteText(dir + "/GPFile_000.txt",
            std::string(kHeader) +
                "1\t2\t3\tRV_INSERT\t2\t1.0\t0\n"
                "4\t5\t6\tRV_INSERT\t2\t1.0\t0\n"
                "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t0\n");
  WriteText(dir + "/GPFile_001.txt",
            std::string(kHeader) + "9\t9\t9\tRV_INSERT\t2\t1.0\t1\n");
  const std::optional<RvInsertion> found = RvInsertionFrom("", dir);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->source, "2 RV_INSERT points of GPFile_000.txt");
  ASSERT_EQ(found->unlabelled.size(), 2u);
  EXPECT_TRUE(found->unlabelled[1].isApprox(Eigen::Vector3d(4, 5, 6)));
  EXPECT_TRUE(found->anterior.empty());
  // The flag comes first.
  EXPECT_EQ(RvInsertionFrom("0,0,0", dir)->source, "--rv_insertion");
  // None: other guide points, or not guide points.
  const std::string none = ScratchDirectory("none");
  WriteText(
      none + "/GPFile_000.txt",
      std::string(kHeader) + "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t0\n");
  EXPECT_FALSE(RvInsertionFrom("", none).has_value());
  WriteText(none + "/tags.csv", "frame,id,x,y,z\n0,0,1,2,3\n");
  EXPECT_FALSE(RvInsertionFrom("", none + "/tags.csv").has_value());
}

}  // namespace
}  // namespace pfdm
