#include "pfdm/phantom/lv_layer_truth.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/phantom/lv_cylinder.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

double Green(double stretch) { return 100.0 * 0.5 * (stretch * stretch - 1); }

// The cylinder's layers written down (lv_cylinder.h): a ring at (h, w)
// moves to radius r = RadialFactor R_w, so Ecc = Green(r / R); the chord
// across the wall, radial, by (r_epi - r_endo) / t; a length of axis by lambda
// and, sheared by the twist's gradient and the contraction's, by r
// dtheta/dz around the axis and dr/dz out from it.
struct CylinderLayers {
  double ecc[3], ell[3], thickening[3];
  double err;
};

CylinderLayers Written(const LvCylinder& c, const LvDeformation& design,
                       LvThickeningLaw law, double h) {
  auto radius_at = [&](double at, double w) {
    return RadialFactor(design, law, c.LawRadii(), at, w, 1.0) * c.Radius(w);
  };
  auto radius = [&](double w) { return radius_at(h, w); };
  const double lambda = 1.0 - design.longitudinal_shortening;
  const double twist_per_mm =
      (design.base_rotation_deg - design.apex_rotation_deg) /
      kDegreesPerRadian / c.length_mm;
  const double bounds[4] = {-1.0, -1.0 / 3, 1.0 / 3, 1.0};
  CylinderLayers out;
  out.err = Green((radius(1.0) - radius(-1.0)) / c.wall_mm);
  for (int k = 0; k < 3; ++k) {
    const double w = k - 1.0, step = 1e-5;
    out.ecc[k] = Green(radius(w) / c.Radius(w));
    const double twist = radius(w) * twist_per_mm;
    const double dr_dz = (radius_at(h + step, w) - radius_at(h - step, w)) /
                         (2 * step * c.length_mm);
    out.ell[k] =
        100.0 * 0.5 * (lambda * lambda + twist * twist + dr_dz * dr_dz - 1.0);
    out.thickening[k] =
        100.0 * ((radius(bounds[k + 1]) - radius(bounds[k])) /
                     (c.Radius(bounds[k + 1]) - c.Radius(bounds[k])) -
                 1.0);
  }
  return out;
}

// The formulas' mean over the mid level's heights, 1/3 to 2/3 (equal
// areas on a cylinder), by the midpoint rule.
CylinderLayers MidLevelMean(const LvCylinder& c, const LvDeformation& design,
                            LvThickeningLaw law) {
  constexpr int kHeights = 60;
  CylinderLayers mean{};
  mean.err = 0.0;
  for (int i = 0; i < kHeights; ++i) {
    const CylinderLayers at =
        Written(c, design, law, (1.0 + (i + 0.5) / kHeights) / 3.0);
    mean.err += at.err / kHeights;
    for (int k = 0; k < 3; ++k) {
      mean.ecc[k] += at.ecc[k] / kHeights;
      mean.ell[k] += at.ell[k] / kHeights;
      mean.thickening[k] += at.thickening[k] / kHeights;
    }
  }
  return mean;
}

// Measured on the cylinder's material points, each mid segment at
// end-systole is what the formulas give over its heights, under both laws,
// within 0.005 points; Err within 0.01 (0.006 off: the cells' rows, 0.007
// of h, do not end on the level's edges, and Err changes fastest with h).
TEST(LvLayerTruthTest, CylinderLayersAreTheWrittenOnes) {
  for (LvThickeningLaw law :
       {LvThickeningLaw::kDesigned, LvThickeningLaw::kIncompressible}) {
    LvPhantomOptions options;
    options.geometry = LvGeometry::kCylinder;
    options.tags = LvTagLayer::kWall;
    options.deformation = CylinderDeformation();
    options.law = law;
    options.num_tags = 50;
    options.num_frames = 3;
    const LvPhantom phantom = MakeLvPhantom(options);
    const auto truth = MeasureLvLayerTruth(phantom);
    ASSERT_EQ(truth.size(), 3u);
    ASSERT_EQ(truth[2].size(), 17u);
    const LvHeights band = LvRegionHeights(LvRegion::kMidventricular);
    const LvCylinder cylinder = CylinderOf(options.shape, band.low, band.high);
    const CylinderLayers written =
        MidLevelMean(cylinder, options.deformation, law);
    for (int s = 6; s < 12; ++s) {
      const LvSegmentLayers& segment = truth[2][s];
      EXPECT_EQ(segment.segment, s + 1);
      EXPECT_NEAR(segment.err_percent, written.err, 0.01);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(segment.layers[k].ecc_percent, written.ecc[k], 0.005) << k;
        EXPECT_NEAR(segment.layers[k].ell_percent, written.ell[k], 0.005) << k;
        EXPECT_NEAR(segment.layers[k].thickening_percent, written.thickening[k],
                    0.02)
            << k;
        // Frame 0 is the reference.
        EXPECT_NEAR(truth[0][s].layers[k].ecc_percent, 0.0, 1e-9);
      }
    }
    // Where the cylinder has no material: no number.
    EXPECT_TRUE(std::isnan(truth[2][16].layers[0].ecc_percent));
    if (law == LvThickeningLaw::kDesigned) {
      // The endocardium shortens most: 24 % contraction at h = 0.5.
      EXPECT_NEAR(Written(cylinder, options.deformation, law, 0.5).ecc[0],
                  Green(0.76), 0.05);
    }
  }
}

// Strain is the material's: a rigid motion of the prolate phantom reads
// zero everywhere; in systole the endocardium shortens more than the
// epicardium in every segment, and under the incompressible law its third
// thickens more (the designed law, a quadratic in w, thickens the outer
// third most: 85 % against 5 % in the mid segments).
TEST(LvLayerTruthTest, ProlateRigidMotionIsNoStrainSystoleIsLayered) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 50;
  options.kinematics = LvKinematics::kRigidTilt;
  const auto rigid = MeasureLvLayerTruth(MakeLvPhantom(options));
  for (const LvSegmentLayers& segment : rigid.back()) {
    EXPECT_NEAR(segment.err_percent, 0.0, 1e-5);
    for (const LvLayerValues& layer : segment.layers) {
      EXPECT_NEAR(layer.ecc_percent, 0.0, 1e-5);
      EXPECT_NEAR(layer.ell_percent, 0.0, 1e-5);
      EXPECT_NEAR(layer.thickening_percent, 0.0, 1e-5);
    }
  }
  options.kinematics = LvKinematics::kSystole;
  options.law = LvThickeningLaw::kIncompressible;
  const auto systole = MeasureLvLayerTruth(MakeLvPhantom(options));
  for (const LvSegmentLayers& segment : systole.back()) {
    EXPECT_LT(segment.layers[0].ecc_percent,
              segment.layers[2].ecc_percent - 5.0)
        << segment.segment;
    EXPECT_GT(segment.layers[0].thickening_percent,
              segment.layers[2].thickening_percent)
        << segment.segment;
    EXPECT_GT(segment.err_percent, 10.0) << segment.segment;
  }
}

}  // namespace
}  // namespace pfdm
