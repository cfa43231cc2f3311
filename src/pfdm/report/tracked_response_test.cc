#include "pfdm/report/tracked_response.h"

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

using Kind = CovarianceEntry::Kind;

// ED and ES of the LV phantom's 400 tags on `layer`.
PointSequence LvTags(LvTagLayer layer) {
  LvPhantomOptions phantom;
  phantom.num_frames = 2;
  phantom.num_tags = 400;
  phantom.tags = layer;
  phantom.seed = 7;
  return MakeLvPhantom(phantom).points;
}

// The LV phantom's ED twice: frame 1's tags where frame 0's are.
SequenceFit FitStill(LvTagLayer layer) {
  PointSequence points = LvTags(layer);
  points.frames[1].points = points.frames[0].points;
  FitOptions options;
  options.uncertainty = true;
  return FitSequence(points, ModelConfig::Paper(9), options);
}

// Response of frame 1's function f at knot k to a step of frame 0's f at
// every knot alike.
double Follows(const SequenceFit& fit, const Eigen::MatrixXd& response, int f,
               int k) {
  const int row = fit.frames[1].covariance.IndexOf(Kind::kKnot, k, f);
  EXPECT_GE(row, 0);
  double sum = 0.0;
  for (int j = 0; j < fit.config.num_knots; ++j) {
    const int column = fit.frames[0].covariance.IndexOf(Kind::kKnot, j, f);
    if (row >= 0 && column >= 0) sum += response(row, column);
  }
  return sum;
}

// Through the wall, with depths held, a tag's material point is wherever
// frame 0's model puts the tag: a frame whose tags stand still redraws frame
// 0's model, errors and all, so it follows a step of frame 0's radius
// one for one and its neighbours' hardly.
TEST(TrackedResponseTest, AStillWallFollowsFrameZerosRadius) {
  const SequenceFit fit = FitStill(LvTagLayer::kWall);
  ASSERT_TRUE(fit.config.Solid());
  ASSERT_TRUE(fit.frames[1].depths_held);
  const Eigen::MatrixXd response = MeasureTrackedResponse(fit, 1).Total();
  ASSERT_EQ(response.rows(),
            static_cast<int>(fit.frames[1].covariance.entries.size()));
  ASSERT_EQ(response.cols(),
            static_cast<int>(fit.frames[0].covariance.entries.size()));
  for (int k : {2, 4, 6}) {
    EXPECT_NEAR(Follows(fit, response, kA1, k), 1.0, 0.1) << k;
    EXPECT_NEAR(Follows(fit, response, kA2, k), 1.0, 0.1) << k;
  }
}

// Through the wall most of it is the depths': the (u, v) part alone follows
// a radial step about as a surface does (next test), the depths' part the
// rest; on one surface there is no depths' part.
TEST(TrackedResponseTest, ThroughTheWallMostOfItIsTheDepths) {
  const SequenceFit fit = FitStill(LvTagLayer::kWall);
  const TrackedResponse wall = MeasureTrackedResponse(fit, 1);
  ASSERT_FALSE(wall.Empty());
  ASSERT_EQ(wall.through_wall.rows(), wall.along_surface.rows());
  for (int k : {2, 4, 6}) {
    const double along = Follows(fit, wall.along_surface, kA1, k);
    const double depths = Follows(fit, wall.through_wall, kA1, k);
    EXPECT_LT(std::abs(along), 0.45) << k;
    EXPECT_GT(depths, 0.55) << k;
    EXPECT_NEAR(along + depths, 1.0, 0.1) << k;
  }
  const TrackedResponse surface =
      MeasureTrackedResponse(FitStill(LvTagLayer::kMidwall), 1);
  ASSERT_FALSE(surface.Empty());
  EXPECT_EQ(surface.through_wall.size(), 0);
}

// On one surface a tag's material point moves along the surface alone: of
// a step of frame 0's radius only the part along the inclined wall moves
// it, and the frame follows that part (0.36, 0.26 and 0.23 at knots 2, 4
// and 6: less toward the base, where the wall stands upright), not the
// whole step.
TEST(TrackedResponseTest, AStillSurfaceDoesNotFollowARadialStep) {
  const SequenceFit fit = FitStill(LvTagLayer::kMidwall);
  ASSERT_FALSE(fit.config.Solid());
  const Eigen::MatrixXd response = MeasureTrackedResponse(fit, 1).Total();
  ASSERT_GT(response.size(), 0);
  for (int k : {2, 4, 6}) {
    EXPECT_LT(std::abs(Follows(fit, response, kA1, k)), 0.45) << k;
  }
}

// The response is the global fit's (the covariance's, fitted before the
// local field): the field through the wall, fitted after it, changes the
// fit's numbers but not M.
TEST(TrackedResponseTest, TheLocalFieldDoesNotChangeIt) {
  const PointSequence points = LvTags(LvTagLayer::kWall);
  FitOptions options;
  options.uncertainty = true;
  const SequenceFit bilinear =
      FitSequence(points, ModelConfig::Paper(9), options);
  options.local.transmural = true;
  const SequenceFit transmural =
      FitSequence(points, ModelConfig::Paper(9), options);
  ASSERT_EQ(bilinear.frames[1].state.knots, transmural.frames[1].state.knots);
  ASSERT_FALSE(transmural.frames[1].state.local.empty());
  const Eigen::MatrixXd a = MeasureTrackedResponse(bilinear, 1).Total();
  const Eigen::MatrixXd b = MeasureTrackedResponse(transmural, 1).Total();
  ASSERT_GT(a.size(), 0);
  EXPECT_EQ(a, b);
}

// No response where frame t's material points are not frame 0's alone, or
// where end-diastole is not frame 0 (the delta method steps ED).
TEST(TrackedResponseTest, NoneWhereItDoesNotApply) {
  SequenceFit fit = FitStill(LvTagLayer::kMidwall);
  EXPECT_EQ(MeasureTrackedResponse(fit, 0).Total().size(), 0);
  EXPECT_EQ(MeasureTrackedResponse(fit, 2).Total().size(), 0);
  fit.frames[1].mixed = true;
  EXPECT_EQ(MeasureTrackedResponse(fit, 1).Total().size(), 0);
  fit.frames[1].mixed = false;
  fit.ed_frame = 1;
  EXPECT_EQ(MeasureTrackedResponse(fit, 1).Total().size(), 0);
  fit.ed_frame = 0;
  fit.frames[1].covariance.unit_covariance.resize(0, 0);
  EXPECT_EQ(MeasureTrackedResponse(fit, 1).Total().size(), 0);
}

}  // namespace
}  // namespace pfdm
