// The LV phantom's cases and the derived numbers that the interval
// calibration judges (lv_interval_calibration_test.cc) and whose sds'
// shrinking with the points is measured (lv_interval_shrink_test.cc).
#ifndef PFDM_TESTING_LV_INTERVAL_CASES_H_
#define PFDM_TESTING_LV_INTERVAL_CASES_H_

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/report/number_uncertainty.h"
#include "pfdm/report/rv_insertion.h"

namespace pfdm {
namespace interval_cases {

inline constexpr int kEs = 1;       // Frames: ED and ES.
inline constexpr int kSegment = 8;  // 0-based: segment 9, mid.
// 0-based: segment 8, mid anteroseptal, where the phantom's lesion is
// (lv_phantom.h): it contracts 15.9 % against its neighbours' 22.5.
inline constexpr int kLesionSegment = 7;

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

inline double MidSegmentTruth(const LvFrameTruth& truth) {
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
inline void CentreOnBias(FitAnalysis* a) {
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
inline std::vector<Judged> Numbers(FitAnalysis a, const LvPhantom& phantom,
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
  // Without the lesion the mid segments contract alike; with it, segment
  // 9 is the lesion's neighbour.
  const double segment_truth =
      phantom.options.deformation.lesion
          ? t1.segments[LvAhaSegmentIndex(kSegment)].radial_contraction_percent
          : MidSegmentTruth(t1);
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
       one_wall ? kNotMeasured : segment_truth},
      {"seg 9 rotation deg", "rotation_deg", seg.rotation_deg,
       seg_sd.rotation_deg, kNotMeasured},
  };
  // With the lesion, its segment alone, against its own truth (the mid
  // segments' mean is no segment's there).
  if (phantom.options.deformation.lesion) {
    const RegionMotion& lesion = a.region_motion[kEs][kLesionSegment];
    const RegionMotion& lesion_sd =
        with_sd ? a.sd.region_motion[kEs][kLesionSegment] : lesion;
    const LvSegmentTruth& lesion_truth =
        t1.segments[LvAhaSegmentIndex(kLesionSegment)];
    judged.push_back({"seg 8 (lesion) Ecc %", "ecc_percent", lesion.ecc_percent,
                      lesion_sd.ecc_percent, kNotMeasured});
    judged.push_back({"seg 8 (lesion) radial %", "radial_contraction_percent",
                      lesion.radial_contraction_percent,
                      lesion_sd.radial_contraction_percent,
                      lesion_truth.radial_contraction_percent});
    judged.push_back({"seg 8 (lesion) rotation deg", "rotation_deg",
                      lesion.rotation_deg, lesion_sd.rotation_deg,
                      lesion_truth.rotation_deg});
    judged.push_back({"seg 8 (lesion) thickening %", "thickening_percent",
                      lesion.thickening_percent, lesion_sd.thickening_percent,
                      lesion_truth.wall_thickening_percent});
  }
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

// With the lesion, the segments are anchored to the phantom's RV insertion
// (as a user who reads segments would give it), so that the fit's segment
// 8 is the phantom's.
inline FitAnalysis FitLv(const LvPhantom& phantom, bool uncertainty,
                         bool transmural) {
  FitOptions fit_options;
  fit_options.uncertainty = uncertainty;
  fit_options.local.transmural = transmural;
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(9), fit_options);
  RegionLayout layout;
  if (phantom.options.deformation.lesion) {
    RvInsertion insertion;
    insertion.source = "phantom";
    insertion.anterior = {phantom.rv_anterior};
    insertion.inferior = {phantom.rv_inferior};
    layout = AnatomicalLayout(fit.ModelAt(0), insertion);
    EXPECT_TRUE(layout.anatomical) << layout.anchor;
  }
  return AnalyzeFit(fit, {}, layout);
}

// The points a frame of a case has: PFDM_CALIBRATION_POINTS, default 400.
inline int CalibrationPoints() {
  const char* text = std::getenv("PFDM_CALIBRATION_POINTS");
  return text != nullptr ? std::max(1, std::atoi(text)) : 400;
}

// The data a case draws: ED and ES of the LV phantom, 0.5 mm noise.
struct Case {
  LvTagLayer layer = LvTagLayer::kMidwall;
  LvSampling sampling = LvSampling::kTags;
  bool lesion = false;      // Segment 8 contracting at 40 % of normal.
  bool transmural = false;  // FitOptions::local.transmural.
};

inline LvPhantomOptions PhantomOptions(const Case& c, int seed) {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = CalibrationPoints();
  options.tags = c.layer;
  options.sampling = c.sampling;
  // biv-me's views: short-axis slices and 3 long-axis planes.
  if (c.sampling == LvSampling::kSaxSlices) options.num_long_axis_planes = 3;
  options.deformation.lesion = c.lesion;
  options.seed = 1000 + seed;
  return options;
}

}  // namespace interval_cases
}  // namespace pfdm

#endif  // PFDM_TESTING_LV_INTERVAL_CASES_H_
