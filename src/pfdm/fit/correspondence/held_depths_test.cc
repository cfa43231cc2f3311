#include "pfdm/fit/correspondence/held_depths.h"

#include <cmath>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// E[w | w_obs] by the trapezoid rule over w in [-1, 1] (20,000 steps: within
// about 2e-7 where the density is steep at the wall, s = 0.05).
double MeanByQuadrature(double w_obs, double s) {
  const int n = 20000;
  double mass = 0.0, moment = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = -1.0 + 2.0 * i / n;
    const double weight = (i == 0 || i == n ? 0.5 : 1.0) *
                          std::exp(-0.5 * std::pow((w_obs - w) / s, 2));
    mass += weight;
    moment += weight * w;
  }
  return moment / mass;
}

// Least-squares slope of y on x.
double Slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= x.size();
  my /= y.size();
  double xy = 0.0, xx = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    xy += (x[i] - mx) * (y[i] - my);
    xx += (x[i] - mx) * (x[i] - mx);
  }
  return xy / xx;
}

TEST(HeldDepthsTest, ShrunkDepthIsTheTruncatedNormalsMean) {
  for (double s : {0.05, 0.1, 0.3}) {
    for (double w_obs : {0.0, 0.3, -0.7, 0.95, 1.0, 1.2, -1.3}) {
      EXPECT_NEAR(ShrunkDepth(w_obs, s), MeanByQuadrature(w_obs, s), 1e-6)
          << w_obs << " " << s;
    }
  }
}

TEST(HeldDepthsTest, ShrunkDepthIsOddBoundedIncreasingAndPlainWithoutNoise) {
  double last = -1.0;
  for (double w_obs = -3.0; w_obs <= 3.0; w_obs += 0.01) {
    const double w = ShrunkDepth(w_obs, 0.1);
    EXPECT_TRUE(std::isfinite(w));
    EXPECT_GE(w, last) << w_obs;
    EXPECT_LE(std::abs(w), 1.0);
    EXPECT_DOUBLE_EQ(w, -ShrunkDepth(-w_obs, 0.1));
    last = w;
  }
  // Far outside the wall: within s / 8 of it.
  EXPECT_GT(ShrunkDepth(50.0, 0.1), 1.0 - 0.1 / 8);
  EXPECT_DOUBLE_EQ(ShrunkDepth(0.4, 0.0), 0.4);
  EXPECT_DOUBLE_EQ(ShrunkDepth(1.3, 0.0), 1.0);
}

// Depths uniform through the wall, read with noise of a tenth of the
// half-wall: regressed on the observed depths, the true ones come out
// attenuated (slope 1 / (1 + 3 s^2) = 0.971); on the shrunk depths, not.
TEST(HeldDepthsTest, TrueDepthsRegressOnShrunkOnesWithSlopeOne) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> across(-1.0, 1.0);
  const double s = 0.1;
  std::normal_distribution<double> noise(0.0, s);
  std::vector<double> truth, observed, shrunk;
  for (int i = 0; i < 200000; ++i) {
    truth.push_back(across(random));
    observed.push_back(truth.back() + noise(random));
    shrunk.push_back(ShrunkDepth(observed.back(), s));
  }
  EXPECT_NEAR(Slope(observed, truth), 1.0 / (1.0 + 3.0 * s * s), 0.003);
  EXPECT_NEAR(Slope(shrunk, truth), 1.0, 0.003);
}

// Tags at known material points through a solid spheroid's 10 mm wall,
// each starting from the mid-wall at a (u, v) 0.05 off: without noise each
// gets its layer and (u, v) back; with 0.5 mm of noise (s = 0.1) the true
// depths regress on the held ones with slope 1.  The model's h is the
// ranks' widened one, as frame 0's is before its noise is taken out.
TEST(HeldDepthsTest, HeldMaterialPointsOfASolidsTags) {
  Model model = TestSpheroid(9);
  model.config.MakeSolid();
  const double sigma = 0.5;
  const double widened = 10.0 + 6.0 * sigma * sigma / 10.0;
  model.state.globals[kH] = widened;
  for (FunctionValues& knot : model.state.knots) knot[kH] = widened;
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(-1.0, 0.3), v(-3.0, 3.0),
      across(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector3d> exact, noisy;
  std::vector<MaterialPoint> truth, start;
  for (int i = 0; i < 5000; ++i) {
    // On the layer the noise-free thickness puts at w.
    const MaterialPoint at{u(random), v(random), across(random)};
    truth.push_back(at);
    exact.push_back(model.WorldPoint(at.u, at.v, at.w * 10.0 / widened));
    noisy.push_back(exact.back() + Eigen::Vector3d(noise(random), noise(random),
                                                   noise(random)));
    start.push_back({at.u + 0.05, at.v - 0.05, 0.0});
  }
  const std::vector<MaterialPoint> clean =
      HeldMaterialPoints(model, exact, start, 0.0);
  for (size_t i = 0; i < clean.size(); ++i) {
    EXPECT_NEAR(clean[i].w, truth[i].w * 10.0 / widened, 1e-4) << i;
    EXPECT_NEAR(clean[i].u, truth[i].u, 1e-4) << i;
    EXPECT_NEAR(clean[i].v, truth[i].v, 1e-4) << i;
  }
  const std::vector<MaterialPoint> held =
      HeldMaterialPoints(model, noisy, start, sigma);
  std::vector<double> true_w, held_w;
  for (size_t i = 0; i < held.size(); ++i) {
    true_w.push_back(truth[i].w);
    held_w.push_back(held[i].w);
  }
  EXPECT_NEAR(Slope(held_w, true_w), 1.0, 0.02);
}

}  // namespace
}  // namespace pfdm
