#include "pfdm/phantom/lv_shape.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

TEST(LvPhantomShapeTest, HasTheRequestedSize) {
  const LvShape shape;
  EXPECT_NEAR(shape.Position(0.0, 1.0, 0.0).norm(), 0.0, 1e-12);
  EXPECT_NEAR(shape.Position(shape.BaseNu(0.0), 0.3, 0.0).z(), 95.0, 1e-9);
  EXPECT_NEAR(shape.BaseNu(0.0), 120.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(shape.Position(kPi / 2, 0.0, 0.0).x(), 27.0, 1e-9);
  // Confocal surfaces share their equator, where the wall is 10 mm thick.
  EXPECT_NEAR(shape.Position(kPi / 2, 0.0, 1.0).x() -
                  shape.Position(kPi / 2, 0.0, -1.0).x(),
              10.0, 1e-9);
  // Thinner at the apex: the endocardial pole above z = 0, the epicardial
  // below, about 4 mm apart.
  EXPECT_NEAR(shape.ApexZ(-1.0), 1.935, 1e-3);
  EXPECT_NEAR(shape.ApexZ(1.0), -2.329, 1e-3);
}

TEST(LvPhantomShapeTest, TransmuralAndHeightInvertPosition) {
  const LvShape shape;
  for (double w : {-1.0, -0.4, 0.0, 0.7, 1.0}) {
    for (double nu : {0.0, 0.3, 1.2, 2.0}) {
      const Eigen::Vector3d x = shape.Position(nu, 0.8, w);
      EXPECT_NEAR(shape.Transmural(x), w, 1e-9) << nu;
      EXPECT_NEAR(shape.NuAtHeight(x.z(), w), nu, 1e-7) << w;
    }
  }
}

// Chord sums along the meridian measure the arc independently.
double ChordLength(const LvShape& shape, double nu_end, double w) {
  double length = 0.0;
  constexpr int kSteps = 20000;
  for (int i = 0; i < kSteps; ++i) {
    length += (shape.Position(nu_end * (i + 1) / kSteps, 0.0, w) -
               shape.Position(nu_end * i / kSteps, 0.0, w))
                  .norm();
  }
  return length;
}

TEST(LvPhantomShapeTest, ArcFractionsSplitTheMeridianEvenly) {
  const LvShape shape;
  for (double w : {-1.0, 0.0, 1.0}) {
    EXPECT_NEAR(shape.NuAtArcFraction(0.0, w), 0.0, 1e-12);
    EXPECT_NEAR(shape.NuAtArcFraction(1.0, w), shape.BaseNu(w), 1e-12);
    const double whole = ChordLength(shape, shape.BaseNu(w), w);
    for (double f : {0.1, 0.5, 0.9}) {
      EXPECT_NEAR(ChordLength(shape, shape.NuAtArcFraction(f, w), w), f * whole,
                  1e-3 * whole)
          << w << " " << f;
    }
  }
}

TEST(LvPhantomShapeTest, ClosedVolumeMatchesSlices) {
  const LvShape shape;
  for (double w : {-1.0, 0.0, 1.0}) {
    // Midpoint rule over discs from the apex pole to the base plane.
    constexpr int kSlices = 20000;
    const double apex = shape.ApexZ(w), dz = (shape.base_z() - apex) / kSlices;
    double volume = 0.0;
    for (int i = 0; i < kSlices; ++i) {
      const double z = apex + (i + 0.5) * dz;
      const double r = shape.Position(shape.NuAtHeight(z, w), 0.0, w).x();
      volume += kPi * r * r * dz;
    }
    EXPECT_NEAR(shape.ClosedVolume(w), volume, 1e-6 * volume) << w;
  }
  EXPECT_NEAR(shape.ClosedVolume(0.0) / 1000.0, 163.18, 0.01);
  EXPECT_NEAR(shape.ClosedVolume(-1.0) / 1000.0, 106.93, 0.01);
}

}  // namespace
}  // namespace pfdm
