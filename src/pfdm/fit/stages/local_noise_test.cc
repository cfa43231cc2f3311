#include "pfdm/fit/stages/local_noise.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/fit/problem/local_fit.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// 400 tracked tags spread over the test spheroid's wall, and the frame's
// points as the fit would have them.
struct TrackedFrame {
  TrackedFrame() : model(TestSpheroid(9)) {
    for (int i = 0; i < 20; ++i) {
      for (int j = 0; j < 20; ++j) {
        const double u =
            model.config.u_min +
            (i + 0.5) / 20 * (model.config.u_max - model.config.u_min);
        material.push_back({u, -M_PI + (j + 0.5) / 20 * 2 * M_PI, 0.0});
      }
    }
    points.index = 1;
    points.kind = FrameKind::kTracked;
    points.positions.resize(material.size());
    points.layer_w.assign(material.size(), 0.0);
    points.is_tag.assign(material.size(), true);
    points.sliding.assign(material.size(), false);
    points.assign_depth.assign(material.size(), false);
    for (size_t i = 0; i < material.size(); ++i) points.tracked.push_back(i);
  }
  Model model;
  std::vector<MaterialPoint> material;
  FramePoints points;
};

// The field is a linear fit of the noise: twice the noise, with the same
// seed, is exactly twice every draw; and the seed is the frame's, so a
// second call gives the same draws.
TEST(LocalNoiseTest, DrawsAreLinearInTheNoiseAndRepeatable) {
  const TrackedFrame frame;
  const FitOptions options;
  const auto one = LocalNoiseDraws(frame.points, frame.material, options,
                                   frame.model, 0.5, 3);
  const auto two = LocalNoiseDraws(frame.points, frame.material, options,
                                   frame.model, 1.0, 3);
  const auto again = LocalNoiseDraws(frame.points, frame.material, options,
                                     frame.model, 0.5, 3);
  ASSERT_EQ(one.size(), 3u);
  double square = 0.0;
  size_t count = 0;
  for (size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one[k].size(), two[k].size());
    for (size_t i = 0; i < one[k].size(); ++i) {
      EXPECT_NEAR(two[k][i], 2.0 * one[k][i], 1e-9);
      EXPECT_EQ(again[k][i], one[k][i]);
      square += one[k][i] * one[k][i];
      ++count;
    }
  }
  // The stiffness damps the noise (0.5 mm a coordinate) but does not
  // remove it: the nodes' rms displacement is a fraction of it.
  const double rms = std::sqrt(square / count);
  EXPECT_GT(rms, 0.05);
  EXPECT_LT(rms, 0.5);
}

// The draws spread over threads (--threads), one solver each, are the
// one thread's to the bit: the noise is drawn in the draws' order first.
TEST(LocalNoiseTest, ThreadsGiveTheSameDrawsToTheBit) {
  const TrackedFrame frame;
  FitOptions options;
  const auto one = LocalNoiseDraws(frame.points, frame.material, options,
                                   frame.model, 0.5, 5);
  ASSERT_EQ(one.size(), 5u);
  options.solver.num_threads = 3;
  const auto three = LocalNoiseDraws(frame.points, frame.material, options,
                                     frame.model, 0.5, 5);
  ASSERT_EQ(three.size(), one.size());
  for (size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(three[k].size(), one[k].size());
    for (size_t i = 0; i < one[k].size(); ++i) {
      EXPECT_EQ(three[k][i], one[k][i]) << k << " " << i;
    }
  }
}

// Without a local field, or without noise, there is nothing to draw.
TEST(LocalNoiseTest, NoFieldNoDraws) {
  const TrackedFrame frame;
  FitOptions options;
  EXPECT_TRUE(
      LocalNoiseDraws(frame.points, frame.material, options, frame.model, 0.0)
          .empty());
  options.local.enabled = false;
  EXPECT_TRUE(
      LocalNoiseDraws(frame.points, frame.material, options, frame.model, 0.5)
          .empty());
}

// A point searched on this frame (a contour's, a tag's on its first) gets
// noise along the normal only: the search took the rest.  Its field then
// moves the surface mostly along the normal, where tracked points' noise
// moves it in every direction.
TEST(LocalNoiseTest, SearchedPointsGetNoiseAlongTheNormal) {
  TrackedFrame frame;
  FitOptions options;
  frame.points.kind = FrameKind::kReference;
  frame.points.sliding.assign(frame.material.size(), true);
  frame.points.untracked = frame.points.tracked;
  frame.points.tracked.clear();
  const auto searched = LocalNoiseDraws(frame.points, frame.material, options,
                                        frame.model, 0.5, 4);
  const TrackedFrame tracked;
  const auto free = LocalNoiseDraws(tracked.points, tracked.material, options,
                                    tracked.model, 0.5, 4);
  // The grid the local fit makes (the draws are its values).
  Model fitted = frame.model;
  FitLocalField(WorldPoints(frame.model, frame.material), frame.material,
                std::vector<bool>(frame.material.size(), false), options,
                &fitted);
  std::vector<Eigen::Vector3d> at;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(frame.model, frame.material, &at);
  // The share of the fields' displacement along the normal at the points.
  auto normal_share = [&](const std::vector<std::vector<double>>& draws) {
    double along = 0.0, total = 0.0;
    for (const std::vector<double>& draw : draws) {
      Model moved = fitted;
      moved.state.local.values = draw;
      const std::vector<Eigen::Vector3d> now =
          WorldPoints(moved, frame.material);
      for (size_t i = 0; i < at.size(); ++i) {
        const Eigen::Vector3d d = now[i] - at[i];
        along += std::pow(d.dot(normals[i]), 2);
        total += d.squaredNorm();
      }
    }
    return along / total;
  };
  EXPECT_GT(normal_share(searched), 0.8);
  EXPECT_LT(normal_share(free), 0.6);
}

// Frame 0's length is set by its highest point.  With 20 points on the rim
// and the rest far below, each draw's top is the highest of 20 noisy
// heights: by the normal's order statistics its mean is 1.8675 sigma above
// the rim and its sd 0.5249 sigma.  Over 4000 draws their standard errors
// are 0.008 sigma and 0.006 sigma.
TEST(LocalNoiseTest, LengthDrawsAreTheHighestOfTheRimsNoise) {
  const Model model = TestSpheroid(9);
  const ModelConfig& config = model.config;
  std::vector<MaterialPoint> material;
  for (int j = 0; j < 20; ++j) {
    const double v = -M_PI + (j + 0.5) / 20 * 2 * M_PI;
    material.push_back({config.u_max, v, 0.0});
    material.push_back({0.5 * (config.u_min + config.u_max), v, 0.0});
  }
  FramePoints points;
  points.index = 0;
  const double sigma = 0.5;
  const std::vector<double> draws =
      LengthNoiseDraws(points, material, FitOptions(), model, sigma, 4000);
  ASSERT_EQ(draws.size(), 4000u);
  const Eigen::Vector3d axis = model.Rotation().col(2);
  const double length = (model.WorldPoint(config.u_max, 0.0) -
                         model.WorldPoint(config.u_min, 0.0))
                            .dot(axis);
  double sum = 0.0, square = 0.0;
  for (double f : draws) {
    sum += f * length;
    square += f * length * f * length;
  }
  const double mean = sum / draws.size();
  const double sd = std::sqrt(square / draws.size() - mean * mean);
  EXPECT_NEAR(mean, 1.8675 * sigma, 0.04 * sigma);
  EXPECT_NEAR(sd, 0.5249 * sigma, 0.03 * sigma);
  // Seeded by the frame: the same draws again.
  EXPECT_EQ(
      LengthNoiseDraws(points, material, FitOptions(), model, sigma, 4000)[7],
      draws[7]);
}

}  // namespace
}  // namespace pfdm
