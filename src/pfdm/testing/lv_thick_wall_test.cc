// The solid model (model/transmural.h) on the independent LV phantom with
// tags through a 10 mm wall: the cavity, the ejection fraction, the walls'
// rotations and the wall's thickening, against the phantom's truth
// measured on its own material points.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/wall_motion.h"

namespace pfdm {
namespace {

struct ThickFit {
  LvPhantom phantom;
  SequenceFit fit;
  std::vector<ClinicalSummary> clinical;
};

ThickFit FitThickPhantom(LvPhantomOptions options,
                         const FitOptions& fit_options = FitOptions()) {
  ThickFit result{MakeLvPhantom(options), {}, {}};
  result.fit =
      FitSequence(result.phantom.points, ModelConfig::Paper(17), fit_options);
  std::vector<Model> models;
  for (size_t t = 0; t < result.fit.frames.size(); ++t) {
    models.push_back(result.fit.ModelAt(t));
  }
  result.clinical = SummarizeSequence(models);
  return result;
}

ThickFit FitThickPhantom(LvTagLayer tags = LvTagLayer::kWall) {
  LvPhantomOptions options;
  options.tags = tags;
  return FitThickPhantom(options);
}

double Rotation(const LvLayerRings& rings, double h) {
  return LvRingValueAt(rings.rotation_deg, h);
}

// A ring array's mean over the summary's contraction rings, as the fit's
// numbers average them.
double OverContractionRings(const std::vector<double>& values) {
  double sum = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    sum += LvRingValueAt(values, (i + 0.5) / kContractionRings);
  }
  return sum / kContractionRings;
}

double Contraction(const LvLayerRings& rings) {
  return OverContractionRings(rings.radial_contraction_percent);
}

double Thickening(const LvFrameTruth& truth) {
  return OverContractionRings(truth.wall_thickening_percent);
}

const ThickFit& Wall() {
  static const ThickFit* fit = new ThickFit(FitThickPhantom());
  return *fit;
}

// Tags through a 10 mm wall (4 mm at the apex), 0.5 mm noise: the cavity
// within 5 % at ED and ES, the ejection fraction within 0.03, each wall's
// apex and base rotation within 1 degree and its radial contraction within
// 2.5 points, wall thickening within 3 points (37.5 % against 39.6 % at
// ES; 1.3 of the 2.1 are the model's quadratic profile across the wall
// against the phantom's, seen with noise-free tags), at the noise floor.
// The tags' noise is measured (0.5 mm) and taken out of h (docs/gauge.md,
// The wall).
TEST(LvThickWallTest, TagsThroughTheWallMakeASolid) {
  const ThickFit& f = Wall();
  ASSERT_TRUE(f.fit.config.Solid()) << f.fit.wall_reason;
  std::printf("wall: %s, tag noise %.3f mm\n", f.fit.wall_reason.c_str(),
              f.fit.tag_noise_mm);
  EXPECT_NEAR(f.fit.tag_noise_mm, 0.5, 0.1);
  for (size_t t = 0; t < f.clinical.size(); ++t) {
    // Frame 0's rounds among them (the chained axis gauge once left them
    // creeping, unconverged after 1,058 iterations).
    EXPECT_EQ(f.fit.frames[t].termination, "CONVERGENCE") << "frame " << t;
    const ClinicalSummary& c = f.clinical[t];
    const LvFrameTruth& truth = f.phantom.truth[t];
    std::printf(
        "frame %zu rms %.2f cavity %.1f (%.1f) myo %.1f (%.1f) thick %.2f "
        "thickening %.1f  endo apex %.2f (%.2f) base %.2f (%.2f)  epi apex "
        "%.2f (%.2f) base %.2f (%.2f)  RC endo %.1f (%.1f) epi %.1f (%.1f) "
        "thickening truth %.1f\n",
        t, f.fit.frames[t].rms_mm, c.volume_ml, truth.endo_volume_ml,
        c.myocardial_volume_ml, truth.myocardial_volume_ml, c.wall_thickness_mm,
        c.wall_thickening_percent, c.endo_apex_rotation_deg,
        Rotation(truth.endo, kApicalRingFraction), c.endo_base_rotation_deg,
        Rotation(truth.endo, kBasalRingFraction), c.epi_apex_rotation_deg,
        Rotation(truth.epi, kApicalRingFraction), c.epi_base_rotation_deg,
        Rotation(truth.epi, kBasalRingFraction),
        c.endo_radial_contraction_percent, Contraction(truth.endo),
        c.epi_radial_contraction_percent, Contraction(truth.epi),
        Thickening(truth));
    const double truth_cavity = truth.endo_volume_ml;
    EXPECT_NEAR(c.volume_ml, truth_cavity, 0.05 * truth_cavity) << t;
    EXPECT_NEAR(c.endo_apex_rotation_deg,
                Rotation(truth.endo, kApicalRingFraction), 1.0)
        << t;
    EXPECT_NEAR(c.endo_base_rotation_deg,
                Rotation(truth.endo, kBasalRingFraction), 1.0)
        << t;
    EXPECT_NEAR(c.epi_apex_rotation_deg,
                Rotation(truth.epi, kApicalRingFraction), 1.0)
        << t;
    EXPECT_NEAR(c.epi_base_rotation_deg,
                Rotation(truth.epi, kBasalRingFraction), 1.0)
        << t;
    EXPECT_NEAR(c.endo_radial_contraction_percent, Contraction(truth.endo), 2.5)
        << t;
    EXPECT_NEAR(c.epi_radial_contraction_percent, Contraction(truth.epi), 2.5)
        << t;
    EXPECT_NEAR(c.wall_thickening_percent, Thickening(truth), 3.0) << t;
    // Noise 0.5 mm per coordinate at frame t and in frame 0's material
    // points: sqrt(6) 0.5 = 1.22 mm, less what the ranks absorb across the
    // wall.
    EXPECT_LT(f.fit.frames[t].rms_mm, t == 0 ? 0.5 : 1.22) << t;
  }
  const size_t es = f.clinical.size() - 1;
  const double ef = 1.0 - f.clinical[es].volume_ml / f.clinical[0].volume_ml;
  const double truth_ef = 1.0 - f.phantom.truth[es].endo_volume_ml /
                                    f.phantom.truth[0].endo_volume_ml;
  std::printf("EF %.3f (truth %.3f)\n", ef, truth_ef);
  EXPECT_NEAR(ef, truth_ef, 0.03);
  // The myocardium keeps its volume, in the fit as in the phantom.
  EXPECT_NEAR(f.clinical[es].myocardial_volume_ml,
              f.clinical[0].myocardial_volume_ml,
              0.05 * f.clinical[0].myocardial_volume_ml);
  // So does its material, apex to rim (material_myocardium.h), within 5 %
  // at every frame as the truth's within 1 %.
  for (const ClinicalSummary& c : f.clinical) {
    std::printf("frame %d material myocardium %.1f ml %+.2f %% (truth %+.2f)\n",
                c.frame, c.material_myocardium_ml,
                c.myocardial_volume_change_percent,
                100.0 * (f.phantom.truth[c.frame].myocardial_volume_ml /
                             f.phantom.truth[0].myocardial_volume_ml -
                         1.0));
    EXPECT_NEAR(c.myocardial_volume_change_percent, 0.0, 5.0) << c.frame;
  }
}

// The same tags on the mid-wall only: one surface, as before the solid.
// The tags' noise is measured on the global model's residuals: the local
// field, with nearly as many unknowns as 400 tags have coordinates, fits
// part of it, and measured after the field 0.5 mm read 0.36-0.39 (seeds
// 1000-1002; 0.48-0.50 without the field), so that h kept part of its
// widening (wall_stage.h).
TEST(LvThickWallTest, TagNoiseIsMeasuredAlikeWithAndWithoutTheLocalField) {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = 400;
  options.tags = LvTagLayer::kWall;
  options.seed = 1000;
  const LvPhantom phantom = MakeLvPhantom(options);
  double noise[2];
  for (bool local : {false, true}) {
    FitOptions fit_options;
    fit_options.local.enabled = local;
    const SequenceFit fit =
        FitSequence(phantom.points, ModelConfig::Paper(9), fit_options);
    ASSERT_TRUE(fit.config.Solid()) << fit.wall_reason;
    noise[local] = fit.tag_noise_mm;
  }
  EXPECT_NEAR(noise[0], 0.5, 0.04);
  EXPECT_NEAR(noise[1], noise[0], 0.005);
}

TEST(LvThickWallTest, MidwallTagsKeepOneSurface) {
  const ThickFit f = FitThickPhantom(LvTagLayer::kMidwall);
  EXPECT_FALSE(f.fit.config.Solid()) << f.fit.wall_reason;
  EXPECT_NE(f.fit.wall_reason.find("one surface"), std::string::npos)
      << f.fit.wall_reason;
  EXPECT_EQ(f.fit.surface, WallLayer::kAnywhere);
  EXPECT_FALSE(f.clinical.back().solid);
  EXPECT_EQ(f.clinical.back().lv_mass_g, 0.0);
}

// Segments: thickening per AHA segment within 3 points of the phantom's
// on average.
TEST(LvThickWallTest, SegmentsThicken) {
  const ThickFit& f = Wall();
  const Model reference = f.fit.ModelAt(0);
  const size_t es = f.clinical.size() - 1;
  RegionLayout sixteen;  // As the phantom's truth: the apical third whole.
  sixteen.apex_cap_fraction = 0.0;
  const std::vector<RegionMotion> motion =
      SummarizeRegions(reference, f.fit.ModelAt(es), sixteen);
  const std::vector<LvSegmentTruth>& truth = f.phantom.truth[es].segments;
  for (size_t r = 0; r < motion.size(); ++r) {
    std::printf("segment %2zu thickening %.1f (truth %.1f)\n", r + 1,
                motion[r].thickening_percent, truth[r].wall_thickening_percent);
    EXPECT_GT(motion[r].thickening_percent, 10.0) << r;
  }
  double fit_mean = 0.0, truth_mean = 0.0;
  for (size_t r = 0; r < motion.size(); ++r) {
    fit_mean += motion[r].thickening_percent / motion.size();
    truth_mean += truth[r].wall_thickening_percent / motion.size();
  }
  EXPECT_NEAR(fit_mean, truth_mean, 3.0);
}

// --incompressible (weight 1) on data whose myocardium keeps its volume
// (the truth's within 1 %): the material myocardium comes closer to frame
// 0's, and the other clinical numbers stay within the tolerances above
// but thickening, which pays for it (docs/accuracy.md, "The myocardium"):
// the free fits read their volume 2-4 % high with thickening right, and
// the constraint takes the volume out of the wall's thickness.
void ExpectIncompressibleKeepsVolume(const LvPhantomOptions& phantom,
                                     double worst_bound,
                                     double thickening_points,
                                     double radial_points = 2.5) {
  FitOptions options;
  const ThickFit free = FitThickPhantom(phantom, options);
  options.incompressible_weight = 1.0;
  const ThickFit held = FitThickPhantom(phantom, options);
  ASSERT_TRUE(held.fit.config.Solid());
  double worst_free = 0.0, worst_held = 0.0;
  for (size_t t = 0; t < held.clinical.size(); ++t) {
    const ClinicalSummary &c = held.clinical[t], &before = free.clinical[t];
    const LvFrameTruth& truth = held.phantom.truth[t];
    std::printf(
        "frame %zu myocardium %+.2f %% (free %+.2f)  thickening %.1f (free "
        "%.1f, truth %.1f)  RC endo %.1f (%.1f) epi %.1f (%.1f)  rms %.3f "
        "(%.3f)\n",
        t, c.myocardial_volume_change_percent,
        before.myocardial_volume_change_percent, c.wall_thickening_percent,
        before.wall_thickening_percent, Thickening(truth),
        c.endo_radial_contraction_percent, Contraction(truth.endo),
        c.epi_radial_contraction_percent, Contraction(truth.epi),
        held.fit.frames[t].rms_mm, free.fit.frames[t].rms_mm);
    worst_free =
        std::max(worst_free, std::abs(before.myocardial_volume_change_percent));
    worst_held =
        std::max(worst_held, std::abs(c.myocardial_volume_change_percent));
    EXPECT_NEAR(c.wall_thickening_percent, Thickening(truth), thickening_points)
        << t;
    EXPECT_LT(c.wall_thickening_percent, before.wall_thickening_percent + 0.1)
        << t;
    EXPECT_NEAR(c.endo_radial_contraction_percent, Contraction(truth.endo),
                radial_points)
        << t;
    EXPECT_NEAR(c.epi_radial_contraction_percent, Contraction(truth.epi),
                radial_points)
        << t;
    EXPECT_NEAR(c.volume_ml, truth.endo_volume_ml, 0.05 * truth.endo_volume_ml)
        << t;
    EXPECT_LT(held.fit.frames[t].rms_mm, free.fit.frames[t].rms_mm + 0.02) << t;
  }
  std::printf("worst material change %.2f %% (free %.2f %%)\n", worst_held,
              worst_free);
  EXPECT_LT(worst_held, worst_bound);
  EXPECT_GT(worst_free, 2.0 * worst_bound);  // What it took out.
}

TEST(LvThickWallTest, IncompressibleTagsKeepTheirVolume) {
  LvPhantomOptions phantom;
  phantom.tags = LvTagLayer::kWall;
  // Noise-free: a noisy wall is fitted widened by the noise and narrowed
  // after the fit (TakeOutTagNoise), frame 0's less than the others', so
  // the volume the constraint holds is not the one reported
  // (docs/accuracy.md).
  phantom.noise_mm = 0.0;
  ExpectIncompressibleKeepsVolume(phantom, 0.5, 3.0);
}

TEST(LvThickWallTest, IncompressibleContoursKeepTheirVolume) {
  LvPhantomOptions phantom;
  phantom.tags = LvTagLayer::kWall;
  phantom.sampling = LvSampling::kSaxSlices;
  // Long-axis planes pin the wall's length: with short-axis slices alone
  // the free fit's material myocardium reads +15 % and the constraint
  // thins the wall for it, thickening 8 points under the truth.
  phantom.num_long_axis_planes = 3;
  // Untracked frames are pulled toward frame 0's radii, at 0.3 of the
  // strength where the slices cover a ring (FitOptions::
  // untracked_prior_covered_radii_scale): the endocardium's radial
  // contraction reads 0.8-1.5 points under the truth's (28.6 % at
  // end-systole against 30.0; 27.1 with the full pull).
  ExpectIncompressibleKeepsVolume(phantom, 1.0, 4.0);
}

}  // namespace
}  // namespace pfdm
