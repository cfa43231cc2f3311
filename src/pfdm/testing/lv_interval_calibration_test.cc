// Issue 30's calibration of the derived numbers' 95 % intervals on the
// independent LV phantom (phantom/lv_phantom.h), which the model did not
// make: over noise seeds, how often the interval (report/
// number_uncertainty.h) holds
//  - the fit's own number on the same tags without noise: what the
//    intervals promise, noise's spread (the coverage should be 90-98 %);
//  - the noise-free fit of ten times the points (DenseNumbers): the
//    model's answer with little of the sampling's own error, which the
//    intervals of the noise do not promise to hold;
//  - the phantom's truth, where it is defined as the fit's number is:
//    noise and the model's bias together; a number whose bias is large
//    against its sd is missed however calibrated the sd.
// Each interval is centred on the number minus the bias the noise puts
// into it (report/local_field_noise.h).  Six kinds of data: mid-wall
// tags, tags through the wall, both walls' contours, the endocardium's,
// the epicardium's or the mid-wall's contours alone; and four of the
// phantom with a hypokinetic segment, whose segments hang on the
// phantom's RV insertion (is the lesion told from its neighbours, and how
// near its truth?): mid-wall tags, tags through the wall with and without
// --local_transmural, both walls' contours.  pfdm claims a number's
// interval calibrated per kind (report/interval_calibration.h), and over
// 100 seeds each claimed row held the noise-free fit in 90-98 % of draws
// (docs/uncertainty_calibration.md).  PFDM_CALIBRATION_SEEDS (default 3,
// about 130 s of one core for the ten) sets the seeds,
// PFDM_CALIBRATION_POINTS (default 400) the points a frame;
// scripts/interval_calibration.sh runs 100 and writes
// docs/uncertainty_calibration.md from the tables printed here.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/report/number_uncertainty.h"
#include "pfdm/report/rv_insertion.h"
#include "pfdm/testing/interval_calibration_table.h"
#include "pfdm/testing/lv_interval_cases.h"

namespace pfdm {
namespace {

using interval_cases::Case;
using interval_cases::CentreOnBias;
using interval_cases::FitLv;
using interval_cases::Judged;
using interval_cases::kEs;
using interval_cases::kLesionSegment;
using interval_cases::Numbers;
using interval_cases::PhantomOptions;

// Whether a reader could tell the lesion from fit noise: its radial
// contraction's interval lies wholly below both its mid-ring neighbours'
// (segments 7 and 9), each centred on the number minus its noise bias.
bool LesionToldApart(FitAnalysis a) {
  if (a.noise_bias.computed) CentreOnBias(&a);
  const auto interval = [&a](int segment) {
    const double value =
        a.region_motion[kEs][segment].radial_contraction_percent;
    const double half = HalfWidth95(
        a.sd.region_motion[kEs][segment].radial_contraction_percent);
    return std::pair{value - half, value + half};
  };
  const double lesion_high = interval(kLesionSegment).second;
  return lesion_high < interval(kLesionSegment - 1).first &&
         lesion_high < interval(kLesionSegment + 1).first;
}

// The numbers of c's noise-free fit with ten times the points (seed 0):
// the model's answer with little of the sampling's own error.  Through the
// wall, 400 tags' depths from their ranks (QuantileDepths) are off by about
// a tenth of the wall, and the local field's wiggles fitted to that put
// +0.3 to +1.6 points into the noise-free fit's GCS (-18.5 against -19.35
// at 4,000 and 12,000 tags, 4 seeds).
std::vector<Judged> DenseNumbers(const Case& c) {
  LvPhantomOptions options = PhantomOptions(c, 0);
  options.num_tags *= 10;
  options.noise_mm = 0.0;
  const LvPhantom phantom = MakeLvPhantom(options);
  return Numbers(FitLv(phantom, false, c.transmural), phantom);
}

// Over CalibrationSeeds() noise draws of c: per number, in the table's order.
// With the lesion, *told_apart counts the draws where LesionToldApart.
std::vector<std::pair<std::string, Tally>> Calibrate(const Case& c,
                                                     int* told_apart) {
  std::vector<std::string> names;
  std::map<std::string, Tally> tally;
  const std::vector<Judged> dense = DenseNumbers(c);
  for (int s = 0; s < CalibrationSeeds(); ++s) {
    LvPhantomOptions options = PhantomOptions(c, s);
    const LvPhantom phantom = MakeLvPhantom(options);
    const FitAnalysis noisy = FitLv(phantom, true, c.transmural);
    EXPECT_TRUE(noisy.sd.computed);
    if (c.lesion) *told_apart += LesionToldApart(noisy);
    options.noise_mm = 0.0;
    const FitAnalysis clean =
        FitLv(MakeLvPhantom(options), false, c.transmural);
    const std::vector<Judged> got = Numbers(noisy, phantom);
    const std::vector<Judged> reference = Numbers(clean, phantom);
    const std::vector<Judged> uncentred = Numbers(noisy, phantom, false);
    for (size_t i = 0; i < got.size(); ++i) {
      // A surface has no wall: its thickening and mass read 0 +- 0.
      if (!Measured(got[i].value) || !(got[i].sd > 0.0)) continue;
      if (!Measured(reference[i].value)) continue;
      if (tally.count(got[i].name) == 0) names.push_back(got[i].name);
      Tally& t = tally[got[i].name];
      t.calibrated = got[i].calibrated;
      const double half = HalfWidth95(got[i].sd);
      const double error = got[i].value - reference[i].value;
      ++t.draws;
      t.inside_fit += std::abs(error) <= half;
      t.sd += got[i].sd;
      t.error_square += error * error;
      t.error += error;
      t.uncentred_error += uncentred[i].value - reference[i].value;
      if (i < dense.size() && Measured(dense[i].value)) {
        const double dense_error = got[i].value - dense[i].value;
        ++t.dense_draws;
        t.inside_dense += std::abs(dense_error) <= half;
        t.dense_error += dense_error;
      }
      if (Measured(got[i].truth)) {
        ++t.truths;
        t.inside_truth += std::abs(got[i].value - got[i].truth) <= half;
        t.bias += got[i].value - got[i].truth;
      }
    }
  }
  std::vector<std::pair<std::string, Tally>> rows;
  for (const std::string& name : names) rows.push_back({name, tally[name]});
  return rows;
}

// c's table, printed; the calibrated numbers' errors in sds have an rms
// about 1 (0.5 to 2 over 3 seeds and correlated numbers; the 100-seed
// tables in docs/).
std::vector<std::pair<std::string, Tally>> CalibrateKind(
    const Case& c, const std::string& title, int* told_apart = nullptr) {
  int unused = 0;
  const auto rows = Calibrate(c, told_apart ? told_apart : &unused);
  const double z_rms = PrintTable(title, rows);
  EXPECT_GT(z_rms, 0.5) << title;
  EXPECT_LT(z_rms, 2.0) << title;
  return rows;
}

TEST(LvIntervalCalibrationTest, MidwallTags) {
  const auto rows = CalibrateKind(Case(), "400 mid-wall tags");
  // The bias the local field's noise puts into GCS (0.7 points, 5 of its
  // delta-method sds, before local_field_noise.h) is taken out of the
  // interval's centre: the centre's mean error is now under the sd.
  const Tally& gcs = Row(rows, "GCS %");
  EXPECT_LT(std::abs(gcs.MeanError()), gcs.MeanSd());
}

// Tags through the wall, their depths held from frame 0 (the default
// since 2026-12-07).  Over 100 seeds GCS's interval held the noise-free fit
// in 0.95 of draws, its centre's mean error +0.20 against an sd of 0.30
// (ranked in every frame: 0.83, -0.32; the ranks put wiggles of their own
// into the fit).  The wall's thickening held it in 0.97, its mean error
// +0.41 (its centre, less the draws' noise bias, -0.15) against an sd of
// 4.0: until the pilot read frame 0's share of the noise as stretched by
// the wall's motion (tangential_stretch.h) it read 1.49 points under, the
// depths shrunk for too little noise (docs/gauge.md, "Why held depths read
// low under noise").  Three seeds cannot see that (their mean error's
// spread is 2.3 points): CI bounds it by its sd, 100 seeds by a quarter of
// it (the old bias was 0.38 sds; LvWallSegmentSeedsTest's mean bound is
// CI's guard).  Against the dense fit the wall's thickening is 1.7 over.
TEST(LvIntervalCalibrationTest, WallTags) {
  const auto rows =
      CalibrateKind(Case{LvTagLayer::kWall}, "400 tags through the wall");
  const Tally& gcs = Row(rows, "GCS %");
  EXPECT_LT(std::abs(gcs.MeanError()), gcs.MeanSd());
  const Tally& thickening = Row(rows, "wall thickening %");
  const double allowed_sds = CalibrationSeeds() >= 100 ? 0.25 : 1.0;
  EXPECT_LT(std::abs(thickening.MeanError()),
            allowed_sds * thickening.MeanSd());
}

// Mid-wall tags of the LV phantom whose segment 8 contracts at 40 % of
// normal (lv_phantom.h): a segment the global model cannot follow, which
// the local field has to find, and whose interval a reader would use to
// tell it from its neighbours.
// c's table with the lesion, and the draws in which it was told apart from
// its neighbours (LesionToldApart), printed; the lesion's radial
// contraction's and (a solid's) thickening's rows.
struct LesionRows {
  int told_apart = 0;
  Tally radial, thickening;  // Thickening: a solid's only.
};
LesionRows CalibrateLesion(const Case& c, const std::string& title) {
  LesionRows lesion;
  const auto rows = CalibrateKind(c, title, &lesion.told_apart);
  std::printf(
      "Lesion told apart (its radial contraction's interval wholly below "
      "both its mid-ring neighbours'): %d of %d draws\n\n",
      lesion.told_apart, CalibrationSeeds());
  lesion.radial = Row(rows, "seg 8 (lesion) radial %");
  if (c.layer == LvTagLayer::kWall) {
    lesion.thickening = Row(rows, "seg 8 (lesion) thickening %");
  }
  return lesion;
}

double MeanBias(const Tally& t) { return t.bias / t.truths; }

TEST(LvIntervalCalibrationTest, LesionMidwallTags) {
  const LesionRows lesion =
      CalibrateLesion(Case{LvTagLayer::kMidwall, LvSampling::kTags, true},
                      "400 mid-wall tags, segment 8 hypokinetic");
  EXPECT_GE(lesion.told_apart, 0.9 * CalibrationSeeds());
  // The local field's smoothness draws the lesion a little toward its
  // neighbours: over 100 seeds its radial contraction read 0.57 points
  // above the truth (its sd 0.56; -0.11 over the first 3), and its
  // interval held the truth in 74 % of draws, the noise-free fit in all.
  EXPECT_LT(std::abs(MeanBias(lesion.radial)), 1.5);
}

// Tags through the wall, the lesion through it too, the defaults: depths
// held from frame 0 (FitOptions::hold_tag_depths) and a field that moves
// every layer alike (FitOptions::local.transmural off).  The lesion's
// motion shows: over 100 seeds (2026-12-07) told apart from its neighbours
// in 95 of 100 draws, its radial contraction 0.87 points above the truth.
// Its thickening reads its ring's, 18.1 points above (16.9 % true): the
// field moves the layers alike.  The report says so (report/
// regional_limit.h).  Ranked anew in every frame (--tag_depths ranked, the
// default until 2026-12-07) the ranks took the sector's motion into the
// tags' depths and the lesion read as its ring: told apart in 2 of 100,
// 3.5 points above.
TEST(LvIntervalCalibrationTest, LesionWallTags) {
  const LesionRows lesion =
      CalibrateLesion(Case{LvTagLayer::kWall, LvSampling::kTags, true},
                      "400 tags through the wall, segment 8 hypokinetic");
  EXPECT_GE(lesion.told_apart, 0.9 * CalibrationSeeds());
  EXPECT_LT(std::abs(MeanBias(lesion.radial)), 1.5);
  EXPECT_GT(MeanBias(lesion.thickening), 10.0);
}

// The same with the field through the wall (--local_transmural on, depths
// held, the field bending between the walls): the lesion's radial
// contraction 0.97 points above the truth over 100 seeds, told apart in 92
// of 100 draws, its thickening 6.0 points above (4.6 until frame 0's noise
// was read as stretched, which shrinks the depths more; docs/
// uncertainty_calibration.md; ranked among neighbours: 2.05, 59 and 22).
TEST(LvIntervalCalibrationTest, LesionWallTagsTransmural) {
  const LesionRows lesion =
      CalibrateLesion(Case{LvTagLayer::kWall, LvSampling::kTags, true, true},
                      "400 tags through the wall, segment 8 hypokinetic, "
                      "--local_transmural on");
  EXPECT_LT(MeanBias(lesion.radial), 3.0);
}

// Both walls' contours (a solid), the lesion through the wall: each wall
// lies where its contours are, so the lesion's motion shows (its radial
// contraction's interval below both neighbours' in 87 of 100 draws), but
// the field moves both walls alike and its thickening reads its ring's:
// 22.8 points above the truth over 100 seeds (16.2 with
// --local_transmural on, measured once), while every interval held the
// noise-free fit (0.91-0.99).  The report says so (regional_limit.h).
TEST(LvIntervalCalibrationTest, LesionWallContours) {
  const LesionRows lesion =
      CalibrateLesion(Case{LvTagLayer::kWall, LvSampling::kSaxSlices, true},
                      "both walls' contours, segment 8 hypokinetic");
  EXPECT_GE(lesion.told_apart, 0.5 * CalibrationSeeds());
  EXPECT_GT(MeanBias(lesion.thickening), 10.0);
}

TEST(LvIntervalCalibrationTest, WallContours) {
  CalibrateKind(Case{LvTagLayer::kWall, LvSampling::kSaxSlices},
                "both walls' contours");
}

// The endocardium's contours alone (biv-me's lv-cavity): one surface,
// searched afresh at every frame.
TEST(LvIntervalCalibrationTest, EndocardialContours) {
  CalibrateKind(Case{LvTagLayer::kEndocardium, LvSampling::kSaxSlices},
                "endocardial contours");
}

// The mid-wall's contours alone: one surface, searched afresh at every
// frame.  Over 100 seeds every number they measure held the noise-free fit
// in 90-97 % of draws.
TEST(LvIntervalCalibrationTest, MidwallContours) {
  CalibrateKind(Case{LvTagLayer::kMidwall, LvSampling::kSaxSlices},
                "mid-wall contours");
}

// The epicardium's contours alone: one surface, searched afresh at every
// frame.  Over 100 seeds every number they measure held the noise-free fit
// in 0.91-0.97 of draws but EDV (0.88).
TEST(LvIntervalCalibrationTest, EpicardialContours) {
  CalibrateKind(Case{LvTagLayer::kEpicardium, LvSampling::kSaxSlices},
                "epicardial contours");
}

}  // namespace
}  // namespace pfdm
