#include "pfdm/fit/stages/frame_summary.h"

#include <cmath>
#include <limits>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// Data 3 mm and 4 mm off the model points along x: residuals model minus
// data, RMS sqrt((9 + 16) / 2), mean 3.5, largest 4.
TEST(FrameSummaryTest, MeasuresTheResidualsOnTheModel) {
  const Model model = TestSpheroid(5);
  FrameFit fit;
  fit.material = {{0.1, 0.2, 0.0}, {-0.5, 2.0, 0.0}};
  std::vector<Eigen::Vector3d> points;
  points.push_back(model.WorldPoint(0.1, 0.2) + Eigen::Vector3d(3, 0, 0));
  points.push_back(model.WorldPoint(-0.5, 2.0) - Eigen::Vector3d(4, 0, 0));
  Summarize(model, points, &fit);
  ASSERT_EQ(fit.residuals.size(), 2u);
  EXPECT_NEAR(fit.residuals[0].x(), -3.0, 1e-9);
  EXPECT_NEAR(fit.residuals[1].x(), 4.0, 1e-9);
  EXPECT_NEAR(fit.rms_mm, std::sqrt(12.5), 1e-9);
  EXPECT_NEAR(fit.mean_distance_mm, 3.5, 1e-9);
  EXPECT_NEAR(fit.max_distance_mm, 4.0, 1e-9);
  EXPECT_EQ(fit.state.globals, model.state.globals);
}

TEST(FrameSummaryTest, ADivergedFitIsAnErrorNamingTheFrame) {
  FrameFit fit;
  fit.frame = 3;
  fit.state = TestSpheroid(5).state;
  EXPECT_NO_THROW(CheckFinite("tags.csv", fit));
  fit.state.knots[2][kTau] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(InputErrorOf([&] { CheckFinite("tags.csv", fit); }),
            "tags.csv: frame 3: the fit diverged (its error is not finite)");
  fit.state = TestSpheroid(5).state;
  fit.rms_mm = std::numeric_limits<double>::infinity();
  EXPECT_NE(InputErrorOf([&] { CheckFinite("tags.csv", fit); }), "");
}

}  // namespace
}  // namespace pfdm
