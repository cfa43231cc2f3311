#include "pfdm/model/raised_top.h"

#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A spheroid (radius 25 mm, half-length 40, cut 20 mm above its equator)
// whose radii taper toward the apex knot by knot, like an LV's.
Model TaperedSpheroid() {
  Model model = TestSpheroid(9);
  for (int k = 0; k < 9; ++k) {
    model.state.knots[k][kA1] = 0.35 + 0.02 * k;
    model.state.knots[k][kA2] = 0.33 + 0.02 * k;
  }
  return model;
}

// The apex stays, the top ring rises by 5 % of the length, and every knot's
// ring below the old top keeps its world radius at its world height: the
// new knot's ring is the old model's ring at the same height.
TEST(RaisedTopTest, KeepsTheApexAndTheShapeBelowTheOldTop) {
  const Model model = TaperedSpheroid();
  const Model raised = RaisedTop(model, 0.05);
  const ModelConfig& c = model.config;
  const Eigen::Vector3d apex = model.WorldPoint(c.u_min, 0.0);
  EXPECT_LT((raised.WorldPoint(c.u_min, 0.0) - apex).norm(), 1e-9);
  const double length = model.WorldPoint(c.u_max, 0.0).z() - apex.z();
  EXPECT_NEAR(raised.WorldPoint(c.u_max, 0.0).z() - apex.z(), 1.05 * length,
              1e-9);
  const KnotGrid grid(c.num_knots, c.u_min, c.u_max);
  int checked = 0;
  for (int k = 1; k < c.num_knots; ++k) {
    const Eigen::Vector3d ring = raised.WorldPoint(grid.KnotU(k), 0.0);
    if (ring.z() >= model.WorldPoint(c.u_max, 0.0).z()) continue;
    // The old model's ring at that height, by bisection on u.
    double low = c.u_min, high = c.u_max;
    for (int i = 0; i < 60; ++i) {
      const double middle = 0.5 * (low + high);
      (model.WorldPoint(middle, 0.0).z() < ring.z() ? low : high) = middle;
    }
    const Eigen::Vector3d old = model.WorldPoint(0.5 * (low + high), 0.0);
    EXPECT_NEAR(ring.x(), old.x(), 1e-6) << "knot " << k;
    EXPECT_NEAR(raised.WorldPoint(grid.KnotU(k), M_PI / 2).y(),
                model.WorldPoint(0.5 * (low + high), M_PI / 2).y(), 1e-6)
        << "knot " << k;
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// The volume grows by about the top's cross-section times the rise, more
// than the uniform stretch's mean cross-section (a3 scaled alone).
TEST(RaisedTopTest, TheVolumeGrowsByTheTopsSection) {
  const Model model = TaperedSpheroid();
  const ModelConfig& c = model.config;
  const double rise = 0.02;
  const double length =
      model.WorldPoint(c.u_max, 0.0).z() - model.WorldPoint(c.u_min, 0.0).z();
  const double top_x = model.WorldPoint(c.u_max, 0.0).x();
  const double top_y = model.WorldPoint(c.u_max, M_PI / 2).y();
  const double slab_ml = M_PI * top_x * top_y * rise * length / 1000.0;
  const double volume = CavityVolumeMl(model);
  const double raised = CavityVolumeMl(RaisedTop(model, rise)) - volume;
  Model stretched = model;
  stretched.state.globals[kA3] *= 1.0 + rise;
  for (FunctionValues& knot : stretched.state.knots) knot[kA3] *= 1.0 + rise;
  const double uniform = CavityVolumeMl(stretched) - volume;
  EXPECT_NEAR(uniform, rise * volume, 0.01 * rise * volume);
  // 1.87 ml against the slab's 1.77: between the knots the functions stay
  // linear in u while the rings' heights move.
  EXPECT_NEAR(raised, slab_ml, 0.08 * slab_ml);
  EXPECT_GT(raised, 1.2 * uniform);
  std::printf("raised %.3f ml, slab %.3f, uniform stretch %.3f\n", raised,
              slab_ml, uniform);
}

}  // namespace
}  // namespace pfdm
