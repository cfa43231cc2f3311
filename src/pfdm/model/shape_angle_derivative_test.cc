#include "pfdm/model/shape_angle_derivative.h"

#include <random>
#include <vector>

#include "ceres/jet.h"
#include "gtest/gtest.h"
#include "pfdm/model/model_point.h"

namespace pfdm {
namespace {

using Jet2 = ceres::Jet<double, 2>;

void ExpectNear(const ShapeAndAngleDerivatives& got,
                const Eigen::Matrix<Jet2, 3, 1>& truth, double u, double v,
                double w) {
  for (int k = 0; k < 3; ++k) {
    const double scale = 1.0 + std::abs(truth[k].a);
    EXPECT_NEAR(got.shape[k], truth[k].a, 1e-13 * scale) << k;
    EXPECT_NEAR(got.d_u[k], truth[k].v[0], 1e-11 * scale)
        << "u " << u << " v " << v << " w " << w << " axis " << k;
    EXPECT_NEAR(got.d_v[k], truth[k].v[1], 1e-11 * scale)
        << "u " << u << " v " << v << " w " << w << " axis " << k;
  }
}

// ReferenceShape differentiated by ceres::Jet in (u, v) (with std::sin and
// std::cos), the functions moving along u at the rates df_du.
void ExpectMatchesJet(const double* f, const double* df_du, double u, double v,
                      bool unit_exponents, double w = 0.0) {
  Jet2 f_jet[kNumFunctions];
  for (int i = 0; i < kNumFunctions; ++i) {
    f_jet[i] = Jet2(f[i]);
    f_jet[i].v[0] = df_du[i];
  }
  const Eigen::Matrix<Jet2, 3, 1> truth = ReferenceShape(
      f_jet, MakeAngles(Jet2(u, 0), Jet2(v, 1)), unit_exponents, w);
  ExpectNear(ShapeAngleDerivatives(f, df_du, u, v, unit_exponents, w), truth, u,
             v, w);
}

struct State {
  double f[kNumFunctions];
  double df[kNumFunctions];
};

State RandomState(std::mt19937* random, bool unit_exponents, bool bent) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  State s;
  const double values[kNumFunctions] = {40,  0.7, 0.6, 0.9, 1.0, 1.0, 3,
                                        1.0, -2,  0.3, 0.2, 1.5, -1,  0.5};
  for (int i = 0; i < kNumFunctions; ++i) {
    s.f[i] = values[i] * (1.0 + 0.2 * uniform(*random));
    s.df[i] = 0.3 * values[i] * uniform(*random);
  }
  if (unit_exponents) {
    s.f[kEps1] = s.f[kEps2] = 1.0;
    s.df[kEps1] = s.df[kEps2] = 0.0;
  }
  if (!bent) s.f[kB0] = s.df[kB0] = s.f[kB2] = s.df[kB2] = 0.0;
  return s;
}

TEST(ShapeAngleDerivativeTest, MatchesJetDerivativesAtRandomPoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u_dist(-1.5707963, 0.5235988);
  std::uniform_real_distribution<double> v_dist(-M_PI, M_PI);
  for (bool unit : {true, false}) {
    for (bool bent : {true, false}) {
      for (int trial = 0; trial < 200; ++trial) {
        const State s = RandomState(&random, unit, bent);
        ExpectMatchesJet(s.f, s.df, u_dist(random), v_dist(random), unit);
      }
    }
  }
}

// The apex pole (no v derivative left), the seam v = +-pi, the axes where a
// cosine or sine and with it a signed power's base vanish, and a model with
// no slopes at all.
TEST(ShapeAngleDerivativeTest, MatchesJetDerivativesAtSingularPoints) {
  std::mt19937 random(11);
  const double us[] = {-M_PI / 2, -M_PI / 2 + 1e-9, -1.0, 0.0, M_PI / 6};
  const double vs[] = {-M_PI, M_PI, 0.0, M_PI / 2, -M_PI / 2, 1e-12};
  for (bool unit : {true, false}) {
    State s = RandomState(&random, unit, true);
    for (double u : us) {
      for (double v : vs) ExpectMatchesJet(s.f, s.df, u, v, unit);
    }
    for (double& d : s.df) d = 0.0;
    for (double u : us) {
      for (double v : vs) ExpectMatchesJet(s.f, s.df, u, v, unit);
    }
  }
}

// Off the mid-wall (a solid's layers, the walls at w = -+1): a wall of
// 7-11 mm whose thickness, twist difference, shift and squeeze all vary
// along u, at random points and at the pole, the seam and the axes.
TEST(ShapeAngleDerivativeTest, MatchesJetDerivativesOffTheMidwall) {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_real_distribution<double> u_dist(-1.5707963, 0.5235988);
  std::uniform_real_distribution<double> v_dist(-M_PI, M_PI);
  const double us[] = {-M_PI / 2, -M_PI / 2 + 1e-9, 0.0, M_PI / 6};
  const double vs[] = {-M_PI, 0.0, M_PI / 2, 1e-12};
  for (bool unit : {true, false}) {
    for (int trial = 0; trial < 100; ++trial) {
      State s = RandomState(&random, unit, trial % 2 == 0);
      s.f[kH] = 9.0 + 2.0 * uniform(random);
      s.df[kH] = 3.0 * uniform(random);
      s.f[kDtau] = 0.2 * uniform(random);
      s.df[kDtau] = 0.1 * uniform(random);
      s.f[kWallShift] = 0.5 * uniform(random);
      s.df[kWallShift] = 0.3 * uniform(random);
      s.f[kWallSqueeze] = 0.4 * uniform(random);
      s.df[kWallSqueeze] = 0.2 * uniform(random);
      for (double w : {-1.0, -1.0 / 3, 0.5, 1.0}) {
        ExpectMatchesJet(s.f, s.df, u_dist(random), v_dist(random), unit, w);
        if (trial == 0) {
          for (double u : us) {
            for (double v : vs) ExpectMatchesJet(s.f, s.df, u, v, unit, w);
          }
        }
      }
    }
  }
}

// A row of points at one u (the seam, the axes and random v's) gives each
// point's single evaluation to the bit: on the mid-wall and off it, unit
// exponents or not, bent or not, at the apex pole too.
TEST(ShapeAngleDerivativeTest, ARowGivesEachPointsBits) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> v_dist(-M_PI, M_PI);
  std::vector<double> v = {-M_PI, 0.0, M_PI / 2, -M_PI / 2, 1e-12};
  for (int j = 0; j < 10; ++j) v.push_back(v_dist(random));
  for (bool unit : {true, false}) {
    for (bool bent : {true, false}) {
      State s = RandomState(&random, unit, bent);
      s.f[kH] = 9.0;
      s.df[kH] = 2.0;
      s.f[kDtau] = 0.1;
      for (double u : {-M_PI / 2, -0.7, 0.3}) {
        for (double w : {0.0, -1.0, 0.5}) {
          std::vector<ShapeAndAngleDerivatives> row(v.size());
          ShapeAngleDerivativesAlong(s.f, s.df, u, v.data(), v.size(), unit, w,
                                     row.data());
          for (size_t j = 0; j < v.size(); ++j) {
            const ShapeAndAngleDerivatives one =
                ShapeAngleDerivatives(s.f, s.df, u, v[j], unit, w);
            EXPECT_TRUE(row[j].shape == one.shape) << u << " " << v[j];
            EXPECT_TRUE(row[j].d_u == one.d_u) << u << " " << v[j];
            EXPECT_TRUE(row[j].d_v == one.d_v) << u << " " << v[j];
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace pfdm
