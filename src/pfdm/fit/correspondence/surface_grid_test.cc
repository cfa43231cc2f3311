#include "pfdm/fit/correspondence/surface_grid.h"

#include <cmath>
#include <limits>
#include <random>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// The tree's nearest sample is the brute-force nearest of the grid's world
// points, to the last bit of its distance.
TEST(SurfaceGridTest, NearestSampleIsTheBruteForceNearest) {
  const Model model = TwistedTestModel();
  const SurfaceGrid grid(model);
  const int samples = SurfaceGrid::kGridU * SurfaceGrid::kGridV;
  std::vector<MaterialPoint> all;
  for (int i = 0; i < samples; ++i) all.push_back(grid.Sample(i));
  const std::vector<Eigen::Vector3d> world = WorldPoints(model, all);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-60.0, 60.0);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d p(coordinate(random), coordinate(random),
                            coordinate(random) - 30.0);
    double best = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& x : world) {
      best = std::min(best, (x - p).squaredNorm());
    }
    const SurfaceGrid::Nearest nearest = grid.NearestTo(p);
    EXPECT_NEAR(nearest.distance_squared, best, 1e-9 * best) << k;
    EXPECT_NEAR((world[nearest.index] - p).squaredNorm(), best, 1e-9 * best);
  }
}

// A search from a grid shared between searches finds what a search that
// builds its own finds, bit for bit, on the mid-wall and on a wall.
TEST(SurfaceGridTest, SharedGridFindsTheSamePoints) {
  Model model = TwistedTestModel();
  const SurfaceGrid grid(model);
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 1.5);
  std::vector<Eigen::Vector3d> points;
  for (double u = -1.4; u < 0.6; u += 0.1) {
    for (double v = -3.1; v < 3.1; v += 0.3) {
      points.push_back(model.WorldPoint(u, v) + Eigen::Vector3d(noise(random),
                                                                noise(random),
                                                                noise(random)));
    }
  }
  CorrespondenceOptions options;
  const auto own = ClosestMaterialPoints(model, points, options);
  const auto shared = ClosestMaterialPointsFrom(grid, model, points, options);
  ASSERT_EQ(own.size(), shared.size());
  for (size_t i = 0; i < own.size(); ++i) {
    EXPECT_EQ(own[i].u, shared[i].u) << i;
    EXPECT_EQ(own[i].v, shared[i].v) << i;
  }
}

// A grid that follows a moving model answers as a grid built of it, to the
// bit, whether it keeps its tree (moved less than kRebuildMm) or not: 400
// points about the surface at each of three moves.
TEST(SurfaceGridTest, FollowingGridAnswersAsAFreshOne) {
  Model model = TwistedTestModel();
  SurfaceGrid following(model);
  EXPECT_EQ(following.builds(), 1);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 2.0);
  std::uniform_real_distribution<double> u(-1.5, 0.6), v(-M_PI, M_PI);
  // Moves: a shift and a bulge within the tolerance, then a larger shift.
  const double shifts[] = {0.6, 0.0, 3.0};
  const double bulges[] = {0.0, 0.01, 0.0};
  const int builds[] = {1, 1, 2};
  for (int step = 0; step < 3; ++step) {
    model.state.center[0] += shifts[step];
    for (FunctionValues& knot : model.state.knots) knot[kA1] += bulges[step];
    following.Follow(model);
    EXPECT_EQ(following.builds(), builds[step]) << step;
    const SurfaceGrid fresh(model);
    for (int k = 0; k < 400; ++k) {
      const Eigen::Vector3d p =
          model.WorldPoint(u(random), v(random)) +
          Eigen::Vector3d(noise(random), noise(random), noise(random));
      const SurfaceGrid::Nearest a = following.NearestTo(p);
      const SurfaceGrid::Nearest b = fresh.NearestTo(p);
      // The apex ring's samples are one point: any of them is the nearest
      // (the search takes its v from the point, not the sample).
      const size_t ring = SurfaceGrid::kGridV;
      EXPECT_TRUE(a.index == b.index || (a.index < ring && b.index < ring))
          << step << " " << k << ": " << a.index << " " << b.index;
      EXPECT_EQ(a.distance_squared, b.distance_squared) << step << " " << k;
    }
  }
}

// A bounded search answers as the unbounded one where its sample is nearer
// than the bound, and not at all where it is not, on a fresh grid and on
// one that followed the model 1 mm (kept its tree): bounds a hair above
// and below each nearest distance, and a hint's typical 1 mm.
TEST(SurfaceGridTest, BoundedSearchFindsOnlyNearerSamples) {
  Model model = TwistedTestModel();
  SurfaceGrid following(model);
  model.state.center[1] += 1.0;
  following.Follow(model);
  ASSERT_EQ(following.builds(), 1);
  const SurfaceGrid fresh(model);
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 2.0);
  std::uniform_real_distribution<double> u(-1.5, 0.6), v(-M_PI, M_PI);
  int found_within_a_millimetre = 0;
  for (const SurfaceGrid* grid :
       std::initializer_list<const SurfaceGrid*>{&fresh, &following}) {
    for (int k = 0; k < 300; ++k) {
      const Eigen::Vector3d p =
          model.WorldPoint(u(random), v(random)) +
          Eigen::Vector3d(noise(random), noise(random), noise(random));
      const SurfaceGrid::Nearest nearest = grid->NearestTo(p);
      const double d = nearest.distance_squared;
      const std::optional<SurfaceGrid::Nearest> above =
          grid->NearestWithin(p, d * (1.0 + 1e-12));
      ASSERT_TRUE(above.has_value()) << k;
      EXPECT_EQ(above->index, nearest.index) << k;
      EXPECT_EQ(above->distance_squared, d) << k;
      EXPECT_FALSE(grid->NearestWithin(p, d).has_value()) << k;
      EXPECT_FALSE(grid->NearestWithin(p, d * (1.0 - 1e-12)).has_value());
      const std::optional<SurfaceGrid::Nearest> hint =
          grid->NearestWithin(p, 1.0);
      EXPECT_EQ(hint.has_value(), d < 1.0) << k;
      if (hint) {
        EXPECT_EQ(hint->index, nearest.index) << k;
        ++found_within_a_millimetre;
      }
    }
  }
  EXPECT_GT(found_within_a_millimetre, 10);
}

}  // namespace
}  // namespace pfdm
