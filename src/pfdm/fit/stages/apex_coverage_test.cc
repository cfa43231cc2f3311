#include "pfdm/fit/stages/apex_coverage.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// A frame-0 fit of the paper's model, upright at the origin (a0 50 mm,
// a3 0.8: the apex pole 40 mm below the origin, the rim 20 mm above),
// with points on it at these u.
SequenceFit FitWithPointsAt(const std::vector<double>& us,
                            std::vector<Eigen::Vector3d>* points) {
  SequenceFit fit;
  fit.config = ModelConfig::Paper(17);
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = 0.5;
  values[kA3] = 0.8;
  const Model model = Model::Uniform(fit.config, values);
  FrameFit frame;
  frame.state = model.state;
  for (double u : us) {
    for (double v : {-2.0, 0.0, 2.0}) {
      frame.material.push_back(MaterialPoint{u, v});
      points->push_back(model.WorldPoint(u, v));
    }
  }
  fit.frames.push_back(frame);
  return fit;
}

TEST(ApexCoverageTest, DataAtTheApex) {
  std::vector<Eigen::Vector3d> points;
  SequenceFit fit = FitWithPointsAt({-1.5, -0.5, 0.3}, &points);
  MeasureApexCoverage(points, &fit);
  EXPECT_TRUE(fit.apex_in_data);
  EXPECT_TRUE(ApexInData(fit.ModelAt(0), points));
  // Height fraction (sin u + 1) / (sin u_max + 1), u_max = pi / 6.
  EXPECT_NEAR(fit.lowest_data_height, (std::sin(-1.5) + 1) / 1.5, 1e-9);
  EXPECT_NEAR(fit.lowest_data_u, -1.5, 1e-12);
  EXPECT_LT(fit.apex_data_distance, kApexReach);
}

// A mid-ventricular segment: the lowest ring 25 % of the length up, 38 mm
// across, farther than 15 % of the length (60 mm) from the apex pole.
TEST(ApexCoverageTest, NoDataNearTheApex) {
  std::vector<Eigen::Vector3d> points;
  SequenceFit fit = FitWithPointsAt({-0.7, 0.0, 0.5}, &points);
  MeasureApexCoverage(points, &fit);
  EXPECT_FALSE(fit.apex_in_data);
  EXPECT_FALSE(ApexInData(fit.ModelAt(0), points));
  EXPECT_NEAR(fit.lowest_data_height, (std::sin(-0.7) + 1) / 1.5, 1e-9);
  EXPECT_NEAR(fit.lowest_data_u, -0.7, 1e-12);
  const double height = 40 * (std::sin(-0.7) + 1);
  const double radius = 25 * std::cos(0.7);
  EXPECT_NEAR(fit.apex_data_distance, std::hypot(height, radius) / 60.0, 1e-9);
  // 0.40 of the length away: within a wider reach.
  EXPECT_FALSE(ApexInData(fit.ModelAt(0), points, 0.39));
  EXPECT_TRUE(ApexInData(fit.ModelAt(0), points, 0.41));
}

// Two points near the apex are not enough (kApexPoints): an outlier or two
// there do not make an apex.
TEST(ApexCoverageTest, AFewPointsNearTheApexAreNotIt) {
  std::vector<Eigen::Vector3d> points;
  SequenceFit fit = FitWithPointsAt({0.0, 0.5}, &points);
  const Model model = fit.ModelAt(0);
  points.push_back(model.WorldPoint(-1.5, 0.0));
  points.push_back(model.WorldPoint(-1.5, 1.0));
  fit.frames[0].material.push_back(MaterialPoint{-1.5, 0.0});
  fit.frames[0].material.push_back(MaterialPoint{-1.5, 1.0});
  MeasureApexCoverage(points, &fit);
  EXPECT_FALSE(fit.apex_in_data);
  EXPECT_FALSE(ApexInData(model, points));
  // A third point there is.
  points.push_back(model.WorldPoint(-1.5, 2.0));
  EXPECT_TRUE(ApexInData(model, points));
  points.pop_back();
  EXPECT_NEAR(fit.apex_data_distance, 25 * std::cos(1.5) / 60, 1e-3);
}

}  // namespace
}  // namespace pfdm
