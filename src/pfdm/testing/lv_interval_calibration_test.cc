// Issue 30's calibration of the derived numbers' 95 % intervals on the
// independent LV phantom (phantom/lv_phantom.h), which the model did not
// make: over noise seeds, how often the interval (report/
// number_uncertainty.h) holds
//  - the fit's own number on the same tags without noise: what the
//    intervals promise, noise's spread (the coverage should be 90-98 %);
//  - the phantom's truth, where it is defined as the fit's number is:
//    noise and the model's bias together; a number whose bias is large
//    against its sd is missed however calibrated the sd.
// The volume fraction, ESV, net twist, shortening and radial contraction
// are calibrated; EDV, GCS, GLS and the segment's numbers are not: noise
// biases them (GCS by +0.76 points, 5 sds) or spreads them beyond their
// sd (EDV 1.7 ml against 0.41: frame 0's scale a0 is held at the highest
// noisy point, which no covariance sees), docs/uncertainty.md.
// PFDM_CALIBRATION_SEEDS (default 3, about 10 s of one core) sets the
// seeds; scripts/interval_calibration.sh runs 100 and writes
// docs/uncertainty_calibration.md from the table printed here.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"

namespace pfdm {
namespace {

constexpr int kEs = 1;       // Frames: ED and ES.
constexpr int kSegment = 8;  // 0-based: segment 9, mid.

// calibrated: the noise-free fit is what its interval should hold; false
// for a number that noise itself biases (see the top of the test).
struct Judged {
  const char* name;
  double value, sd, truth;  // truth NaN: none defined like the fit's.
  bool calibrated = true;
};

double MidSegmentTruth(const LvFrameTruth& truth) {
  double sum = 0.0;
  int count = 0;
  for (const LvSegmentTruth& s : truth.segments) {
    if (s.name.rfind("mid", 0) != 0) continue;
    sum += s.radial_contraction_percent;
    ++count;
  }
  return count > 0 ? sum / count : kNotMeasured;
}

// The numbers judged, from an analysis with sds; truth from the phantom.
// (The noise-free fit's, without sds, reads its values only.)
std::vector<Judged> Numbers(const FitAnalysis& a, const LvPhantom& phantom) {
  const bool with_sd = a.sd.computed;
  const ClinicalSummary& es = a.clinical[kEs];
  const ClinicalSummary& sd = with_sd ? a.sd.clinical[kEs] : es;
  const RegionMotion& seg = a.region_motion[kEs][kSegment];
  const RegionMotion& seg_sd =
      with_sd ? a.sd.region_motion[kEs][kSegment] : seg;
  const GlobalStrain& strain_sd = with_sd ? a.sd.strain[kEs] : a.strain[kEs];
  const LvFrameTruth& t0 = phantom.truth[0];
  const LvFrameTruth& t1 = phantom.truth[kEs];
  const LvLayerRings& rings = t1.midwall;
  const double twist = LvRingValueAt(rings.rotation_deg, kBasalRingFraction) -
                       LvRingValueAt(rings.rotation_deg, kApicalRingFraction);
  return {
      {"volume fraction", a.ejection_fraction.ratio,
       a.sd.ejection_fraction.ratio,
       (t0.volume_ml - t1.volume_ml) / t0.volume_ml},
      {"EDV ml", a.ejection_fraction.edv_ml, a.sd.ejection_fraction.edv_ml,
       t0.volume_ml, false},
      {"ESV ml", a.ejection_fraction.esv_ml, a.sd.ejection_fraction.esv_ml,
       t1.volume_ml},
      {"net twist deg", es.net_twist_deg, sd.net_twist_deg, twist},
      {"shortening %", es.longitudinal_shortening_percent,
       sd.longitudinal_shortening_percent, t1.longitudinal_shortening_percent},
      {"radial contraction %", es.radial_contraction_percent,
       sd.radial_contraction_percent, kNotMeasured},
      {"GCS %", a.strain[kEs].gcs_percent, strain_sd.gcs_percent, kNotMeasured,
       false},
      {"GLS %", a.strain[kEs].gls_percent, strain_sd.gls_percent, kNotMeasured,
       false},
      {"seg 9 Ecc %", seg.ecc_percent, seg_sd.ecc_percent, kNotMeasured, false},
      {"seg 9 radial %", seg.radial_contraction_percent,
       seg_sd.radial_contraction_percent, MidSegmentTruth(t1), false},
      {"seg 9 rotation deg", seg.rotation_deg, seg_sd.rotation_deg,
       kNotMeasured, false},
  };
}

FitAnalysis FitLv(const LvPhantomOptions& options, bool uncertainty) {
  FitOptions fit_options;
  fit_options.uncertainty = uncertainty;
  return AnalyzeFit(FitSequence(MakeLvPhantom(options).points,
                                ModelConfig::Paper(9), fit_options));
}

struct Tally {
  int draws = 0, inside_fit = 0, inside_truth = 0, truths = 0;
  double sd = 0.0, error_square = 0.0, mean_error = 0.0, bias = 0.0;
};

int Seeds() {
  const char* text = std::getenv("PFDM_CALIBRATION_SEEDS");
  return text != nullptr ? std::max(1, std::atoi(text)) : 3;
}

TEST(LvIntervalCalibrationTest, IntervalsCoverNoiseOnTheLvPhantom) {
  const int seeds = Seeds();
  std::vector<Judged> names;
  std::vector<Tally> tally;
  for (int s = 0; s < seeds; ++s) {
    LvPhantomOptions options;
    options.num_frames = 2;
    options.num_tags = 400;
    options.seed = 1000 + s;
    const LvPhantom phantom = MakeLvPhantom(options);
    const FitAnalysis noisy = FitLv(options, true);
    ASSERT_TRUE(noisy.sd.computed);
    options.noise_mm = 0.0;
    const FitAnalysis clean = FitLv(options, false);
    const std::vector<Judged> got = Numbers(noisy, phantom);
    const std::vector<Judged> reference = Numbers(clean, phantom);
    if (tally.empty()) {
      names = got;
      tally.resize(got.size());
    }
    for (size_t i = 0; i < got.size(); ++i) {
      const double half = HalfWidth95(got[i].sd);
      const double error = got[i].value - reference[i].value;
      Tally& t = tally[i];
      ++t.draws;
      t.inside_fit += std::abs(error) <= half;
      t.sd += got[i].sd / seeds;
      t.error_square += error * error / seeds;
      t.mean_error += error / seeds;
      if (Measured(got[i].truth)) {
        ++t.truths;
        t.inside_truth += std::abs(got[i].value - got[i].truth) <= half;
        t.bias += (got[i].value - got[i].truth) / seeds;
      }
    }
  }
  std::printf(
      "| number | coverage of the noise-free fit | mean sd | "
      "rms error | mean error | coverage of the truth | mean bias |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n");
  int pooled = 0, total = 0, calibrated = 0;
  double z_square = 0.0;
  for (size_t i = 0; i < tally.size(); ++i) {
    const Tally& t = tally[i];
    pooled += t.inside_fit;
    total += t.draws;
    std::printf("| %s | %.3f | %.4g | %.4g | %.3g | ", names[i].name,
                t.inside_fit / double(t.draws), t.sd, std::sqrt(t.error_square),
                t.mean_error);
    if (t.truths > 0) {
      std::printf("%.3f | %.4g |\n", t.inside_truth / double(t.truths), t.bias);
    } else {
      std::printf("- | - |\n");
    }
    if (names[i].calibrated) {
      z_square += t.error_square / (t.sd * t.sd);
      ++calibrated;
    }
  }
  // The calibrated numbers' errors in sds: their rms about 1 (0.5 to 2
  // over 3 seeds and 5 correlated numbers; the 24-seed table in docs/).
  const double z_rms = std::sqrt(z_square / calibrated);
  std::printf("rms error / sd of the calibrated numbers: %.3f\n", z_rms);
  EXPECT_GT(z_rms, 0.5);
  EXPECT_LT(z_rms, 2.0);
  std::printf("pooled coverage of the noise-free fit: %.3f over %d seeds\n",
              pooled / static_cast<double>(total), seeds);
  // The bias noise puts into GCS (docs/uncertainty.md): 0.76 points against
  // an sd of 0.14 over 12 seeds, so the interval never holds the noise-free
  // fit's.  When this fails the bias has gone, and the docs must say so.
  const Tally& gcs = tally[6];
  EXPECT_GT(std::abs(gcs.mean_error), 2.0 * gcs.sd);
}

}  // namespace
}  // namespace pfdm
