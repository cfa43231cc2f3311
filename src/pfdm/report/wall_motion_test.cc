#include "pfdm/report/wall_motion.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

Model Sphere(double radius_fraction) {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = values[kA3] = radius_fraction;
  return Model::Uniform(ModelConfig::Paper(17), values);
}

// Without an RV insertion: today's sectors from v = -pi, counter-clockwise,
// named by level and number, and the apex cap last.
TEST(WallMotionTest, PlainLayoutHasSeventeenSegmentsBasalFirst) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  ASSERT_EQ(regions.size(), 17u);
  EXPECT_EQ(regions[0].Name(), "basal 1");
  EXPECT_EQ(regions[6].Name(), "mid 1");
  EXPECT_EQ(regions[15].Name(), "apical 4");
  EXPECT_EQ(regions[15].segment, 16);
  EXPECT_EQ(regions[16].Name(), "apex");
  EXPECT_EQ(regions[16].segment, 17);
  EXPECT_EQ(regions[16].level, kApex);
  EXPECT_NEAR(regions[13].v_begin, -kPi / 2, 1e-12);
  EXPECT_NEAR(regions[13].v_end, 0.0, 1e-12);
  RegionLayout quarters;
  quarters.basal_sectors = quarters.mid_sectors = 4;
  quarters.apex_cap_fraction = 0.0;
  EXPECT_EQ(Regions(quarters).size(), 12u);
}

// The AHA's: anterior insertion at v = 1 rad, the septum at decreasing v.
// Basal 1 (anterior) runs from the insertion 60 degrees away from the
// septum, basal 2 and 3 (anteroseptal, inferoseptal) past it; apical
// septal is centred 60 degrees past the insertion.
TEST(WallMotionTest, AnatomicalLayoutHasTheAhaNamesAndPlaces) {
  RegionLayout layout;
  layout.anatomical = true;
  layout.anchor_v = 1.0;
  layout.direction = -1.0;
  const std::vector<WallRegion> regions = Regions(layout);
  ASSERT_EQ(regions.size(), 17u);
  const char* const names[] = {"basal anterior",
                               "basal anteroseptal",
                               "basal inferoseptal",
                               "basal inferior",
                               "basal inferolateral",
                               "basal anterolateral",
                               "mid anterior",
                               "mid anteroseptal",
                               "mid inferoseptal",
                               "mid inferior",
                               "mid inferolateral",
                               "mid anterolateral",
                               "apical anterior",
                               "apical septal",
                               "apical inferior",
                               "apical lateral",
                               "apex"};
  for (int r = 0; r < 17; ++r) {
    EXPECT_EQ(regions[r].Name(), names[r]);
    EXPECT_EQ(regions[r].segment, r + 1);
  }
  const double deg = kPi / 180;
  EXPECT_NEAR(regions[0].v_begin, 1.0, 1e-12);  // Anterior: [1, 1 + 60 deg).
  EXPECT_NEAR(regions[0].v_end, 1.0 + 60 * deg, 1e-12);
  EXPECT_NEAR(regions[1].v_end, 1.0, 1e-12);  // Anteroseptal ends there.
  EXPECT_NEAR(regions[2].v_begin, 1.0 - 120 * deg, 1e-12);
  EXPECT_NEAR(regions[13].v_begin, 1.0 - 105 * deg, 1e-12);  // Septal.
  EXPECT_NEAR(regions[13].v_end, 1.0 - 15 * deg, 1e-12);
  // v_begin wraps into [-pi, pi): basal inferolateral, 1 - 240 deg.
  EXPECT_NEAR(regions[4].v_begin, 1.0 - 240 * deg + 2 * kPi, 1e-12);
  // Assignment follows: just past the insertion toward the septum.
  const Model reference = Sphere(0.8);
  EXPECT_EQ(AssignRegion(reference, std::asin(0.3), 1.0 - 0.01, layout), 1);
  EXPECT_EQ(AssignRegion(reference, std::asin(0.3), 1.0 + 0.01, layout), 0);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.3), 1.0 - 1.1, layout), 8);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.3), 1.0 - 2.6, layout), 9);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.7), 1.0 - 0.3, layout), 13);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.7), 1.0 + 0.3, layout), 12);
  // The cap: the lowest tenth of the axis, sin u below -0.85.
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.86), 0.0, layout), 16);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.84), 1.0 - 1.0, layout), 13);
  // A layout of other sector counts keeps numbered names.
  layout.apical_sectors = 6;
  EXPECT_EQ(Regions(layout)[12].Name(), "apical 1");
}

TEST(WallMotionTest, AssignsByThirdsOfTheAxisAndSectorsOfLongitude) {
  // Rings at sin u from -1 (apex) to 0.5 (rim): thirds end at -0.5 and 0.
  const Model reference = Sphere(0.8);
  RegionLayout layout;
  layout.apex_cap_fraction = 0.0;  // The apical third whole.
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.8), -3.0, layout), 12);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.8), 0.1, layout), 14);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.45), 0.1, layout), 6 + 3);
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.05), -0.1, layout), 6 + 2);
  EXPECT_EQ(AssignRegion(reference, std::asin(0.3), 3.1, layout), 5);
  EXPECT_EQ(AssignRegion(reference, std::asin(0.3), kPi, layout), 0);  // Wraps.
  EXPECT_EQ(AssignRegion(reference, reference.config.u_min, 0.0, layout), 14);
  EXPECT_EQ(AssignRegion(reference, reference.config.u_max, -kPi, layout), 0);
  // A longer basal half moves the thirds up: the axis, not u, decides.
  Model stretched = reference;
  for (int k = 9; k < 17; ++k) stretched.state.knots[k][kA3] = 1.0;
  EXPECT_EQ(AssignRegion(reference, std::asin(-0.48), 0.1, layout), 9);
  EXPECT_EQ(AssignRegion(stretched, std::asin(-0.48), 0.1, layout), 14);
  // With the cap, the lowest tenth is segment 17 (index 16).
  EXPECT_EQ(
      AssignRegion(reference, reference.config.u_min, 0.0, RegionLayout()), 16);
}

TEST(WallMotionTest, UniformContractionAndLinearTwistPerSegment) {
  const Model reference = Sphere(0.8);
  Model current = Sphere(0.64);  // Every radius 20 % shorter.
  const int k = current.config.num_knots;
  for (int i = 0; i < k; ++i) {
    // -5 degrees at the apex to +2 at the base, linear along the axis.
    current.state.knots[i][kTau] = (-5.0 + 7.0 * i / (k - 1)) * kPi / 180.0;
  }
  const std::vector<RegionMotion> motion =
      SummarizeRegions(reference, current, RegionLayout());
  ASSERT_EQ(motion.size(), 17u);
  // Green-Lagrange: (0.8^2 - 1) / 2 along the circles of latitude; along
  // the meridians the twist, linear in sin u (dtau/du = c cos u, c = 7
  // degrees over 1.5 of sin u), adds 0.64 (c cos^2 u)^2 / 2 < 0.22 points
  // and a shear 0.64 c cos^2 u / 2 < 2.7 points.
  double area = 0.0;
  for (const RegionMotion& m : motion) {
    EXPECT_NEAR(m.radial_contraction_percent, 20.0, 1e-6);
    EXPECT_NEAR(m.ecc_percent, -18.0, 1e-5);
    EXPECT_GE(m.ell_percent, -18.0);
    EXPECT_LT(m.ell_percent, -18.0 + 0.22);
    EXPECT_GT(m.ecl_percent, 0.0);
    EXPECT_LT(m.ecl_percent, 2.7);
    area += m.area_mm2;
  }
  // A sphere of radius 40 mm from sin u = -1 to 0.5: 2 pi R^2 1.5.
  EXPECT_NEAR(area, 2 * kPi * 1600.0 * 1.5, 1e-3);
  // A sphere's area is uniform in sin u: each level's mean twist is tau at
  // the middle of its part of the axis, sin u = 0.25, -0.25, -0.675 (the
  // apical third less the cap, below -0.85), -0.925 (the cap).
  auto tau_at = [](double s) { return -5.0 + 7.0 * (s + 1.0) / 1.5; };
  EXPECT_NEAR(motion[0].rotation_deg, tau_at(0.25), 0.05);
  EXPECT_NEAR(motion[8].rotation_deg, tau_at(-0.25), 0.05);
  EXPECT_NEAR(motion[15].rotation_deg, tau_at(-0.675), 0.05);
  // The cap's 6 rows of samples: within 0.1.
  EXPECT_NEAR(motion[16].rotation_deg, tau_at(-0.925), 0.1);
  // The cap is a tenth of the sphere's area here.
  EXPECT_NEAR(motion[16].area_mm2, 2 * kPi * 1600.0 * 0.15, 1e-3);
  // No motion, no numbers.
  for (const RegionMotion& m :
       SummarizeRegions(reference, reference, RegionLayout())) {
    EXPECT_NEAR(m.rotation_deg, 0.0, 1e-12);
    EXPECT_NEAR(m.radial_contraction_percent, 0.0, 1e-9);
    EXPECT_NEAR(m.ecc_percent, 0.0, 1e-9);
    EXPECT_NEAR(m.ell_percent, 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace pfdm

namespace pfdm {
namespace {

void ExpectSameSamples(const ReferenceSamples& a, const ReferenceSamples& b) {
  ASSERT_EQ(a.samples.size(), b.samples.size());
  EXPECT_EQ(a.axis, b.axis);
  for (size_t i = 0; i < a.samples.size(); ++i) {
    const ReferenceSamples::Sample &x = a.samples[i], &y = b.samples[i];
    ASSERT_TRUE(x.region == y.region && x.weight == y.weight &&
                x.from == y.from && x.plane_inverse == y.plane_inverse &&
                x.thickness == y.thickness)
        << i;
  }
}

// A knot's step taken again only between its neighbours gives the samples
// taken on the moved model from scratch, row for row; a step of the first
// knot (the apex's height, which cuts the levels) takes every row again.
TEST(WallMotionTest, ResampleReferenceTakesWhatAStepMoves) {
  Model model = TestSpheroid(9);
  for (size_t k = 0; k < model.state.knots.size(); ++k) {
    model.state.knots[k][kA1] *= 1.0 + 0.05 * std::sin(1.3 * k);
    model.state.knots[k][kTau] = 0.02 * k;
  }
  const RegionLayout layout;
  const ReferenceSamples before = SampleReference(model, layout);
  const KnotGrid& grid = model.config.Grid();
  for (int knot : {0, 4}) {
    Model moved = model;
    moved.state.knots[knot][kA3] *= 1.1;
    ReferenceSamples samples = before;
    ResampleReference(moved, layout, knot == 0 ? -1e300 : grid.KnotU(knot - 1),
                      grid.KnotU(knot + 1), &samples);
    SCOPED_TRACE(knot);
    ExpectSameSamples(samples, SampleReference(moved, layout));
    // The step moved some samples, and an inner knot's not all: the rows
    // kept are compared too.
    size_t moved_samples = 0;
    for (size_t i = 0; i < samples.samples.size(); ++i) {
      moved_samples += samples.samples[i].from != before.samples[i].from;
    }
    EXPECT_GT(moved_samples, 0u);
    if (knot > 0) EXPECT_LT(moved_samples, samples.samples.size() / 2);
  }
  // A step of the first knot that keeps the apex's height (a1, not a3)
  // keeps every row's level: its span's rows alone, strictly inside u's
  // range, give the samples taken from scratch.
  Model widened = model;
  widened.state.knots[0][kA1] *= 1.2;
  ReferenceSamples samples = before;
  ResampleReference(widened, layout, std::nextafter(model.config.u_min, 0.0),
                    grid.KnotU(1), &samples);
  ExpectSameSamples(samples, SampleReference(widened, layout));
}

}  // namespace
}  // namespace pfdm
