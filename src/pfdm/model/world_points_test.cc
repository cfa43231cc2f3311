#include "pfdm/model/world_points.h"

#include <cmath>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A spheroid given every deformation: functions that vary along the axis,
// bends, twist, offsets, a wall, a local field and a pose.
Model DeformedModel(bool unit_exponents) {
  Model model = TestSpheroid(6);
  for (int k = 0; k < 6; ++k) {
    FunctionValues& knot = model.state.knots[k];
    knot[kA1] = 0.45 + 0.02 * k;
    knot[kA2] = 0.5 - 0.01 * k;
    knot[kB0] = 2.0 - 0.3 * k;
    knot[kB1] = 0.1 * k;
    knot[kB2] = -1.0 + 0.2 * k;
    knot[kB3] = 0.3;
    knot[kTau] = 0.05 * k;
    knot[kE1o] = 0.4 * std::sin(k);
    knot[kE2o] = -0.3 * std::cos(k);
    knot[kH] = 9.0;
  }
  model.state.globals[kH] = 9.0;  // Held: the globals' value serves.
  if (!unit_exponents) {
    model.state.globals[kEps1] = 0.8;
    model.state.globals[kEps2] = 1.2;
  }
  model.state.center = {3.0, -7.0, 11.0};
  model.state.quaternion = {0.9, 0.2, -0.3, 0.1};
  Eigen::Map<Eigen::Vector4d>(model.state.quaternion.data()).normalize();
  AddTestLocalField(1.5, &model);
  return model;
}

TEST(WorldPointsTest, MatchModelWorldPointOneByOne) {
  for (bool unit_exponents : {true, false}) {
    const Model model = DeformedModel(unit_exponents);
    ASSERT_EQ(model.UnitExponents(), unit_exponents);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> uvw;
    const double u_min = model.config.u_min, u_max = model.config.u_max;
    // The poles and the ends of the u range, v on the axes, then at random
    // (more than a batch, and not a whole number of batches).
    for (double u : {u_min, u_max, 0.0}) {
      for (double v : {-M_PI, -M_PI / 2, 0.0, M_PI / 2}) {
        uvw.insert(uvw.end(), {u, v, 0.0});
      }
    }
    for (int i = 0; i < 77; ++i) {
      uvw.insert(uvw.end(),
                 {u_min + (u_max - u_min) * unit(random),
                  -M_PI + 2 * M_PI * unit(random), 2.0 * unit(random) - 1.0});
    }
    const size_t n = uvw.size() / 3;
    std::vector<Eigen::Vector3d> points(n);
    WorldPoints(model, n, &uvw[0], &uvw[1], &uvw[2], 3, points.data());
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d expected =
          model.WorldPoint(uvw[3 * i], uvw[3 * i + 1], uvw[3 * i + 2]);
      EXPECT_LT((points[i] - expected).norm(), 1e-11)
          << "point " << i << " u " << uvw[3 * i] << " v " << uvw[3 * i + 1]
          << " w " << uvw[3 * i + 2]
          << (unit_exponents ? " unit exponents" : "");
    }
  }
}

// Points ring by ring, as surfaces and grids come (a ring's functions and
// Bessel values are taken once, from its first point): the same points as
// Model::WorldPoint's one by one, rings changing inside a batch and across
// batches, on the mid-wall and off it.  The bends differ from ring to ring,
// so a ring's values taken for the next would show.
TEST(WorldPointsTest, RingByRingMatchesOneByOne) {
  for (bool unit_exponents : {true, false}) {
    const Model model = DeformedModel(unit_exponents);
    std::vector<double> u, v, w;
    const double u_min = model.config.u_min, u_max = model.config.u_max;
    for (int ring = 0; ring < 7; ++ring) {
      for (int j = 0; j < 13; ++j) {
        u.push_back(u_min + (u_max - u_min) * (ring + 0.5) / 7);
        v.push_back(-M_PI + 2 * M_PI * j / 13);
        w.push_back(ring % 3 == 0 ? 0.0 : 0.5 * (j % 3 - 1));
      }
    }
    std::vector<Eigen::Vector3d> points(u.size());
    WorldPoints(model, u.size(), u.data(), v.data(), w.data(), 1,
                points.data());
    for (size_t i = 0; i < u.size(); ++i) {
      EXPECT_LT((points[i] - model.WorldPoint(u[i], v[i], w[i])).norm(), 1e-11)
          << "point " << i;
    }
  }
}

}  // namespace
}  // namespace pfdm
