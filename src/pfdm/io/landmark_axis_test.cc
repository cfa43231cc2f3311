#include "pfdm/io/landmark_axis.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

const char kHeader[] = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";

TEST(LandmarkAxisTest, ApexPointToTheValvesCentroidOfFrameZero) {
  const std::string dir = ScratchDirectory("gp");
  WriteText(dir + "/GPFile_000.txt",
            std::string(kHeader) +
                "1\t2\t-90\tAPEX_POINT\t1\t1.0\t0\n"
                "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                "12\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                "0\t12\t10\tMITRAL_VALVE\t2\t1.0\t0\n"
                "0\t-4\t14\tAORTA_VALVE\t2\t1.0\t0\n"
                "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t0\n");
  // Frame 1 has other landmarks, and no apex: frame 0's count.
  WriteText(dir + "/GPFile_001.txt",
            std::string(kHeader) + "0\t0\t99\tMITRAL_VALVE\t1\t1.0\t1\n");
  const std::optional<AxisHint> hint = LandmarkAxis(dir);
  ASSERT_TRUE(hint.has_value());
  EXPECT_TRUE(hint->apex.isApprox(Eigen::Vector3d(1, 2, -90), 1e-12));
  EXPECT_TRUE(hint->base_center.isApprox(Eigen::Vector3d(3, 2, 11), 1e-12));
  EXPECT_EQ(hint->source, "APEX_POINT and MITRAL_VALVE, AORTA_VALVE");
  // One file is frame 0 itself.
  EXPECT_TRUE(LandmarkAxis(dir + "/GPFile_000.txt").has_value());
  EXPECT_FALSE(LandmarkAxis(dir + "/GPFile_001.txt").has_value());
}

TEST(LandmarkAxisTest, NoneWithoutBothLandmarksOrGuidePoints) {
  const std::string dir = ScratchDirectory("gp");
  WriteText(dir + "/GPFile_000.txt",
            std::string(kHeader) + "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n" +
                "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t0\n");
  EXPECT_FALSE(LandmarkAxis(dir).has_value());
  WriteText(dir + "/tags.csv", "frame,id,x,y,z\n0,0,1,2,3\n");
  EXPECT_FALSE(LandmarkAxis(dir + "/tags.csv").has_value());
  EXPECT_FALSE(LandmarkAxis(ScratchDirectory("empty")).has_value());
  const std::string mitral = ScratchDirectory("mitral");
  WriteText(mitral + "/GPFile_000.txt",
            std::string(kHeader) + "1\t2\t-90\tAPEX_POINT\t1\t1.0\t0\n" +
                "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n");
  EXPECT_EQ(LandmarkAxis(mitral)->source, "APEX_POINT and MITRAL_VALVE");
}

// --apex/--base come first.
TEST(LandmarkAxisTest, KeepsTheUsersHint) {
  const std::string dir = ScratchDirectory("gp");
  WriteText(dir + "/GPFile_000.txt", std::string(kHeader) +
                                         "1\t2\t-90\tAPEX_POINT\t1\t1.0\t0\n" +
                                         "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n");
  FitOptions options;
  AddLandmarkAxis(dir, &options);
  ASSERT_TRUE(options.hint.has_value());
  EXPECT_EQ(options.hint->source, "APEX_POINT and MITRAL_VALVE");
  options.hint = AxisHint{{0, 0, 0}, {0, 0, 1}};
  AddLandmarkAxis(dir, &options);
  EXPECT_EQ(options.hint->source, "--apex/--base");
  EXPECT_EQ(options.hint->apex, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace pfdm
