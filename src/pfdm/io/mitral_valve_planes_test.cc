#include "pfdm/io/mitral_valve_planes.h"

#include <cmath>
#include <filesystem>

#include "gtest/gtest.h"
#include "pfdm/model/model_surface.h"
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

const char kHeader[] = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";

// Issue 29: the same file under another name, read with --format gpfile,
// was closed at the rim (138.8 ml) where as GPFile_*.txt it had its plane.
TEST(MitralValvePlanesTest, TheFormatNotTheNameSaysGuidePoints) {
  const std::string dir = ScratchDirectory("gpname");
  const std::string text = std::string(kHeader) +
                           "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                           "10\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                           "0\t10\t10\tMITRAL_VALVE\t2\t1.0\t0\n";
  WriteText(dir + "/GPFile_000.txt", text);
  WriteText(dir + "/case.txt", text);
  const std::vector<BasePlane> by_name =
      MitralValvePlanes(dir + "/GPFile_000.txt", "auto");
  const std::vector<BasePlane> by_format =
      MitralValvePlanes(dir + "/case.txt", "gpfile");
  ASSERT_EQ(by_name.size(), 1u);
  ASSERT_EQ(by_format.size(), 1u);
  EXPECT_EQ(by_name[0].point, by_format[0].point);
  EXPECT_EQ(by_name[0].normal, by_format[0].normal);
  EXPECT_TRUE(MitralValvePlanes(dir + "/case.txt", "auto").empty());
  EXPECT_TRUE(MitralValvePlanes(dir + "/GPFile_000.txt", "csv").empty());
}

// A bad row or a stray valve point was once taken for a frame without valve
// points and closed at the rim; fewer than 3 points still are.
TEST(MitralValvePlanesTest, BadValvePointsAreErrorsTooFewAreNone) {
  const std::string dir = ScratchDirectory("gpbad");
  const std::string path = dir + "/GPFile_000.txt";
  WriteText(path, std::string(kHeader) +
                      "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                      "10\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n");
  EXPECT_TRUE(MitralValvePlanes(path).empty());
  WriteText(path, std::string(kHeader) +
                      "0\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                      "10\t0\t10\tMITRAL_VALVE\t1\t1.0\t0\n"
                      "0\t10\t10\tMITRAL_VALVE\t2\t1.0\t0\n"
                      "0\t10\t900000\tMITRAL_VALVE\t2\t1.0\t0\n");
  try {
    MitralValvePlanes(path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path +
                  ":5: frame 0: the point lies 899990 mm from the centre of "
                  "the frame's points, beyond any heart (500 mm)");
  }
}

// A midwall of a0 = 40 about (0, 0, 50), axis +z: apex at z = 50 - 40 a3
// = 30 (a3 = 0.5).
SequenceFit OneFrameFit() {
  SequenceFit fit;
  fit.config = ModelConfig::Paper(5);
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 40.0;
  Model model = Model::Uniform(fit.config, f);
  model.state.center = {0.0, 0.0, 50.0};
  fit.frames.resize(1);
  fit.frames[0].state = model.state;
  return fit;
}

// Issue 29: a valve plane below the apex gave a cavity of 0.0 ml, exit 0.
TEST(MitralValvePlanesTest, APlaneBeyondTheFittedApexIsRefused) {
  const SequenceFit fit = OneFrameFit();
  const Model model = fit.ModelAt(0);
  BasePlane plane;
  plane.point = Eigen::Vector3d(5.0, -3.0, 20.0);
  plane.normal = Eigen::Vector3d(0.0, 0.0, -1.0);  // Its sign is free.
  EXPECT_EQ(CavityVolumeMl(model, &plane), 0.0);   // What was reported.
  try {
    CheckPlanesBelowApex("GPFile_000.txt", {plane}, fit);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "GPFile_000.txt: frame 0: the MITRAL_VALVE plane lies 10.0 "
                 "mm beyond the fitted apex, closing no cavity; --base_plane "
                 "rim closes at the rim");
  }
  plane.point.z() = 31.0;  // 1 mm above the apex: a sliver, but a cavity.
  EXPECT_GT(CavityVolumeMl(model, &plane), 0.0);
  EXPECT_NO_THROW(CheckPlanesBelowApex("GPFile_000.txt", {plane}, fit));
  // Planes that are not one per frame are not used, nor checked.
  EXPECT_NO_THROW(CheckPlanesBelowApex("x", {plane, plane}, fit));
}

}  // namespace
}  // namespace pfdm
