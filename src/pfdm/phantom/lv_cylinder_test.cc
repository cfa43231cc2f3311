#include "pfdm/phantom/lv_cylinder.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

constexpr double kMid = 0.5;  // A ring height inside the segment (0.30-0.72).

int RingIndex(double h) {
  const std::vector<double> heights = LvRingHeights();
  for (size_t i = 0; i < heights.size(); ++i) {
    if (std::abs(heights[i] - h) < 1e-9) return static_cast<int>(i);
  }
  return -1;
}

// The designed law at h = 0.5, ES: c_mid 0.22, endocardium 0.30, epicardium
// 0.065: radii 22 -> 15.4 and 32 -> 29.92 mm, thickness 10 -> 14.52 mm.
TEST(LvCylinderTest, DesignedTruthByHand) {
  const LvCylinder cylinder = CylinderOf(LvShapeSize(), 0.30, 0.72);
  const LvFrameTruth truth =
      CylinderTruth(cylinder, LvDeformation(), LvThickeningLaw::kDesigned, 1.0);
  const int i = RingIndex(kMid);
  ASSERT_GE(i, 0);
  EXPECT_NEAR(truth.endo.radial_contraction_percent[i], 30.0, 1e-9);
  EXPECT_NEAR(truth.midwall.radial_contraction_percent[i], 22.0, 1e-9);
  EXPECT_NEAR(truth.epi.radial_contraction_percent[i], 6.5, 1e-9);
  EXPECT_NEAR(truth.wall_thickening_percent[i], 45.2, 1e-9);
  EXPECT_NEAR(truth.longitudinal_shortening_percent, 17.0, 1e-12);
  // Rotation -10 + 13 h degrees.
  EXPECT_NEAR(truth.endo.rotation_deg[i], -3.5, 1e-12);
  // ED: the shell between radii 22 and 32 mm, 0.42 x 95 mm long.
  const LvFrameTruth ed =
      CylinderTruth(cylinder, LvDeformation(), LvThickeningLaw::kDesigned, 0.0);
  EXPECT_NEAR(ed.myocardial_volume_ml,
              3.14159265358979 * (32 * 32 - 22 * 22) * 0.42 * 95 / 1000, 1e-3);
}

// The incompressible law keeps the myocardium's volume exactly and moves
// the endocardium farther than the designed law's profile of the same
// epicardium: at h = 0.5, ES, r_endo^2 = 29.92^2 - (32^2 - 22^2) / 0.83.
TEST(LvCylinderTest, IncompressibleKeepsTheVolume) {
  const LvCylinder cylinder = CylinderOf(LvShapeSize(), 0.30, 0.72);
  const LvFrameTruth ed = CylinderTruth(cylinder, LvDeformation(),
                                        LvThickeningLaw::kIncompressible, 0.0);
  const LvFrameTruth es = CylinderTruth(cylinder, LvDeformation(),
                                        LvThickeningLaw::kIncompressible, 1.0);
  EXPECT_NEAR(es.myocardial_volume_ml, ed.myocardial_volume_ml,
              1e-9 * ed.myocardial_volume_ml);
  const int i = RingIndex(kMid);
  const double endo = std::sqrt(29.92 * 29.92 - (32.0 * 32 - 22 * 22) / 0.83);
  EXPECT_NEAR(es.endo.radial_contraction_percent[i], 100 * (1 - endo / 22),
              1e-9);
  EXPECT_NEAR(es.epi.radial_contraction_percent[i], 6.5, 1e-9);
  EXPECT_NEAR(es.wall_thickening_percent[i], 100 * ((29.92 - endo) / 10 - 1),
              1e-9);
  // Endocardial thickening exceeds epicardial: the inner half of the wall
  // thickens more than the outer.
  const double mid = 27 * (1 - es.midwall.radial_contraction_percent[i] / 100);
  EXPECT_GT((mid - endo) / 5.0, (29.92 - mid) / 5.0);
}

// The tags move as the truth says: each noise-free tag's distance from the
// world axis, over its ED distance, is 1 minus its layer's contraction.
TEST(LvCylinderTest, TagsMoveAsTheTruth) {
  for (LvThickeningLaw law :
       {LvThickeningLaw::kDesigned, LvThickeningLaw::kIncompressible}) {
    LvPhantomOptions options;
    options.geometry = LvGeometry::kCylinder;
    options.law = law;
    options.tags = LvTagLayer::kWall;
    options.noise_mm = 0.0;
    options.num_tags = 200;
    const LvPhantom phantom = MakeLvPhantom(options);
    EXPECT_EQ(phantom.options.region, LvRegion::kMidventricular);
    const LvCylinder cylinder = CylinderOf(LvShapeSize(), 0.30, 0.72);
    const LvFrameTruth& es = phantom.truth.back();
    for (int i = 0; i < options.num_tags; ++i) {
      const LvMaterialPoint m = cylinder.MaterialPoint(phantom.tag_material[i]);
      ASSERT_GE(m.h, 0.30 - 1e-12);
      ASSERT_LE(m.h, 0.72 + 1e-12);
      ASSERT_LE(std::abs(m.w), 1.0);
      const Eigen::Vector3d body =
          es.world_from_body.inverse() *
          phantom.points.frames.back().points[i].position;
      const double ratio = std::hypot(body.x(), body.y()) / m.radius;
      const double factor = RadialFactor(LvDeformation(), law,
                                         cylinder.LawRadii(), m.h, m.w, 1.0);
      EXPECT_NEAR(ratio, factor, 1e-9) << i;
      EXPECT_NEAR(body.z(), 0.83 * m.z, 1e-9) << i;
      if (std::abs(m.w + 1) < 0.02) {
        EXPECT_NEAR(100 * (1 - ratio),
                    LvRingValueAt(es.endo.radial_contraction_percent, m.h), 0.6)
            << i;
      }
    }
  }
}

// The cylinder's own motion: about 30 % thickening under either law.
TEST(LvCylinderTest, CylinderDeformationThickensAbout30Percent) {
  const LvCylinder cylinder = CylinderOf(LvShapeSize(), 0.30, 0.72);
  const int i = RingIndex(kMid);
  const LvFrameTruth designed = CylinderTruth(cylinder, CylinderDeformation(),
                                              LvThickeningLaw::kDesigned, 1.0);
  EXPECT_NEAR(designed.wall_thickening_percent[i], 33.6, 1e-9);
  EXPECT_NEAR(designed.endo.radial_contraction_percent[i], 24.0, 1e-9);
  const LvFrameTruth incompressible = CylinderTruth(
      cylinder, CylinderDeformation(), LvThickeningLaw::kIncompressible, 1.0);
  EXPECT_NEAR(incompressible.wall_thickening_percent[i], 30.2, 0.05);
  EXPECT_NEAR(incompressible.endo.radial_contraction_percent[i], 22.4, 0.05);
  EXPECT_NEAR(incompressible.epi.radial_contraction_percent[i], 6.0, 1e-9);
}

TEST(LvCylinderTest, Names) {
  LvGeometry geometry;
  EXPECT_TRUE(ParseLvGeometry("cylinder", &geometry));
  EXPECT_EQ(LvGeometryName(geometry), "cylinder");
  EXPECT_FALSE(ParseLvGeometry("cube", &geometry));
  LvThickeningLaw law;
  EXPECT_TRUE(ParseLvThickeningLaw("incompressible", &law));
  EXPECT_EQ(LvThickeningLawName(law), "incompressible");
  EXPECT_FALSE(ParseLvThickeningLaw("linear", &law));
}

}  // namespace
}  // namespace pfdm
