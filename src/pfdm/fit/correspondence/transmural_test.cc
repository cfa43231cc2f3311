#include "pfdm/fit/correspondence/transmural.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"
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

// A cylinder's tags through a 10 mm wall, one sector of 60 degrees in the
// middle third of its height 4 mm farther out (a segment that stayed out
// while its ring contracted).  Ranked in its band of latitude, that
// sector's tags take the band's outer ranks: their mean w reads the offset
// as depth.  Ranked among their neighbours they keep their own, whatever
// the offset, and the tags away from the sector's edges are placed as in
// a uniform wall.
TEST(TransmuralDepthTest, NeighbourhoodRanksKeepASectorsOffsetOutOfTheDepth) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> midwall;
  std::vector<double> u, distances, truth;
  std::vector<bool> in_sector, inside;
  for (int i = 0; i < 4000; ++i) {
    const double v = -kPi + 2 * kPi * unit(random);
    const double z = 60.0 * unit(random);
    const double w = -1.0 + 2.0 * unit(random);
    const bool sector = std::abs(v) < kPi / 6 && z > 20.0 && z < 40.0;
    midwall.emplace_back(30.0 * std::cos(v), 30.0 * std::sin(v), z);
    u.push_back(z);
    truth.push_back(w);
    distances.push_back(5.0 * w + (sector ? 4.0 : 0.0));
    in_sector.push_back(sector);
    inside.push_back(std::abs(v) < kPi / 6 - 0.15 && z > 25.0 && z < 35.0);
  }
  const std::vector<bool> all(u.size(), true);
  const std::vector<double> ring = QuantileDepths(u, distances, all);
  const std::vector<double> near = NeighbourhoodDepths(midwall, distances, all);
  double ring_mean = 0.0, near_mean = 0.0, worst_inside = 0.0;
  int count = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    if (!in_sector[i]) continue;
    ring_mean += ring[i];
    near_mean += near[i];
    ++count;
    if (inside[i]) {
      worst_inside = std::max(worst_inside, std::abs(near[i] - truth[i]));
    }
  }
  ring_mean /= count;
  near_mean /= count;
  std::printf(
      "sector of %d tags: mean w %.3f in bands, %.3f among "
      "neighbours; worst inside %.3f\n",
      count, ring_mean, near_mean, worst_inside);
  EXPECT_GT(ring_mean, 0.4);
  EXPECT_LT(std::abs(near_mean), 0.2);  // 0.13: the sector's edges mix.
  // Ranks among 31 neighbours (4000 / 128): the DKW bound at 95 %,
  // 2 x 1.36 / sqrt(31) = 0.49.
  EXPECT_LT(worst_inside, 0.49);
}

// Few points: one band, ranks still spread over (-1, 1).
TEST(TransmuralDepthTest, FewPointsMakeOneBand) {
  const std::vector<double> w =
      QuantileDepths({0.0, 0.1, 0.2, 0.3}, {3.0, -1.0, 2.0, 0.0});
  EXPECT_EQ(w, (std::vector<double>{0.75, -0.75, 0.25, -0.25}));
}

// With the cubic term free the fitted endpoints widen more, about 20
// sigma^2 / h: a cubic fitted by least squares to ranked uniform plus
// Gaussian distances, h back within 1 %.
TEST(TransmuralDepthTest, SqueezedDeconvolutionUndoesTheCubicsWidening) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (double h : {6.0, 9.0, 14.0}) {
    for (double sigma : {0.3, 0.7}) {
      std::uniform_real_distribution<double> across(-0.5 * h, 0.5 * h);
      std::vector<double> u(100000, 0.0), distances;
      for (size_t i = 0; i < u.size(); ++i) {
        distances.push_back(across(random) + sigma * noise(random));
      }
      const std::vector<double> w = QuantileDepths(u, distances);
      // Least squares of distance on (1, w, w^2, w^3 - w): k(1) - k(-1).
      Eigen::MatrixXd a(w.size(), 4);
      Eigen::VectorXd b(w.size());
      for (size_t i = 0; i < w.size(); ++i) {
        a.row(i) << 1.0, w[i], w[i] * w[i], w[i] * w[i] * w[i] - w[i];
        b[i] = distances[i];
      }
      const Eigen::Vector4d c = a.colPivHouseholderQr().solve(b);
      const double h_obs = 2.0 * c[1];
      EXPECT_GT(h_obs, h + 12.0 * sigma * sigma / h) << h << " " << sigma;
      EXPECT_NEAR(DeconvolvedThickness(h_obs, sigma, true), h, 0.01 * h)
          << h << " " << sigma;
    }
  }
  EXPECT_EQ(DeconvolvedThickness(9.0, 0.0, true), 9.0);
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

// Tags on a spheroid's mid-wall at random (u, v), their distances from it
// `across(u, i)`.
template <typename Across>
std::vector<double> DistancesAt(const Model& model, int num_points,
                                Across across,
                                std::vector<Eigen::Vector3d>* midwall) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.4, 0.4), v(-3.1, 3.1);
  std::vector<MaterialPoint> material;
  std::vector<double> distances;
  for (int i = 0; i < num_points; ++i) {
    material.push_back({u(random), v(random), 0.0});
    distances.push_back(across(material.back().u, i, random));
  }
  *midwall = WorldPoints(model, material);
  return distances;
}

// Each 20th tag 5-10 mm off the wall, either way.
double Offset(int i, std::mt19937& random) {
  if (i % 20 != 0) return 0.0;
  const double size = std::uniform_real_distribution<double>(5.0, 10.0)(random);
  return i % 40 == 0 ? size : -size;
}

// Against its neighbours, a shape the surface misses alike departs by
// little (its change over a neighbour's distance, 0.13 mm at most here, to
// the 6-8 mm it misses by); a tag 7 mm off them by 7 mm.
TEST(TransmuralOutlierTest, NeighbourDeparturesSeeSpikesNotMissedShapes) {
  std::vector<Eigen::Vector3d> midwall;
  const std::vector<double> distances = DistancesAt(
      TestSpheroid(9), 3000,
      [](double u, int i, std::mt19937&) {
        return 6.0 + 2.0 * std::sin(u) + (i % 50 == 0 ? 7.0 : 0.0);
      },
      &midwall);
  const std::vector<double> departures =
      NeighbourDepartures(midwall, distances);
  for (size_t i = 0; i < departures.size(); ++i) {
    EXPECT_NEAR(departures[i], i % 50 == 0 ? 7.0 : 0.0, 0.25) << i;
  }
}

// Tags on one surface (noise 0.5 mm) with 5 % of them 5-10 mm off: on all
// of them the spread reads a wall; the outliers, and only they, are left
// out, and the rest spread as the noise does, 3.46 sigma (the mean square
// difference of two tags is 2 sigma^2).
TEST(TransmuralOutlierTest, OutliersDoNotReadAsAWall) {
  std::vector<Eigen::Vector3d> midwall;
  const std::vector<double> distances = DistancesAt(
      TestSpheroid(9), 3000,
      [](double, int i, std::mt19937& random) {
        return std::normal_distribution<double>(0.0, 0.5)(random) +
               Offset(i, random);
      },
      &midwall);
  EXPECT_GT(WallSpreadMm(midwall, distances), 6.0);
  const RobustWallSpread robust = RobustWallSpreadMm(midwall, distances);
  EXPECT_NEAR(robust.spread_mm, 3.46 * 0.5, 0.15);
  EXPECT_EQ(robust.outliers, 150u);
  for (size_t i = 0; i < distances.size(); ++i) {
    EXPECT_EQ(robust.inlier[i], i % 20 != 0) << i << " " << distances[i];
  }
  // Four robust deviations of the departures: of the noise (0.5 mm) and of
  // the median of 8 neighbours (1.25 sigma / sqrt(8)), 4 x 0.55 mm.
  EXPECT_NEAR(robust.fence_mm, 2.2, 0.2);
}

// Past 16,384 tags the outliers are sought among the sampled ones (every
// second of 20,000 here; every 21st tag is 5-10 mm off, so are every 42nd
// of the sampled ones): the fence and the spread as from all tags, and
// each tag, sampled or not, judged against that fence (TagInliers).
TEST(TransmuralOutlierTest, ManyTagsAreJudgedOnTheSampledOnes) {
  std::vector<Eigen::Vector3d> midwall;
  const std::vector<double> distances = DistancesAt(
      TestSpheroid(9), 20000,
      [](double, int i, std::mt19937& random) {
        return std::normal_distribution<double>(0.0, 0.5)(random) +
               Offset(i % 21 == 0 ? 0 : 1, random) * (i % 2 == 0 ? 1 : -1);
      },
      &midwall);
  const RobustWallSpread robust = RobustWallSpreadMm(midwall, distances);
  EXPECT_EQ(robust.step, 2u);
  ASSERT_EQ(robust.inlier.size(), 10000u);
  // 0, 42, ..., 19,992, and a tag or two whose neighbours' median two
  // outliers on one side pull.
  EXPECT_GE(robust.outliers, 477u);
  EXPECT_LE(robust.outliers, 480u);
  EXPECT_NEAR(robust.spread_mm, 3.46 * 0.5, 0.15);
  EXPECT_NEAR(robust.fence_mm, 2.2, 0.2);
  const std::vector<bool> inlier = TagInliers(robust, midwall, distances);
  ASSERT_EQ(inlier.size(), distances.size());
  int wrongly_out = 0;
  for (size_t i = 0; i < distances.size(); ++i) {
    if (i % 21 == 0) EXPECT_FALSE(inlier[i]) << i << " " << distances[i];
    if (i % 21 != 0 && !inlier[i]) ++wrongly_out;
    if (i % 2 == 0) EXPECT_EQ(inlier[i], robust.inlier[i / 2]) << i;
  }
  EXPECT_LE(wrongly_out, 6);
}

// WallSpreadMm of the examined tags that are no outliers.
double SpreadOfExaminedInliers(const RobustWallSpread& robust,
                               const std::vector<Eigen::Vector3d>& midwall,
                               const std::vector<double>& distances) {
  std::vector<Eigen::Vector3d> examined_points;
  std::vector<double> examined;
  for (size_t i = 0; i < distances.size(); i += robust.step) {
    examined_points.push_back(midwall[i]);
    examined.push_back(distances[i]);
  }
  EXPECT_EQ(examined.size(), robust.inlier.size());
  return WallSpreadMm(KeptEntries(examined_points, robust.inlier),
                      KeptEntries(examined, robust.inlier));
}

// The robust spread is WallSpreadMm's of the examined inliers to the bit,
// though each inlier's nearest inlier comes from the list of its 8
// neighbours, outliers among them: on all of 3,000 tags and on every
// second of 20,000, each 20th 7 mm off.
TEST(TransmuralOutlierTest, TheInliersSpreadIsWallSpreadMmsOfThem) {
  for (int num_points : {3000, 20000}) {
    std::vector<Eigen::Vector3d> midwall;
    const std::vector<double> distances = DistancesAt(
        TestSpheroid(9), num_points,
        [&](double, int i, std::mt19937& random) {
          return std::normal_distribution<double>(0.0, 0.5)(random) +
                 (i % 20 == 0 ? 7.0 : 0.0);
        },
        &midwall);
    const RobustWallSpread robust = RobustWallSpreadMm(midwall, distances);
    EXPECT_GE(robust.outliers, robust.inlier.size() / 20) << num_points;
    EXPECT_EQ(robust.spread_mm,
              SpreadOfExaminedInliers(robust, midwall, distances))
        << num_points;
  }
}

// A tag whose 8 neighbours are all outliers (4 of them 7 mm out, 4 in, so
// their median is its own distance) finds its nearest inlier beyond them.
TEST(TransmuralOutlierTest, AnInlierAmongOutliersFindsItsNearestInlier) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::normal_distribution<double> noise(0.0, 0.3);
  std::vector<Eigen::Vector3d> midwall;
  std::vector<double> distances;
  for (int row = -10; row <= 10; ++row) {
    for (int col = -10; col <= 10; ++col) {
      midwall.emplace_back(col + jitter(random), row + jitter(random), 0.0);
      const bool ring = std::max(std::abs(row), std::abs(col)) == 1;
      distances.push_back(ring ? ((row + col) % 2 == 0 ? 7.0 : -7.0)
                               : noise(random));
    }
  }
  const size_t centre = 10 * 21 + 10;
  const RobustWallSpread robust = RobustWallSpreadMm(midwall, distances);
  EXPECT_EQ(robust.outliers, 8u);
  EXPECT_TRUE(robust.inlier[centre]);
  EXPECT_FALSE(robust.inlier[centre + 1]);
  EXPECT_EQ(robust.spread_mm,
            SpreadOfExaminedInliers(robust, midwall, distances));
}

// Tags uniform through a 10 mm wall: none is an outlier (a uniform's tails
// are short: departures reach 1.35 robust deviations, the fence is at 4),
// so the spread is WallSpreadMm's to the bit.  Noise-free tags on one
// surface are no outliers either (the fence's floor).
TEST(TransmuralOutlierTest, AWallsTagsAreNoOutliers) {
  const Model model = TestSpheroid(9);
  std::vector<Eigen::Vector3d> midwall;
  const std::vector<double> wall = DistancesAt(
      model, 3000,
      [](double, int, std::mt19937& random) {
        return std::uniform_real_distribution<double>(-5.0, 5.0)(random);
      },
      &midwall);
  const RobustWallSpread robust = RobustWallSpreadMm(midwall, wall);
  EXPECT_EQ(robust.outliers, 0u);
  EXPECT_EQ(robust.spread_mm, WallSpreadMm(midwall, wall));
  EXPECT_NEAR(robust.spread_mm, 10.0, 0.6);
  EXPECT_GT(robust.fence_mm, 12.0);

  const std::vector<double> exact = DistancesAt(
      model, 3000, [](double, int i, std::mt19937&) { return 1e-12 * (i % 7); },
      &midwall);
  const RobustWallSpread flat = RobustWallSpreadMm(midwall, exact);
  EXPECT_EQ(flat.outliers, 0u);
  EXPECT_EQ(flat.fence_mm, kMinOutlierMm);
}

// Within a band, two interquartile ranges of its median: -7 and 30 lie
// beyond (quartiles 1.75 and 7.25, median 4.5: the fence is 11 mm off it).
TEST(TransmuralOutlierTest, InsideTheWallFencesEachBand) {
  const std::vector<double> distances = {5, -7, 0, 1, 2, 3, 30, 4, 6, 7, 8, 9};
  const std::vector<double> u(distances.size(), 0.0);
  const std::vector<bool> inside = InsideTheWall(u, distances);
  for (size_t i = 0; i < distances.size(); ++i) {
    EXPECT_EQ(inside[i], distances[i] != -7 && distances[i] != 30) << i;
  }
  EXPECT_EQ(KeptEntries(distances, inside),
            (std::vector<double>{5, 0, 1, 2, 3, 4, 6, 7, 8, 9}));
}

// Tags uniform through a 10 mm wall, 5 % of them 5-10 mm off it (along the
// normal, the worst case, uniform in u): those more than half a wall past
// either surface are left out of the thickness, none of the wall's.  The
// ranks of all read 11.33 mm, of those inside 10.83 (without outliers, 10.0;
// the outliers left lie at most half a wall past a surface).
TEST(TransmuralOutlierTest, InsideTheWallLeavesOutTagsFarBeyondIt) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> across(-5.0, 5.0), along(-1.5, 0.5);
  std::vector<double> u, distances;
  for (int i = 0; i < 4000; ++i) {
    u.push_back(along(random));
    distances.push_back(across(random) + Offset(i, random));
  }
  const std::vector<bool> inside = InsideTheWall(u, distances);
  int wall_left_out = 0, outliers_left_out = 0, far_beyond = 0;
  for (size_t i = 0; i < inside.size(); ++i) {
    if (i % 20 == 0 && std::abs(distances[i]) > 10.5) ++far_beyond;
    if (inside[i]) continue;
    ++(i % 20 == 0 ? outliers_left_out : wall_left_out);
    // The fence: two interquartile ranges (5 mm) of the median (0).
    EXPECT_GT(std::abs(distances[i]), 9.5) << i;
  }
  EXPECT_EQ(wall_left_out, 0);
  EXPECT_GE(outliers_left_out, far_beyond);
  EXPECT_EQ(outliers_left_out, 42);
  const double all =
      ThicknessFromDepths(distances, QuantileDepths(u, distances));
  const std::vector<double> kept = KeptEntries(distances, inside);
  const double inliers =
      ThicknessFromDepths(kept, QuantileDepths(KeptEntries(u, inside), kept));
  EXPECT_NEAR(all, 11.33, 0.01);
  EXPECT_NEAR(inliers, 10.83, 0.01);
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
