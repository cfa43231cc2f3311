// What frame 0's ranked depths leave to the data and what they do not.  A
// solid's frame 0 gives each tag through the wall the depth w that its
// distance's rank among its band's tags says (transmural.h QuantileDepths:
// bands of latitude, each a whole ring).  A mid-wall whose section is off
// in shape but not in size (too elliptic, say) moves the tags of one side
// outward and of the other inward; ranked again, those tags take outer and
// inner ranks, and the depths explain what the data would otherwise have
// corrected.  So, to first order, the rings' ranks leave the section's
// shape about the axis to wherever the rounds start (the mid-wall fit
// before the wall decision), and frame 0's covariance, which holds the
// depths, is too sure of it: on 150 tags the mean radius (a1 + a2) / 2
// covered 87-98 % and (a1 - a2) / 2 68-78 % (docs/uncertainty.md).
//
// Shown here on the LV phantom (150 tags through the wall, 0.5 mm): frame
// 0's fit given 0.3 mm more ellipticity at every knot, then what the fit's
// end does, two rounds of (rank, search on the layers, one Gauss-Newton
// step): with the depths held the data take it out; ranked again it
// stays.
#include <cmath>
#include <optional>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/correspondence/frame_correspondence.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

constexpr int kKnots = 9;
constexpr double kEllipticityMm = 0.3;

struct FittedFrameZero {
  PointSequence sequence;
  Model model;
  std::vector<MaterialPoint> material;
  FitOptions options;
};

FittedFrameZero FitWallTags(unsigned seed, int num_tags) {
  LvPhantomOptions phantom_options;
  phantom_options.num_frames = 2;
  phantom_options.num_tags = num_tags;
  phantom_options.tags = LvTagLayer::kWall;
  phantom_options.seed = seed;
  FittedFrameZero fitted;
  fitted.sequence = MakeLvPhantom(phantom_options).points;
  fitted.options.local.enabled = false;
  const SequenceFit fit =
      FitSequence(fitted.sequence, ModelConfig::Paper(kKnots), fitted.options);
  fitted.model = fit.ModelAt(0);
  fitted.material = fit.frames[0].material;
  return fitted;
}

// (a1 - a2) / 2 at `knot`, mm.
double HalfDifference(const Model& model, int knot) {
  return 0.5 * model.state.globals[kA0] *
         (model.state.knots[knot][kA1] - model.state.knots[knot][kA2]);
}

constexpr int kJudgedKnots[] = {2, 4, 6};

// The share of kEllipticityMm added to frame 0's fit that two rounds of
// the fit's end leave at each of kJudgedKnots, the depths ranked again in
// each round or held.
std::vector<double> KeptEllipticity(const FittedFrameZero& fitted, bool rank,
                                    bool neighbourhoods = false) {
  const Frame& frame = fitted.sequence.frames[0];
  std::vector<MaterialPoint> material = fitted.material;
  std::vector<MaterialPoint> unused;
  const FramePoints points = MakeFramePoints(
      frame, true, CountFramesPerId(fitted.sequence), {}, &unused);
  std::vector<size_t> tags;
  for (size_t i : points.untracked) {
    if (points.assign_depth[i]) tags.push_back(i);
  }
  Model model = fitted.model;
  const double step = kEllipticityMm / model.state.globals[kA0];
  for (FunctionValues& values : model.state.knots) {
    values[kA1] += step;
    values[kA2] -= step;
  }
  DepthRanking ranking;
  ranking.neighbourhoods = neighbourhoods;
  DepthRanking held;
  held.hold = true;
  for (int round = 0; round < 2; ++round) {
    if (rank) RerankDepths(model, points.positions, tags, &material, ranking);
    std::vector<Eigen::Vector3d> normals(points.positions.size()), found;
    UpdateClosest(model, points.positions, tags, 1, points.layer_w,
                  points.assign_depth, /*warm=*/true, &material, &normals,
                  &found, held);
    normals = SlidingNormals(model, material, points.sliding);
    StepFrame({points.positions, material, normals, std::nullopt,
               FrameKind::kReference, fitted.model.state, fitted.model.state},
              fitted.options, &model);
  }
  std::vector<double> kept;
  for (int knot : kJudgedKnots) {
    kept.push_back(
        (HalfDifference(model, knot) - HalfDifference(fitted.model, knot)) /
        kEllipticityMm);
  }
  return kept;
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

// 150 tags, seeds 1000 and 1001: held, -0.11 to -0.03 of it kept at
// knots 2, 4 and 6; ranked again, 0.29-1.02 (means 0.69 and 0.89).
TEST(LvWallRankShapeTest, RingRanksKeepWhatTheDataWouldCorrect) {
  for (unsigned seed : {1000u, 1001u}) {
    const FittedFrameZero fitted = FitWallTags(seed, 150);
    for (double kept : KeptEllipticity(fitted, false)) {
      EXPECT_LT(std::abs(kept), 0.15) << seed;
    }
    EXPECT_GT(Mean(KeptEllipticity(fitted, true)), 0.5) << seed;
  }
}

// Ranked among each tag's nearest tags (NeighbourhoodDepths, the
// transmural local field's), a side's tags keep their spread about their
// own mid-wall and the data set the section's shape: 600 tags, seeds 1000
// and 1001, means -0.12 and -0.24 kept (each knot -0.58 to 0.10) against
// the rings' 1.16 and 0.59.  At 150 tags a neighbourhood (24 tags) is a
// sixth of the wall, and it kept -0.06 to 1.26 (not asserted).
TEST(LvWallRankShapeTest, NeighbourhoodRanksLeaveTheShapeToTheData) {
  for (unsigned seed : {1000u, 1001u}) {
    const FittedFrameZero fitted = FitWallTags(seed, 600);
    EXPECT_GT(Mean(KeptEllipticity(fitted, true)), 0.5) << seed;
    EXPECT_LT(std::abs(Mean(KeptEllipticity(fitted, true, true))), 0.35)
        << seed;
  }
}

}  // namespace
}  // namespace pfdm
