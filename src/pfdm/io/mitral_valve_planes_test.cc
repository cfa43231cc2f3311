#include "pfdm/io/mitral_valve_planes.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(MitralValvePlanesTest, FromGuidePointFilesOrNone) {
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

// Six copies of one point were taken as a plane and changed the volume
// (issue 14).
TEST(MitralValvePlanesTest, PointsAtOnePlaceAreAnError) {
  const std::string dir = ScratchDirectory("gp");
  std::string text = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";
  for (int i = 0; i < 6; ++i) text += "1\t2\t3\tMITRAL_VALVE\t1\t1.0\t0\n";
  WriteText(dir + "/GPFile_000.txt", text);
  try {
    MitralValvePlanes(dir);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir +
                  ": frame 0: its 6 MITRAL_VALVE points lie at one place or "
                  "on a line, no plane; --base_plane rim closes at the rim");
  }
}

}  // namespace
}  // namespace pfdm
