#include "pfdm/fit/problem/directional_noise.h"

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "Eigen/Dense"
#include "gtest/gtest.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A grid of material points on the shell's mid-wall (a solid, whose
// tracked tags the covariance weighs by their sd across the wall), their
// model points and unit normals.
struct Surface {
  Model model = TestShell(5);
  std::vector<MaterialPoint> material;
  std::vector<Eigen::Vector3d> at, normals;
  Surface() {
    for (double u = -1.3; u < 1.3; u += 0.1) {
      for (double v = -M_PI; v < M_PI; v += 0.2) material.push_back({u, v});
    }
    normals = SurfaceNormals(model, material, &at);
  }
  // A unit vector across point i's normal.
  Eigen::Vector3d Across(size_t i) const {
    return normals[i].cross(Eigen::Vector3d::UnitZ()).normalized();
  }
};

// Points moved by 0.8 mm along the normal and 0.3 across it, signs
// alternating: each direction's sd read back exactly (no parameters).
TEST(DirectionalNoiseTest, SplitsTheResidualAlongAndAcrossTheNormals) {
  const Surface s;
  std::vector<Eigen::Vector3d> points;
  for (size_t i = 0; i < s.at.size(); ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    points.push_back(s.at[i] + sign * 0.8 * s.normals[i] + 0.3 * s.Across(i));
  }
  const std::vector<Eigen::Vector3d> residuals =
      Residuals(s.model, points, s.material);
  const DirectionalSigma split =
      DirectionalDataSigma(residuals, s.normals, "none", 0.0, 0.0, 0.0);
  EXPECT_NEAR(split.normal_mm, 0.8, 1e-9);
  // 0.3 mm in one of the two coordinates across: sqrt(0.09 / 2).
  EXPECT_NEAR(split.tangent_mm, 0.3 / std::sqrt(2.0), 1e-9);
  // With parameters, each direction's residuals lose their share.
  const DirectionalSigma fewer =
      DirectionalDataSigma(residuals, s.normals, "none", 0.0, 100.0, 50.0);
  const double n = static_cast<double>(points.size());
  EXPECT_NEAR(fewer.normal_mm, 0.8 * std::sqrt(n / (n - 100.0)), 1e-9);
  EXPECT_NEAR(fewer.tangent_mm, 0.3 * std::sqrt(n / (2.0 * n - 50.0)), 1e-9);
}

// A linear least squares of 3-row data and a prior: C is the sandwich
// A^-1 (sigma^2 P'P + s_t^2 J'J) A^-1, and sigma^2 A^-1 when s_t = sigma.
TEST(DirectionalNoiseTest, CovarianceIsTheSandwichOfTheRowsNoise) {
  std::mt19937 random(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  const int p = 4;
  Eigen::MatrixXd data(60, p), prior(p, p);
  for (int r = 0; r < data.rows(); ++r) {
    for (int c = 0; c < p; ++c) data(r, c) = unit(random);
  }
  prior = 0.7 * Eigen::MatrixXd::Identity(p, p);
  NormalParts parts;
  parts.data_normal = data.transpose() * data;
  const Eigen::MatrixXd a = parts.data_normal + prior.transpose() * prior;
  parts.pseudo_inverse = a.inverse();
  const double sigma = 0.8, tangent = 0.5;
  const Eigen::MatrixXd sandwich = parts.pseudo_inverse *
                                   (sigma * sigma * prior.transpose() * prior +
                                    tangent * tangent * parts.data_normal) *
                                   parts.pseudo_inverse;
  const Eigen::MatrixXd c = DirectionalCovariance(parts, 3, sigma, tangent);
  EXPECT_LT((c - sandwich.topLeftCorner(3, 3)).norm(), 1e-12 * sandwich.norm());
  const Eigen::MatrixXd pooled = DirectionalCovariance(parts, p, sigma, sigma);
  EXPECT_LT((pooled - sigma * sigma * parts.pseudo_inverse).norm(),
            1e-12 * pooled.norm());
}

// Over draws of a tracked frame's points (`draw`), each fitted with its
// covariance: per checked knot its sd (the draws' mean) over its rms error
// against the fit of `reference_points`, and the last draw's covariance.
// Without priors: their pull toward a target the noise does not move
// shrinks the spread that C, their rows taken as information, keeps.
struct Spread {
  std::vector<double> sd_over_rms;
  FrameCovariance last;
};
Spread KnotSpread(const Surface& s,
                  const std::vector<Eigen::Vector3d>& reference_points,
                  const std::function<std::vector<Eigen::Vector3d>()>& draw,
                  bool depths_held) {
  FitOptions options;
  options.prior_weight = 0.0;
  options.smoothness_weight = 0.0;
  const std::vector<Eigen::Vector3d> no_normals(s.at.size(),
                                                Eigen::Vector3d::Zero());
  const ModelState start = s.model.state;
  auto fit = [&](const std::vector<Eigen::Vector3d>& points, Model* model) {
    *model = s.model;
    const FrameInputs frame{points,       s.material,          no_normals,
                            std::nullopt, FrameKind::kTracked, start,
                            start};
    EXPECT_TRUE(SolveFrame(frame, options, model).usable);
    return EstimateFrameCovariance(frame, options, *model, depths_held);
  };
  Model clean;
  fit(reference_points, &clean);
  const int kDraws = 40;
  const std::vector<std::pair<int, int>> checked = {
      {2, kA1}, {2, kTau}, {3, kA3}};
  std::vector<double> squared(checked.size(), 0.0), predicted = squared;
  Spread spread;
  for (int d = 0; d < kDraws; ++d) {
    Model noisy;
    spread.last = fit(draw(), &noisy);
    EXPECT_TRUE(spread.last.computed);
    for (size_t c = 0; c < checked.size(); ++c) {
      const auto [k, f] = checked[c];
      const double error = noisy.state.knots[k][f] - clean.state.knots[k][f];
      squared[c] += error * error;
      predicted[c] += spread.last.KnotSd(noisy.config, f, k);
    }
  }
  for (size_t c = 0; c < checked.size(); ++c) {
    spread.sd_over_rms.push_back(predicted[c] / kDraws /
                                 std::sqrt(squared[c] / kDraws));
  }
  return spread;
}

// A tracked frame whose points err along their normals by fixed offsets
// (sd 1 mm, the same in every draw, as a solid's ranked depths do) and
// by 0.3 mm of noise in every coordinate, drawn anew: against the fit of
// the offsets alone, the knots' errors over 40 draws have the sds the
// covariance gives (within 25 %), which weighs the rows by their sd across
// the normals; the pooled sigma, 0.65 mm, would have given about twice.
TEST(DirectionalNoiseTest, ATrackedFramesIntervalsAreTheNoisesNotTheOffsets) {
  const Surface s;
  std::mt19937 random(11);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> offset_points;
  for (size_t i = 0; i < s.at.size(); ++i) {
    offset_points.push_back(s.at[i] + unit(random) * s.normals[i]);
  }
  const Spread spread = KnotSpread(
      s, offset_points,
      [&]() {
        std::vector<Eigen::Vector3d> points = offset_points;
        for (Eigen::Vector3d& p : points) {
          p += 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
        }
        return points;
      },
      /*depths_held=*/false);
  EXPECT_NEAR(spread.last.tangent_sigma_mm, 0.3, 0.03);
  EXPECT_NEAR(spread.last.normal_sigma_mm, std::sqrt(1.0 + 0.09), 0.15);
  EXPECT_GT(spread.last.sigma_mm, 0.6);
  for (size_t c = 0; c < spread.sd_over_rms.size(); ++c) {
    EXPECT_NEAR(spread.sd_over_rms[c], 1.0, 0.25) << c;
  }
}

// Held depths: the offsets along the normals are frame 0's noise, drawn
// anew with each draw (sd 0.6 mm), beside 0.3 mm in every coordinate.
// Against the fit of the points without either, the covariance with
// depths_held, whose rows along the normals take the excess of their
// variance over the variance across them, gives the knots' errors (within
// 25 %: a1's, tau's and a3's sds 0.82, 0.88 and 1.06 of them); the rows
// weighed by the sd across the normals alone read a1's at 0.51.
TEST(DirectionalNoiseTest, HeldDepthsErrAlongTheNormalsByTheNoise) {
  const Surface s;
  std::mt19937 random(13);
  std::normal_distribution<double> unit(0.0, 1.0);
  auto draw = [&]() {
    std::vector<Eigen::Vector3d> points = s.at;
    for (size_t i = 0; i < points.size(); ++i) {
      points[i] +=
          0.6 * unit(random) * s.normals[i] +
          0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
    }
    return points;
  };
  const Spread held = KnotSpread(s, s.at, draw, /*depths_held=*/true);
  EXPECT_NEAR(held.last.normal_sigma_mm, std::sqrt(0.36 + 0.09), 0.08);
  for (size_t c = 0; c < held.sd_over_rms.size(); ++c) {
    EXPECT_NEAR(held.sd_over_rms[c], 1.0, 0.25) << c;
  }
  // a1 moves the wall along its normals, tau and a3 across them.
  const Spread across = KnotSpread(s, s.at, draw, /*depths_held=*/false);
  EXPECT_LT(across.sd_over_rms[0], 0.6);
}

// One surface's tags sit on it: their frames keep the pooled sigma.
TEST(DirectionalNoiseTest, OneSurfacesTagsKeepThePooledSigma) {
  Surface s;
  s.model = TestSpheroid(5);
  s.normals = SurfaceNormals(s.model, s.material, &s.at);
  std::vector<Eigen::Vector3d> points;
  for (size_t i = 0; i < s.at.size(); ++i) {
    points.push_back(s.at[i] + (i % 2 == 0 ? 0.5 : -0.5) * s.normals[i]);
  }
  const std::vector<Eigen::Vector3d> no_normals(points.size(),
                                                Eigen::Vector3d::Zero());
  const ModelState start = s.model.state;
  const FitOptions options;
  const FrameCovariance covariance =
      EstimateFrameCovariance({points, s.material, no_normals, std::nullopt,
                               FrameKind::kTracked, start, start},
                              options, s.model);
  ASSERT_TRUE(covariance.computed);
  EXPECT_EQ(covariance.tangent_sigma_mm, 0.0);
  EXPECT_EQ(covariance.NoiseSigma(), covariance.sigma_mm);
}

}  // namespace
}  // namespace pfdm
