#include "pfdm/model/base_plane.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(BasePlaneTest, LeastSquaresPlaneThroughPoints) {
  // z = 2x + 1: normal along (2, 0, -1).
  std::vector<Eigen::Vector3d> points;
  for (double x : {0.0, 1.0, 3.0}) {
    for (double y : {-1.0, 2.0}) points.emplace_back(x, y, 2 * x + 1);
  }
  const std::optional<BasePlane> plane = FitBasePlane(points);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(
      std::abs(plane->normal.dot(Eigen::Vector3d(2, 0, -1).normalized())), 1.0,
      1e-12);
  EXPECT_NEAR(plane->point.z(), 2 * plane->point.x() + 1, 1e-12);
  EXPECT_EQ(plane->num_points, 6);
  EXPECT_FALSE(FitBasePlane({{0, 0, 0}, {1, 1, 1}}).has_value());
  EXPECT_FALSE(FitBasePlane({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).has_value());
}

TEST(BasePlaneTest, MitralPlanesFromGuidePointFilesOrNone) {
  const std::string dir = ScratchDirectory("gp");
  const std::string header =
      "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";
  WriteText(dir + "/GPFile_000.txt",
            header +
                "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                "10\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                "0\t10\t10\tMITRAL_VALVE\t2\t1.0\t0\n"
                "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t0\n");
  WriteText(dir + "/GPFile_001.txt", header +
                                         "0\t0\t8\tMITRAL_VALVE\t1\t1.0\t1\n"
                                         "10\t0\t8\tMITRAL_VALVE\t1\t1.0\t1\n"
                                         "0\t10\t9\tMITRAL_VALVE\t2\t1.0\t1\n");
  const std::vector<BasePlane> planes = MitralValvePlanes(dir);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_NEAR(planes[0].point.z(), 10.0, 1e-12);
  EXPECT_NEAR(std::abs(planes[0].normal.z()), 1.0, 1e-12);
  EXPECT_EQ(planes[1].num_points, 3);
  // A frame without valve points: no planes at all (the flat lid for all).
  WriteText(dir + "/GPFile_002.txt",
            header + "5\t5\t-30\tSAX_LV_ENDOCARDIAL\t3\t1.0\t2\n");
  EXPECT_TRUE(MitralValvePlanes(dir).empty());
  EXPECT_TRUE(MitralValvePlanes(dir + "/tags.csv").empty());
}

}  // namespace
}  // namespace pfdm
