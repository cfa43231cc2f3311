#include "pfdm/fit/correspondence/transmural.h"

#include <cmath>
#include <random>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Distances uniform across a 10 mm wall: ranks give w uniform in (-1, 1),
// and the slope of distance on w gives the thickness back.
TEST(TransmuralDepthTest, RanksOfAUniformWallGiveItsThickness) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> across(-5.0, 5.0), along(-1.5, 0.5);
  std::vector<double> u, distances;
  for (int i = 0; i < 4000; ++i) {
    u.push_back(along(random));
    distances.push_back(across(random));
  }
  const std::vector<double> w = QuantileDepths(u, distances);
  double lowest = 1.0, highest = -1.0;
  for (size_t i = 0; i < w.size(); ++i) {
    lowest = std::min(lowest, w[i]);
    highest = std::max(highest, w[i]);
    // Ranks among 250 tags of a band: within 0.2 (the DKW bound, 2 x 1.36 /
    // sqrt(250), at 95 %).
    EXPECT_NEAR(w[i], distances[i] / 5.0, 0.2) << i;
  }
  EXPECT_LT(lowest, -0.99);
  EXPECT_GT(highest, 0.99);
  EXPECT_NEAR(ThicknessFromDepths(distances, w), 10.0, 0.15);
}

// Few points: one band, ranks still spread over (-1, 1).
TEST(TransmuralDepthTest, FewPointsMakeOneBand) {
  const std::vector<double> w =
      QuantileDepths({0.0, 0.1, 0.2, 0.3}, {3.0, -1.0, 2.0, 0.0});
  EXPECT_EQ(w, (std::vector<double>{0.75, -0.75, 0.25, -0.25}));
}

// Noise sigma widens ranked distances to h + 6 sigma^2 / h; the
// deconvolution gives h back.
TEST(TransmuralDepthTest, DeconvolutionUndoesTheNoisesWidening) {
  for (double h : {4.0, 9.0, 14.0}) {
    const double sigma = 0.5;
    EXPECT_NEAR(DeconvolvedThickness(h + 6.0 * sigma * sigma / h, sigma), h,
                1e-9);
  }
  EXPECT_EQ(DeconvolvedThickness(9.0, 0.0), 9.0);
  EXPECT_EQ(DeconvolvedThickness(1.0, 1.0), 0.5);  // No real root.
  // Simulated: uniform across 8 mm plus Gaussian noise of 0.6 mm.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> across(-4.0, 4.0);
  std::normal_distribution<double> noise(0.0, 0.6);
  std::vector<double> u(200000, 0.0), distances;
  for (size_t i = 0; i < u.size(); ++i) {
    distances.push_back(across(random) + noise(random));
  }
  const double h_obs =
      ThicknessFromDepths(distances, QuantileDepths(u, distances));
  EXPECT_NEAR(h_obs, 8.0 + 6.0 * 0.36 / 8.0, 0.03);
  EXPECT_NEAR(DeconvolvedThickness(h_obs, 0.6), 8.0, 0.03);
}

// Neighbours along the wall: points spread through it read its thickness;
// points on one surface that it misses alike read nothing.  60,000 points
// take their neighbours among a quarter of them.
TEST(TransmuralDepthTest, WallSpreadComparesNeighbours) {
  const Model model = TestSpheroid(9);
  for (int num_points : {3000, 60000}) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.4, 0.4), v(-3.1, 3.1),
        across(-4.0, 4.0);
    std::vector<MaterialPoint> material;
    std::vector<double> wall, missed;
    for (int i = 0; i < num_points; ++i) {
      material.push_back({u(random), v(random), 0.0});
      wall.push_back(across(random));
      missed.push_back(6.0 + 2.0 * std::sin(material.back().u));
    }
    const std::vector<Eigen::Vector3d> midwall = WorldPoints(model, material);
    EXPECT_NEAR(WallSpreadMm(midwall, wall), 8.0, 0.5) << num_points;
    EXPECT_LT(WallSpreadMm(midwall, missed), 0.5) << num_points;
  }
}

// Left out of the ranks, tags take -1 or +1 by their side, and the others
// rank among themselves: 0.5 mm of ranked distances over (-1, 1) again.
TEST(TransmuralDepthTest, TagsLeftOutOfTheRanksTakeTheirSide) {
  const std::vector<double> u = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
  const std::vector<double> distances = {3.0, -1.0, 2.0, 0.0, -9.0, 12.0};
  const std::vector<double> w =
      QuantileDepths(u, distances, {true, true, true, true, false, false});
  EXPECT_EQ(w, (std::vector<double>{0.75, -0.75, 0.25, -0.25, -1.0, 1.0}));
  // All ranked: the two-argument form.
  EXPECT_EQ(QuantileDepths(u, distances, std::vector<bool>(6, true)),
            QuantileDepths(u, distances));
}

// A solid spheroid of a 10 mm wall: within it, or within the band outside
// either surface.
TEST(TransmuralDepthTest, WithinWallWidensTheWallByTheBand) {
  Model model = TestSpheroid(9);
  model.config.MakeSolid();
  model.state.globals[kH] = 10.0;
  for (FunctionValues& knot : model.state.knots) knot[kH] = 10.0;
  const std::vector<MaterialPoint> material(6, MaterialPoint{0.2, 1.0, 0.0});
  // The wall's surfaces along the normal, at this (u, v).
  const std::vector<double> distances = {0.0, 4.9, -4.9, 5.9, -6.1, 8.0};
  EXPECT_EQ(WithinWall(model, material, distances, 1.0),
            (std::vector<bool>{true, true, true, true, false, false}));
  EXPECT_EQ(WithinWall(model, material, distances, 0.0),
            (std::vector<bool>{true, true, true, false, false, false}));
}

// Tangential residuals of sigma = 0.5 mm per direction and frame (2 sigma^2
// in each tangential direction): the mean and the median read 0.5; 5 % of
// them moved 5-10 mm in a random direction take the mean to 0.86 mm and
// the median to 0.52.
TEST(TransmuralDepthTest, RobustTangentialNoiseIgnoresOutliers) {
  const Model model = TestSpheroid(9);
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.5 * std::sqrt(2.0));
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.2, 0.4), v(-3.1, 3.1),
      far(5.0, 10.0);
  std::vector<MaterialPoint> material;
  std::vector<Eigen::Vector3d> residuals;
  std::vector<size_t> which;
  for (int i = 0; i < 20000; ++i) {
    material.push_back({u(random), v(random), 0.0});
    residuals.emplace_back(noise(random), noise(random), noise(random));
    which.push_back(i);
  }
  EXPECT_NEAR(TangentialNoiseMm(model, residuals, material, which), 0.5, 0.01);
  EXPECT_NEAR(TangentialNoiseMm(model, residuals, material, which, true), 0.5,
              0.015);
  for (size_t i = 0; i < residuals.size(); i += 20) {
    const Eigen::Vector3d direction(unit(random), unit(random), unit(random));
    residuals[i] += far(random) * direction.normalized();
  }
  EXPECT_NEAR(TangentialNoiseMm(model, residuals, material, which), 0.86, 0.05);
  EXPECT_NEAR(TangentialNoiseMm(model, residuals, material, which, true), 0.52,
              0.02);
}

TEST(TransmuralDepthTest, WallModelNames) {
  EXPECT_EQ(WallModelFromName("solid"), WallModel::kSolid);
  EXPECT_STREQ(WallModelName(WallModelFromName("midwall")), "midwall");
  EXPECT_STREQ(WallModelName(WallModelFromName("auto")), "auto");
  EXPECT_THROW(WallModelFromName("thick"), InputError);
}

}  // namespace
}  // namespace pfdm
