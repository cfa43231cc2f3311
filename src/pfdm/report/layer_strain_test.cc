#include "pfdm/report/layer_strain.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// A spherical shell: mid-wall radius 30 mm, wall h (25 to 35 mm at 10).
Model Shell(double h) {
  ModelConfig config = ModelConfig::Paper(5);
  config.MakeSolid();
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  f[kA1] = f[kA2] = f[kA3] = 0.5;
  f[kH] = h;
  return Model::Uniform(config, f);
}

// Green-Lagrange strain of a stretch, percent.
double Green(double stretch) { return 100.0 * 0.5 * (stretch * stretch - 1); }

// The wall thickens from 10 to 12 mm about its mid-wall: the endocardium
// (25 -> 24 mm) shortens in both directions, the epicardium (35 -> 36)
// lengthens, the mid-wall keeps its length; the chord across the wall
// stretches 1.2 and every third of the wall thickens 20 %, in every segment.
TEST(LayerStrainTest, ThickerShellStretchesEachLayerByItsRadius) {
  const RegionLayout layout;
  const LayerSamples samples = SampleLayers(Shell(10.0), layout);
  const std::vector<RegionLayers> regions =
      SummarizeLayers(samples, Shell(12.0));
  ASSERT_EQ(regions.size(), 17u);
  const double radius_stretch[kWallLayers] = {24.0 / 25.0, 1.0, 36.0 / 35.0};
  for (size_t r = 0; r < regions.size(); ++r) {
    for (int k = 0; k < kWallLayers; ++k) {
      const LayerStrain& layer = regions[r].layers[k];
      EXPECT_NEAR(layer.ecc_percent, Green(radius_stretch[k]), 1e-4) << r;
      EXPECT_NEAR(layer.ell_percent, Green(radius_stretch[k]), 1e-4) << r;
      EXPECT_NEAR(layer.thickening_percent, 20.0, 1e-6) << r;
    }
    EXPECT_NEAR(regions[r].err_percent, Green(1.2), 1e-4) << r;
  }
  EXPECT_NEAR(Green(24.0 / 25.0), -3.92, 1e-9);
}

// Strain is the material's: a rigid motion of the current frame reads
// zero in every layer.
TEST(LayerStrainTest, RigidMotionReadsNoStrain) {
  const Model reference = Shell(10.0);
  Model moved = reference;
  moved.state.center = {10.0, -4.0, 7.0};
  const double norm = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
  moved.state.quaternion = {0.9 / norm, 0.1 / norm, -0.3 / norm, 0.2 / norm};
  const std::vector<RegionLayers> regions =
      SummarizeLayers(SampleLayers(reference, RegionLayout()), moved);
  ASSERT_EQ(regions.size(), 17u);
  for (const RegionLayers& region : regions) {
    EXPECT_NEAR(region.err_percent, 0.0, 1e-5);
    for (const LayerStrain& layer : region.layers) {
      EXPECT_NEAR(layer.ecc_percent, 0.0, 1e-5);
      EXPECT_NEAR(layer.ell_percent, 0.0, 1e-5);
      EXPECT_NEAR(layer.thickening_percent, 0.0, 1e-6);
    }
  }
}

// A squeeze moves the layers inside the wall, not its walls: the walls'
// surfaces keep their strain-free state, the middle third thins, the outer
// thirds thicken, and the wall's chord, Err across it, keeps its length.
TEST(LayerStrainTest, SqueezeMovesTheInnerLayersOnly) {
  const Model reference = Shell(10.0);
  Model squeezed = reference;
  for (FunctionValues& knot : squeezed.state.knots) knot[kWallSqueeze] = 1.0;
  squeezed.state.globals[kWallSqueeze] = 1.0;
  const std::vector<RegionLayers> regions =
      SummarizeLayers(SampleLayers(reference, RegionLayout()), squeezed);
  ASSERT_FALSE(regions.empty());
  // Depth k(w) = 5 w + (w^3 - w): the thirds' bounds at -+1/3 move to
  // -+(5/3 - 8/27) = -+1.3704 mm from the mid-wall (from 1.6667).
  const double middle = 2.0 * (5.0 / 3.0 - 8.0 / 27.0);
  const double outer = 5.0 - middle / 2.0;
  for (const RegionLayers& region : regions) {
    EXPECT_NEAR(region.layers[0].ecc_percent, 0.0, 1e-4);
    EXPECT_NEAR(region.layers[2].ell_percent, 0.0, 1e-4);
    EXPECT_NEAR(region.layers[1].thickening_percent,
                100.0 * (middle / (10.0 / 3.0) - 1.0), 1e-4);
    EXPECT_NEAR(region.layers[0].thickening_percent,
                100.0 * (outer / (10.0 / 3.0) - 1.0), 1e-4);
    // The chord across the wall keeps its ends.
    EXPECT_NEAR(region.err_percent, 0.0, 1e-6);
  }
}

TEST(LayerStrainTest, AMidWallSurfaceHasNoLayers) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  f[kA1] = f[kA2] = f[kA3] = 0.5;
  const Model surface = Model::Uniform(ModelConfig::Paper(5), f);
  const LayerSamples samples = SampleLayers(surface, RegionLayout());
  EXPECT_TRUE(samples.samples.empty());
  EXPECT_TRUE(SummarizeLayers(samples, surface).empty());
}

}  // namespace
}  // namespace pfdm
