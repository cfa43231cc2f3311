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
// tags, tags through the wall, both walls' contours, and the endocardium's,
// the epicardium's or the mid-wall's contours alone; pfdm claims a number's
// interval calibrated per kind (report/interval_calibration.h), and over
// 100 seeds each claimed row held the noise-free fit in 90-98 % of draws
// (docs/uncertainty_calibration.md).  PFDM_CALIBRATION_SEEDS (default 3,
// about 80 s of one core for the six) sets the seeds;
// scripts/interval_calibration.sh runs 100 and writes
// docs/uncertainty_calibration.md from the tables printed here.
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

namespace pfdm {
namespace {

constexpr int kEs = 1;       // Frames: ED and ES.
constexpr int kSegment = 8;  // 0-based: segment 9, mid.

// key: fit.json's name of the number, which says whether pfdm claims its
// interval calibrated on the data fitted (interval_calibration.h); value
// is the interval's centre: the number minus its noise bias
// (report/local_field_noise.h).
struct Judged {
  const char* name;
  const char* key;
  double value, sd, truth;  // truth NaN: none defined like the fit's.
  bool calibrated = false;  // Set from key.
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

// a's numbers at ED (the mass) and ES moved to their intervals' centres: minus
// the bias.
void CentreOnBias(FitAnalysis* a) {
  const NumberSd& b = a->noise_bias;
  auto shift = [](std::vector<double*> values, std::vector<double*> biases) {
    for (size_t i = 0; i < values.size(); ++i) {
      if (std::isfinite(*biases[i])) *values[i] -= *biases[i];
    }
  };
  NumberSd bias = b;
  shift(ClinicalFields(&a->clinical[0]), ClinicalFields(&bias.clinical[0]));
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
std::vector<Judged> Numbers(FitAnalysis a, const LvPhantom& phantom,
                            bool centre = true) {
  const bool with_sd = a.sd.computed;
  if (centre && a.noise_bias.computed) CentreOnBias(&a);
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
  // A solid's volumes are the cavity's, a surface's the mid-wall's (the
  // endocardium's the cavity's, the epicardium's its own).  The phantom's
  // shortening and segments are the mid-wall's: no truth for one wall's.
  const bool cavity = a.volume_surface == "cavity";
  const bool epi = a.volume_surface == "epicardial";
  const bool one_wall = epi || a.interval_data == IntervalData::kEndoContours;
  const auto volume = [&](const LvFrameTruth& t) {
    return cavity ? t.endo_volume_ml : epi ? t.epi_volume_ml : t.volume_ml;
  };
  const double edv = volume(t0);
  const double esv = volume(t1);
  std::vector<Judged> judged = {
      {"volume fraction", "ratio", a.ejection_fraction.ratio,
       a.sd.ejection_fraction.ratio, (edv - esv) / edv},
      {"EDV ml", "edv_ml", a.ejection_fraction.edv_ml,
       a.sd.ejection_fraction.edv_ml, edv},
      {"ESV ml", "esv_ml", a.ejection_fraction.esv_ml,
       a.sd.ejection_fraction.esv_ml, esv},
      {"net twist deg", "net_twist_deg", es.net_twist_deg, sd.net_twist_deg,
       twist},
      {"shortening %", "longitudinal_shortening_percent",
       es.longitudinal_shortening_percent, sd.longitudinal_shortening_percent,
       one_wall ? kNotMeasured : t1.longitudinal_shortening_percent},
      {"radial contraction %", "radial_contraction_percent",
       es.radial_contraction_percent, sd.radial_contraction_percent,
       kNotMeasured},
      {"GCS %", "gcs_percent", a.strain[kEs].gcs_percent, strain_sd.gcs_percent,
       kNotMeasured},
      {"GLS %", "gls_percent", a.strain[kEs].gls_percent, strain_sd.gls_percent,
       kNotMeasured},
      {"torsion deg/cm", "torsion_deg_per_cm", es.torsion_deg_per_cm,
       sd.torsion_deg_per_cm, kNotMeasured},
      {"wall thickening %", "wall_thickening_percent",
       es.wall_thickening_percent, sd.wall_thickening_percent, kNotMeasured},
      {"LV mass g", "lv_mass_g", a.clinical[0].lv_mass_g,
       with_sd ? a.sd.clinical[0].lv_mass_g : a.clinical[0].lv_mass_g,
       kNotMeasured},
      {"seg 9 Ecc %", "ecc_percent", seg.ecc_percent, seg_sd.ecc_percent,
       kNotMeasured},
      {"seg 9 radial %", "radial_contraction_percent",
       seg.radial_contraction_percent, seg_sd.radial_contraction_percent,
       one_wall ? kNotMeasured : MidSegmentTruth(t1)},
      {"seg 9 rotation deg", "rotation_deg", seg.rotation_deg,
       seg_sd.rotation_deg, kNotMeasured},
  };
  // Every segment's, pooled in one row each.
  for (size_t r = 0; r < a.region_motion[kEs].size(); ++r) {
    const RegionMotion& m = a.region_motion[kEs][r];
    const RegionMotion& m_sd = with_sd ? a.sd.region_motion[kEs][r] : m;
    judged.push_back({"segments Ecc %", "ecc_percent", m.ecc_percent,
                      m_sd.ecc_percent, kNotMeasured});
    judged.push_back({"segments radial %", "radial_contraction_percent",
                      m.radial_contraction_percent,
                      m_sd.radial_contraction_percent, kNotMeasured});
    judged.push_back({"segments rotation deg", "rotation_deg", m.rotation_deg,
                      m_sd.rotation_deg, kNotMeasured});
    judged.push_back({"segments Ell %", "ell_percent", m.ell_percent,
                      m_sd.ell_percent, kNotMeasured});
    judged.push_back({"segments thickening %", "thickening_percent",
                      m.thickening_percent, m_sd.thickening_percent,
                      kNotMeasured});
  }
  for (Judged& j : judged) {
    j.calibrated =
        KeyCalibration(a.interval_data, j.key) == Calibration::kCalibrated;
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
  double uncentred_error = 0.0;  // Of the number itself, not minus its bias.
  int dense_draws = 0, inside_dense = 0;  // Where the dense fit measured it.
  double dense_error = 0.0;
  double MeanSd() const { return sd / draws; }
  double RmsError() const { return std::sqrt(error_square / draws); }
  double MeanError() const { return error / draws; }
  double MeanUncentredError() const { return uncentred_error / draws; }
  double MeanDenseError() const { return dense_error / dense_draws; }
  double DenseCoverage() const {
    return inside_dense / static_cast<double>(dense_draws);
  }
};

int Seeds() {
  const char* text = std::getenv("PFDM_CALIBRATION_SEEDS");
  return text != nullptr ? std::max(1, std::atoi(text)) : 3;
}

// The data a case draws: ED and ES of the LV phantom, 0.5 mm noise.
struct Case {
  LvTagLayer layer = LvTagLayer::kMidwall;
  LvSampling sampling = LvSampling::kTags;
};

LvPhantomOptions PhantomOptions(const Case& c, int seed) {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = 400;
  options.tags = c.layer;
  options.sampling = c.sampling;
  // biv-me's views: short-axis slices and 3 long-axis planes.
  if (c.sampling == LvSampling::kSaxSlices) options.num_long_axis_planes = 3;
  options.seed = 1000 + seed;
  return options;
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
  return Numbers(FitLv(options, false), MakeLvPhantom(options));
}

// Over Seeds() noise draws of c: per number, in the table's order.
std::vector<std::pair<std::string, Tally>> Calibrate(const Case& c) {
  std::vector<std::string> names;
  std::map<std::string, Tally> tally;
  const std::vector<Judged> dense = DenseNumbers(c);
  for (int s = 0; s < Seeds(); ++s) {
    LvPhantomOptions options = PhantomOptions(c, s);
    const LvPhantom phantom = MakeLvPhantom(options);
    const FitAnalysis noisy = FitLv(options, true);
    EXPECT_TRUE(noisy.sd.computed);
    options.noise_mm = 0.0;
    const FitAnalysis clean = FitLv(options, false);
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

// Over 100 seeds and more, a number whose interval pfdm claims calibrated
// (interval_calibration.h, where coverage read 0.90-0.98) holds the
// noise-free fit in 88-99 % of draws: the binomial's sd at 100 draws is
// 2.2 points, and a change of the code moves a row by a draw or two.
// Segment 9 alone is shown, not asserted (the claim is the pooled
// segments'; it read 0.87 for Ecc on mid-wall tags).
void ExpectCoverageClaimed(const std::string& name, const Tally& t) {
  if (Seeds() < 100 || name.rfind("seg 9", 0) == 0) return;
  const double coverage = t.inside_fit / static_cast<double>(t.draws);
  EXPECT_GE(coverage, 0.88) << name;
  EXPECT_LE(coverage, 0.99) << name;
}

// Prints the table (scripts/interval_calibration.sh copies it into docs/)
// and returns the rms of the calibrated numbers' errors in their sds.
double PrintTable(const std::string& title,
                  const std::vector<std::pair<std::string, Tally>>& rows) {
  std::printf("## %s\n\n", title.c_str());
  std::printf(
      "| number | claimed | coverage of the noise-free fit | mean sd | "
      "rms error | mean error | mean error without the bias | "
      "coverage of the dense fit | mean error against it | "
      "coverage of the truth | mean bias |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  int pooled = 0, total = 0, calibrated = 0;
  double z_square = 0.0;
  for (const auto& [name, t] : rows) {
    pooled += t.inside_fit;
    total += t.draws;
    std::printf("| %s | %s | %.3f | %.4g | %.4g | %.3g | %.3g | %.3f | %.3g | ",
                name.c_str(), t.calibrated ? "yes" : "",
                t.inside_fit / double(t.draws), t.MeanSd(), t.RmsError(),
                t.MeanError(), t.MeanUncentredError(), t.DenseCoverage(),
                t.MeanDenseError());
    if (t.truths > 0) {
      std::printf("%.3f | %.4g |\n", t.inside_truth / double(t.truths),
                  t.bias / t.truths);
    } else {
      std::printf("- | - |\n");
    }
    if (t.calibrated) {
      z_square += std::pow(t.RmsError() / t.MeanSd(), 2);
      ++calibrated;
      ExpectCoverageClaimed(name, t);
    }
  }
  std::printf("\npooled coverage of the noise-free fit: %.3f over %d seeds\n\n",
              pooled / static_cast<double>(total), Seeds());
  return std::sqrt(z_square / calibrated);
}

const Tally& Row(const std::vector<std::pair<std::string, Tally>>& rows,
                 const std::string& name) {
  for (const auto& row : rows) {
    if (row.first == name) return row.second;
  }
  static const Tally none;
  ADD_FAILURE() << "no row " << name;
  return none;
}

// c's table, printed; the calibrated numbers' errors in sds have an rms
// about 1 (0.5 to 2 over 3 seeds and correlated numbers; the 100-seed
// tables in docs/).
std::vector<std::pair<std::string, Tally>> CalibrateKind(
    const Case& c, const std::string& title) {
  const auto rows = Calibrate(c);
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

TEST(LvIntervalCalibrationTest, WallTags) {
  const auto rows =
      CalibrateKind(Case{LvTagLayer::kWall}, "400 tags through the wall");
  // The same 400 tags' noise-free fit is not GCS's yardstick through the
  // wall: the tags' ranked depths put wiggles of their own into it, which
  // the noise bias, scaled by the residual of both, takes out too.  The
  // interval's centre lies at the dense fit's GCS (mean error +0.06 over
  // 100 seeds, -0.68 against the noise-free fit; 3 seeds: -0.24, -0.78).
  const Tally& gcs = Row(rows, "GCS %");
  EXPECT_LT(std::abs(gcs.MeanDenseError()), 0.5 * std::abs(gcs.MeanError()));
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
