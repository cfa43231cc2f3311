// Issue 30's calibration of the derived numbers' 95 % intervals on the
// independent LV phantom (phantom/lv_phantom.h), which the model did not
// make: over noise seeds, how often the interval (report/
// number_uncertainty.h) holds
//  - the fit's own number on the same tags without noise: what the
//    intervals promise, noise's spread (the coverage should be 90-98 %);
//  - the phantom's truth, where it is defined as the fit's number is:
//    noise and the model's bias together; a number whose bias is large
//    against its sd is missed however calibrated the sd.
// Each interval is centred on the number minus the bias the local
// field's noise puts into it (report/local_field_noise.h).  Over 120
// seeds the volume fraction, net twist, shortening, radial contraction,
// GCS, GLS and the segments' radial contraction and rotation hold the
// noise-free fit in 90-98 % of draws; EDV does not (frame 0's length is
// set by the highest and lowest noisy points and held, which no
// covariance sees), ESV and the segments' Ecc come close
// (docs/uncertainty.md).
// PFDM_CALIBRATION_SEEDS (default 3, about 10 s of one core) sets the
// seeds; scripts/interval_calibration.sh runs 100 and writes
// docs/uncertainty_calibration.md from the table printed here.
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
#include "pfdm/report/number_uncertainty.h"

namespace pfdm {
namespace {

constexpr int kEs = 1;       // Frames: ED and ES.
constexpr int kSegment = 8;  // 0-based: segment 9, mid.

// calibrated: the noise-free fit is what its interval should hold; false
// for a number that noise itself biases (see the top of the test).
// value is the interval's centre: the number minus its noise bias
// (report/local_field_noise.h).
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

// a's numbers at ES moved to their intervals' centres: minus the bias.
void CentreOnBias(FitAnalysis* a) {
  const NumberSd& b = a->noise_bias;
  auto shift = [](std::vector<double*> values, std::vector<double*> biases) {
    for (size_t i = 0; i < values.size(); ++i) {
      if (std::isfinite(*biases[i])) *values[i] -= *biases[i];
    }
  };
  NumberSd bias = b;
  shift(ClinicalFields(&a->clinical[kEs]), ClinicalFields(&bias.clinical[kEs]));
  shift(StrainFields(&a->strain[kEs]), StrainFields(&bias.strain[kEs]));
  for (size_t r = 0; r < a->region_motion[kEs].size(); ++r) {
    shift(RegionFields(&a->region_motion[kEs][r]),
          RegionFields(&bias.region_motion[kEs][r]));
  }
  EjectionFraction& ef = a->ejection_fraction;
  const EjectionFraction& eb = bias.ejection_fraction;
  for (auto [value, shift_by] :
       {std::pair{&ef.ratio, eb.ratio}, std::pair{&ef.edv_ml, eb.edv_ml},
        std::pair{&ef.esv_ml, eb.esv_ml}}) {
    if (std::isfinite(shift_by)) *value -= shift_by;
  }
}

// The numbers judged, from an analysis with sds; truth from the phantom.
// (The noise-free fit's, without sds, reads its values only.)
std::vector<Judged> Numbers(FitAnalysis a, const LvPhantom& phantom) {
  const bool with_sd = a.sd.computed;
  if (a.noise_bias.computed) CentreOnBias(&a);
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
  std::vector<Judged> judged = {
      {"volume fraction", a.ejection_fraction.ratio,
       a.sd.ejection_fraction.ratio,
       (t0.volume_ml - t1.volume_ml) / t0.volume_ml},
      {"EDV ml", a.ejection_fraction.edv_ml, a.sd.ejection_fraction.edv_ml,
       t0.volume_ml, false},
      {"ESV ml", a.ejection_fraction.esv_ml, a.sd.ejection_fraction.esv_ml,
       t1.volume_ml, false},
      {"net twist deg", es.net_twist_deg, sd.net_twist_deg, twist},
      {"shortening %", es.longitudinal_shortening_percent,
       sd.longitudinal_shortening_percent, t1.longitudinal_shortening_percent},
      {"radial contraction %", es.radial_contraction_percent,
       sd.radial_contraction_percent, kNotMeasured},
      {"GCS %", a.strain[kEs].gcs_percent, strain_sd.gcs_percent, kNotMeasured},
      {"GLS %", a.strain[kEs].gls_percent, strain_sd.gls_percent, kNotMeasured},
      {"seg 9 Ecc %", seg.ecc_percent, seg_sd.ecc_percent, kNotMeasured, false},
      {"seg 9 radial %", seg.radial_contraction_percent,
       seg_sd.radial_contraction_percent, MidSegmentTruth(t1)},
      {"seg 9 rotation deg", seg.rotation_deg, seg_sd.rotation_deg,
       kNotMeasured},
  };
  // Every segment's, pooled in one row each.
  for (size_t r = 0; r < a.region_motion[kEs].size(); ++r) {
    const RegionMotion& m = a.region_motion[kEs][r];
    const RegionMotion& m_sd = with_sd ? a.sd.region_motion[kEs][r] : m;
    judged.push_back({"segments Ecc %", m.ecc_percent, m_sd.ecc_percent,
                      kNotMeasured, false});
    judged.push_back({"segments radial %", m.radial_contraction_percent,
                      m_sd.radial_contraction_percent, kNotMeasured});
    judged.push_back({"segments rotation deg", m.rotation_deg,
                      m_sd.rotation_deg, kNotMeasured});
  }
  return judged;
}

FitAnalysis FitLv(const LvPhantomOptions& options, bool uncertainty) {
  FitOptions fit_options;
  fit_options.uncertainty = uncertainty;
  return AnalyzeFit(FitSequence(MakeLvPhantom(options).points,
                                ModelConfig::Paper(9), fit_options));
}

// Sums over the draws (and, for the pooled rows, the segments).
struct Tally {
  bool calibrated = true;
  int draws = 0, inside_fit = 0, inside_truth = 0, truths = 0;
  double sd = 0.0, error_square = 0.0, error = 0.0, bias = 0.0;
  double MeanSd() const { return sd / draws; }
  double RmsError() const { return std::sqrt(error_square / draws); }
  double MeanError() const { return error / draws; }
};

int Seeds() {
  const char* text = std::getenv("PFDM_CALIBRATION_SEEDS");
  return text != nullptr ? std::max(1, std::atoi(text)) : 3;
}

TEST(LvIntervalCalibrationTest, IntervalsCoverNoiseOnTheLvPhantom) {
  const int seeds = Seeds();
  std::vector<std::string> names;  // In the table's order.
  std::map<std::string, Tally> tally;
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
    for (size_t i = 0; i < got.size(); ++i) {
      if (!Measured(got[i].value) || !Measured(got[i].sd)) continue;
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
      if (Measured(got[i].truth)) {
        ++t.truths;
        t.inside_truth += std::abs(got[i].value - got[i].truth) <= half;
        t.bias += got[i].value - got[i].truth;
      }
    }
  }
  std::printf(
      "| number | coverage of the noise-free fit | mean sd | "
      "rms error | mean error | coverage of the truth | mean bias |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n");
  int pooled = 0, total = 0, calibrated = 0;
  double z_square = 0.0;
  for (const std::string& name : names) {
    const Tally& t = tally[name];
    pooled += t.inside_fit;
    total += t.draws;
    std::printf("| %s | %.3f | %.4g | %.4g | %.3g | ", name.c_str(),
                t.inside_fit / double(t.draws), t.MeanSd(), t.RmsError(),
                t.MeanError());
    if (t.truths > 0) {
      std::printf("%.3f | %.4g |\n", t.inside_truth / double(t.truths),
                  t.bias / t.truths);
    } else {
      std::printf("- | - |\n");
    }
    if (t.calibrated) {
      z_square += std::pow(t.RmsError() / t.MeanSd(), 2);
      ++calibrated;
    }
  }
  // The calibrated numbers' errors in sds: their rms about 1 (0.5 to 2
  // over 3 seeds and correlated numbers; the 120-seed table in docs/).
  const double z_rms = std::sqrt(z_square / calibrated);
  std::printf("rms error / sd of the calibrated numbers: %.3f\n", z_rms);
  EXPECT_GT(z_rms, 0.5);
  EXPECT_LT(z_rms, 2.0);
  std::printf("pooled coverage of the noise-free fit: %.3f over %d seeds\n",
              pooled / static_cast<double>(total), seeds);
  // The bias the local field's noise puts into GCS (0.7 points, 5 of its
  // delta-method sds, before local_field_noise.h) is taken out of the
  // interval's centre: the centre's mean error is now under the sd.
  const Tally& gcs = tally["GCS %"];
  EXPECT_LT(std::abs(gcs.MeanError()), gcs.MeanSd());
}

}  // namespace
}  // namespace pfdm
