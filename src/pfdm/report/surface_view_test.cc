#include "pfdm/report/surface_view.h"

#include <cstring>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/model/model_surface.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/fit_report.h"
#include "pfdm/report/viewer_script.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

// The largest distance (mm) between a surface's vertices and the scene's
// integers times its step.
double LargestRoundingMm(const std::vector<Eigen::Vector3d>& points,
                         const nlohmann::json& ints, double step) {
  EXPECT_EQ(ints.size(), 3 * points.size());
  double largest = 0.0;
  for (size_t i = 0; i < points.size() && 3 * i + 2 < ints.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      largest = std::max(
          largest,
          std::abs(ints[3 * i + c].get<double>() * step - points[i][c]));
    }
  }
  return largest;
}

// The scene read back: the phantom's points and the surfaces that
// MakeModelSurface samples, within half the 0.1 mm step.
TEST(SurfaceViewTest, SceneJsonRoundTrips) {
  PhantomOptions options;
  options.num_frames = 3;
  options.num_points = 120;
  const Phantom phantom = MakePhantom(options);
  const nlohmann::json scene = nlohmann::json::parse(
      SceneJson(phantom.points, phantom.truth, {0.0, 40.0, 80.0}, 0, 2));
  EXPECT_DOUBLE_EQ(scene["scale"].get<double>(), 0.1);
  EXPECT_EQ(scene["point_stride"].get<int>(), 1);
  EXPECT_EQ(scene["frame_ms"].get<int>(), 40);
  ASSERT_EQ(scene["frames"].size(), 3u);
  ASSERT_EQ(scene["walls"].size(), 1u);
  EXPECT_EQ(scene["walls"][0]["name"], "fitted surface");
  EXPECT_EQ(scene["frames"][0]["label"], "frame 0, 0 ms (ED)");
  EXPECT_EQ(scene["frames"][2]["label"], "frame 2, 80 ms (ES)");
  const ModelSurface first = MakeModelSurface(phantom.truth[0], 24, 36);
  EXPECT_EQ(scene["triangles"].size(), 3 * first.mesh.triangles.size());
  EXPECT_EQ(scene["triangles"][5].get<int>(), first.mesh.triangles[1][2]);
  for (int t = 0; t < 3; ++t) {
    const nlohmann::json& frame = scene["frames"][t];
    std::vector<Eigen::Vector3d> data;
    for (const DataPoint& p : phantom.points.frames[t].points) {
      data.push_back(p.position);
    }
    EXPECT_LE(LargestRoundingMm(data, frame["points"], 0.1), 0.05 + 1e-9);
    const ModelSurface surface = MakeModelSurface(phantom.truth[t], 24, 36);
    EXPECT_LE(LargestRoundingMm(surface.mesh.points, frame["surfaces"][0], 0.1),
              0.05 + 1e-9);
  }
  // Without times, frames by number only, played at 120 ms a frame.
  const nlohmann::json untimed =
      nlohmann::json::parse(SceneJson(phantom.points, phantom.truth, {}, 0, 1));
  EXPECT_EQ(untimed["frames"][1]["label"], "frame 1 (ES)");
  EXPECT_EQ(untimed["frame_ms"].get<int>(), 120);
}

// A frame of more than max_points shows every k-th point: 10,000 of at
// most 4,000 every 3rd, 3,334 of them.
TEST(SurfaceViewTest, ManyPointsAreThinned) {
  EXPECT_EQ(PointStride(4000, 4000), 1);
  EXPECT_EQ(PointStride(4001, 4000), 2);
  EXPECT_EQ(PointStride(10000, 4000), 3);
  PhantomOptions options;
  options.num_frames = 2;
  options.num_points = 10000;
  const Phantom phantom = MakePhantom(options);
  const nlohmann::json scene =
      nlohmann::json::parse(SceneJson(phantom.points, phantom.truth, {}, 0, 1));
  EXPECT_EQ(scene["point_stride"].get<int>(), 3);
  ASSERT_EQ(scene["frames"][1]["points"].size(), 3u * 3334);
  const Eigen::Vector3d& third = phantom.points.frames[1].points[3].position;
  EXPECT_NEAR(scene["frames"][1]["points"][3].get<double>() * 0.1, third.x(),
              0.05 + 1e-9);
}

// A solid's scene holds its endocardium (w = -1) and epicardium (w = 1).
TEST(SurfaceViewTest, SolidShowsBothWalls) {
  PhantomOptions options;
  options.num_frames = 2;
  options.num_points = 30;
  Phantom phantom = MakePhantom(options);
  for (Model& model : phantom.truth) {
    model.config.MakeSolid();
    model.state.globals[kH] = 8.0;
    for (FunctionValues& knot : model.state.knots) knot[kH] = 8.0;
  }
  const nlohmann::json scene =
      nlohmann::json::parse(SceneJson(phantom.points, phantom.truth, {}, 0, 1));
  ASSERT_EQ(scene["walls"].size(), 2u);
  EXPECT_EQ(scene["walls"][0]["name"], "endocardium");
  EXPECT_EQ(scene["walls"][1]["name"], "epicardium");
  for (int k = 0; k < 2; ++k) {
    const ModelSurface wall =
        MakeModelSurface(phantom.truth[1], 24, 36, {}, k == 0 ? -1.0 : 1.0);
    EXPECT_LE(LargestRoundingMm(wall.mesh.points,
                                scene["frames"][1]["surfaces"][k], 0.1),
              0.05 + 1e-9);
  }
  EXPECT_NE(scene["frames"][1]["surfaces"][0],
            scene["frames"][1]["surfaces"][1]);
}

// The page the docs state the size of: 25 frames of 2,000 tags, under
// 3 MB with the plots (a few hundred kB) added.
TEST(SurfaceViewTest, PageOf25FramesOf2000PointsIsSmall) {
  PhantomOptions options;
  options.num_frames = 25;
  options.num_points = 2000;
  const Phantom phantom = MakePhantom(options);
  const SequenceFit fit = TruthAsFit(phantom);
  const std::string html =
      FitReportHtml(phantom.points, fit, AnalyzeFit(fit), "", "");
  const size_t script = std::strlen(kViewerScript);
  std::printf("page %zu bytes, of which the script %zu\n", html.size(), script);
  EXPECT_LT(html.size(), 2500000u);
  EXPECT_GT(html.size(), script + 25 * 2000 * 3 * 3);  // The points are in.
  EXPECT_NE(html.find("<canvas"), std::string::npos);
  EXPECT_NE(html.find("id=\"pfdm-scene\""), std::string::npos);
}

// The bundle can stand in the page: three.js is in it, and nothing closes
// the script early.
TEST(SurfaceViewTest, ViewerScriptIsInlinable) {
  const std::string script = kViewerScript;
  EXPECT_GT(script.size(), 200000u);
  EXPECT_LT(script.size(), 1000000u);
  EXPECT_EQ(script.find("</script"), std::string::npos);
  EXPECT_NE(script.find("pfdm-scene"), std::string::npos);
  EXPECT_NE(script.find("WebGL"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
