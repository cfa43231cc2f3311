#include "pfdm/fit/correspondence/neighbour_noise.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/tangential_stretch.h"
#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/testing/stretched_noise.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// Tags on a spheroid's mid-wall with residuals of noise 0.5 mm per
// coordinate in each frame (0.5 sqrt(2) per tangential direction) on top of
// a misfit that varies smoothly over the surface, 0.6 mm at most.
struct Tags {
  std::vector<MaterialPoint> material;
  std::vector<Eigen::Vector3d> positions, residuals;
  std::vector<size_t> which;
};
Tags NoisyTags(const Model& model, double noise_mm, double misfit_mm) {
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, noise_mm * std::sqrt(2.0));
  std::uniform_real_distribution<double> u(-1.2, 0.4), v(-3.1, 3.1);
  Tags tags;
  for (int i = 0; i < 3000; ++i) {
    const MaterialPoint m{u(random), v(random), 0.0};
    tags.material.push_back(m);
    tags.positions.push_back(model.WorldPoint(m.u, m.v));
    const Eigen::Vector3d misfit =
        misfit_mm * Eigen::Vector3d(std::sin(2.0 * m.v), std::cos(m.u),
                                    std::sin(m.u + m.v));
    tags.residuals.push_back(
        misfit + Eigen::Vector3d(noise(random), noise(random), noise(random)));
    tags.which.push_back(i);
  }
  return tags;
}

TEST(NeighbourNoiseTest, LeavesTheSmoothMisfitOut) {
  const Model model = TestSpheroid(9);
  const Tags tags = NoisyTags(model, 0.5, 0.6);
  const double neighbours = NeighbourTangentialNoiseMm(
      model, tags.positions, tags.residuals, tags.material, tags.which);
  const double robust = NeighbourTangentialNoiseMm(
      model, tags.positions, tags.residuals, tags.material, tags.which, true);
  std::printf("noise from neighbours %.3f (robust %.3f) mm\n", neighbours,
              robust);
  EXPECT_NEAR(neighbours, 0.5, 0.02);
  EXPECT_NEAR(robust, 0.5, 0.03);
  // Each residual alone reads the misfit as noise.
  EXPECT_GT(TangentialNoiseMm(model, tags.residuals, tags.material, tags.which),
            0.56);
}

TEST(NeighbourNoiseTest, ReadsLittleWithoutNoise) {
  const Model model = TestSpheroid(9);
  const Tags tags = NoisyTags(model, 0.0, 0.6);
  EXPECT_LT(NeighbourTangentialNoiseMm(model, tags.positions, tags.residuals,
                                       tags.material, tags.which),
            0.03);
  EXPECT_GT(TangentialNoiseMm(model, tags.residuals, tags.material, tags.which),
            0.15);
}

// Frame 0's tangential noise carried into a frame that contracted the
// spheroid's radius by a fifth (its (u, v) is frame 0's closest point), on
// top of the frame's own: read as 0.5 mm given each tag's stretch, from
// neighbours and from each residual alone (TangentialNoiseMm), lower
// without.
TEST(NeighbourNoiseTest, TakesFrameZerosNoiseAsStretched) {
  const Model first = TestSpheroid(9);
  const Model later = RadiallyScaled(first, 0.8);
  Tags tags = NoisyTags(first, 0.0, 0.0);
  tags.residuals = StretchedTagResiduals(first, later, tags.material, 0.5, 11);
  for (size_t i = 0; i < tags.material.size(); ++i) {
    tags.positions[i] =
        later.WorldPoint(tags.material[i].u, tags.material[i].v);
  }
  const std::vector<double> stretch =
      TangentialStretchSquared(first, later, tags.material);
  const double given =
      NeighbourTangentialNoiseMm(later, tags.positions, tags.residuals,
                                 tags.material, tags.which, false, &stretch);
  const double robust =
      NeighbourTangentialNoiseMm(later, tags.positions, tags.residuals,
                                 tags.material, tags.which, true, &stretch);
  const double unstretched = NeighbourTangentialNoiseMm(
      later, tags.positions, tags.residuals, tags.material, tags.which);
  std::printf("stretched %.3f (robust %.3f), unstretched %.3f mm\n", given,
              robust, unstretched);
  EXPECT_NEAR(given, 0.5, 0.02);
  EXPECT_NEAR(robust, 0.5, 0.03);
  // Without the stretch every tag is read as if frame 0's noise reached
  // it whole: sigma^2 (2 + |F|^2) / 4 for sigma^2.
  double gain = 0.0;
  for (double s : stretch) gain += (2.0 + s) / 4.0 / stretch.size();
  EXPECT_LT(gain, 0.95);
  EXPECT_NEAR(unstretched / given, std::sqrt(gain), 0.01);
  const double alone = TangentialNoiseMm(later, tags.residuals, tags.material,
                                         tags.which, false, &stretch);
  EXPECT_NEAR(alone, 0.5, 0.015);
  EXPECT_NEAR(TangentialNoiseMm(later, tags.residuals, tags.material,
                                tags.which, true, &stretch),
              0.5, 0.025);
  EXPECT_NEAR(
      TangentialNoiseMm(later, tags.residuals, tags.material, tags.which) /
          alone,
      std::sqrt(gain), 0.01);
}

TEST(NeighbourNoiseTest, NoneForFewerThanTwoTags) {
  const Model model = TestSpheroid(9);
  const Tags tags = NoisyTags(model, 0.5, 0.0);
  EXPECT_EQ(NeighbourTangentialNoiseMm(model, tags.positions, tags.residuals,
                                       tags.material, {0}),
            0.0);
}

// Residuals of 0.8 mm along each tag's normal and 0.5 mm per coordinate
// across it, on a smooth misfit of 0.6 mm: the excess along the normal,
// 0.64 - 0.25 mm^2, without the misfit, which each residual alone would
// count (its sd along the normal is then 0.91 mm).
TEST(NeighbourNoiseTest, ExcessAlongTheNormalLeavesTheMisfitOut) {
  const Model model = TestSpheroid(9);
  Tags tags = NoisyTags(model, 0.0, 0.6);
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, tags.material);
  std::mt19937 random(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  double along = 0.0;
  for (size_t i = 0; i < tags.residuals.size(); ++i) {
    Eigen::Vector3d across(unit(random), unit(random), unit(random));
    across -= across.dot(normals[i]) * normals[i];
    tags.residuals[i] += 0.8 * unit(random) * normals[i] + 0.5 * across;
    along += std::pow(tags.residuals[i].dot(normals[i]), 2) /
             static_cast<double>(tags.residuals.size());
  }
  const double excess =
      NeighbourNormalExcessMm2(tags.positions, tags.residuals, normals);
  std::printf("excess along the normal %.3f mm^2 (sd alone %.3f mm)\n", excess,
              std::sqrt(along));
  EXPECT_NEAR(excess, 0.64 - 0.25, 0.05);
  EXPECT_GT(std::sqrt(along), 0.85);
  EXPECT_EQ(NeighbourNormalExcessMm2({tags.positions[0]}, {tags.residuals[0]},
                                     {normals[0]}),
            0.0);
}

}  // namespace
}  // namespace pfdm
