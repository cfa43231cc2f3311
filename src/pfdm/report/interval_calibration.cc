#include "pfdm/report/interval_calibration.h"

#include <algorithm>

namespace pfdm {

IntervalData IntervalDataOf(const SequenceFit& fit) {
  // Tags and contours in one fit: no kind's calibration is theirs.
  const auto mixed = [](const FrameFit& f) { return f.mixed; };
  if (std::any_of(fit.frames.begin(), fit.frames.end(), mixed)) {
    return IntervalData::kOther;
  }
  const auto tracked = [](const FrameFit& f) { return f.tracked; };
  if (std::all_of(fit.frames.begin(), fit.frames.end(), tracked)) {
    return fit.config.Solid() ? IntervalData::kWallTags
                              : IntervalData::kMidwallTags;
  }
  if (std::none_of(fit.frames.begin(), fit.frames.end(), tracked)) {
    if (fit.config.Solid()) return IntervalData::kContours;
    switch (fit.surface) {
      case WallLayer::kEndocardium:  // biv-me's lv-cavity.
        return IntervalData::kEndoContours;
      case WallLayer::kEpicardium:
        return IntervalData::kEpiContours;
      case WallLayer::kAnywhere:
        return IntervalData::kMidwallContours;
    }
  }
  return IntervalData::kOther;
}

std::string IntervalDataName(IntervalData data) {
  switch (data) {
    case IntervalData::kMidwallTags:
      return "midwall tags";
    case IntervalData::kWallTags:
      return "wall tags";
    case IntervalData::kContours:
      return "wall contours";
    case IntervalData::kEndoContours:
      return "endocardial contours";
    case IntervalData::kEpiContours:
      return "epicardial contours";
    case IntervalData::kMidwallContours:
      return "midwall contours";
    case IntervalData::kOther:
      break;
  }
  return "other";
}

namespace {

const std::vector<std::string>& MidwallTagsKeys() {
  // GCS's interval (and its peak's) held the noise-free fit in 0.99 of
  // draws on 2026-12-05: too wide for issue 30's 90-98 %.  Over 300 draws
  // (2026-12-07) it held it in 0.983 but in 0.853 with the hypokinetic
  // segment (its sd 0.74 of its rms error there): not claimed.  ESV, 0.90
  // over 100 draws, held it in 0.947 and 0.953 over 300: claimed.
  static const std::vector<std::string> keys = {
      "ratio",
      "edv_ml",
      "esv_ml",
      "net_twist_deg",
      "torsion_deg_per_cm",
      "longitudinal_shortening_percent",
      "radial_contraction_percent",
      "gls_percent",
      "peak_gls_percent",
      "ecc_percent",
      "peak_ecc_percent",
      "ell_percent",
      "rotation_deg"};
  return keys;
}

const std::vector<std::string>& WallTagsKeys() {
  // Tags through the wall at held depths (the default since 2026-12-07),
  // 100 draws with and without the hypokinetic segment: shortening 0.98
  // and 0.98 (its sd 1.26 times its error), the segments' thickening 0.975
  // and 0.971.  Since the tracked frame's rows along the normals carry the
  // held depths' noise (directional_noise.h, 2026-12-07) the wall's
  // thickening 0.94 and 0.95 (0.90 and 0.89 before: its sd 3.41 against
  // an rms error of 3.84) and GCS 0.95 and 0.95 (0.92 and 0.90) are
  // claimed; the net twist 0.99, torsion 0.98-0.99 and the frames' radial
  // contraction 0.99 (too wide; the segments' 0.96) are not.  Since the
  // held depths' noise is read as stretched by the wall's motion
  // (tangential_stretch.h) the wall's thickening holds in 0.97 and 0.96,
  // its bias gone (docs/gauge.md), the segments' 0.972 and 0.973.  Over
  // 300 draws each (2026-12-07; rounded to the whole percent, as 100
  // draws give it) the net twist and torsion held in 0.973-0.977 and are
  // claimed; the volume fraction in 0.987 without the lesion (its sd 1.20
  // times its rms error; 0.973 with it) and the frames' radial
  // contraction in 0.987 and 0.987 (1.22 and 1.25): too wide, not.  Since
  // the tracked frame follows ED's errors (tracked_response.h, 2026-12-08;
  // 300 draws) radial contraction holds in 0.977 and 0.977 (claimed), ESV,
  // now taking ED's errors through the response, in 0.990 and 0.993 (its
  // sd 1.33 and 1.27 times its error: no longer claimed), the volume
  // fraction in 0.987 and 0.973 (not).  Since ED's noise through the held
  // depths is counted once (tracked_response.h, 2026-12-08; 300 draws) ESV
  // holds in 0.967 and 0.967 (sd 1.12 and 1.08 times its error), the
  // volume fraction in 0.970 and 0.967: both claimed.
  static const std::vector<std::string> keys = {
      "ratio",
      "edv_ml",
      "esv_ml",
      "radial_contraction_percent",
      "lv_mass_g",
      "net_twist_deg",
      "torsion_deg_per_cm",
      "longitudinal_shortening_percent",
      "gcs_percent",
      "gls_percent",
      "peak_gcs_percent",
      "peak_gls_percent",
      "wall_thickening_percent",
      "ecc_percent",
      "peak_ecc_percent",
      "ell_percent",
      "rotation_deg",
      "thickening_percent",
  };
  return keys;
}

const std::vector<std::string>& ContoursKeys() {
  // EDV's, 0.89 while frame 0's length took the top's error alone, is 0.91
  // with the apex's too (FrameCovariance::apex_length_variance).  The
  // segments' Ell held it in 0.981 of draws (too wide) while untracked
  // frames' length was held at frame 0's; left to the data, 0.952.
  static const std::vector<std::string> keys = {
      "ratio",
      "edv_ml",
      "esv_ml",
      "lv_mass_g",
      "longitudinal_shortening_percent",
      "radial_contraction_percent",
      "gcs_percent",
      "gls_percent",
      "peak_gcs_percent",
      "peak_gls_percent",
      "wall_thickening_percent",
      "ecc_percent",
      "peak_ecc_percent",
      "ell_percent",
      "thickening_percent"};
  return keys;
}

const std::vector<std::string>& OneSurfaceContoursKeys() {
  // One surface's contours (no wall to thicken or weigh, no turn seen)
  // measure these; each kind claims them but those whose intervals missed
  // 90-98 % over 100 draws on 2026-12-06 (untracked frames' length left to
  // the data, the covered radii's pull eased).
  static const std::vector<std::string> keys = {
      "ratio",
      "edv_ml",
      "esv_ml",
      "longitudinal_shortening_percent",
      "radial_contraction_percent",
      "gcs_percent",
      "gls_percent",
      "peak_gcs_percent",
      "peak_gls_percent",
      "ecc_percent",
      "peak_ecc_percent",
      "ell_percent"};
  return keys;
}

}  // namespace

const std::vector<std::string>& CalibratedIntervalKeys(IntervalData data) {
  static const std::vector<std::string> none;
  switch (data) {
    case IntervalData::kMidwallTags:
      return MidwallTagsKeys();
    case IntervalData::kWallTags:
      return WallTagsKeys();
    case IntervalData::kContours:
      return ContoursKeys();
    // Each one surface's kind claims all its keys since the length noise's
    // derivative is taken by the top's rise (model/raised_top.h), not a
    // uniform stretch: over 100 draws on 2026-12-06 the mid-wall's ESV and
    // volume fraction held the noise-free fit in 0.94 and 0.91 of draws
    // (0.87 and 0.89 with the stretch), the epicardium's EDV, ESV and
    // volume fraction in 0.95, 0.94 and 0.92 (0.88, 0.88, 0.89).  The
    // endocardium's GCS 0.95 (0.99, too wide, while the covered radii were
    // pulled toward frame 0's as hard as the rest).
    case IntervalData::kEndoContours:
    case IntervalData::kEpiContours:
    case IntervalData::kMidwallContours:
      return OneSurfaceContoursKeys();
    case IntervalData::kOther:
      break;
  }
  return none;
}

Calibration KeyCalibration(IntervalData data, const std::string& key) {
  const std::vector<std::string>& keys = CalibratedIntervalKeys(data);
  return std::find(keys.begin(), keys.end(), key) != keys.end()
             ? Calibration::kCalibrated
             : Calibration::kNotCalibrated;
}

std::string CalibrationNote(IntervalData data) {
  const std::vector<std::string>& keys = CalibratedIntervalKeys(data);
  if (keys.empty()) {
    return "No interval is calibrated on data of this kind (tags and "
           "contours mixed, or tags that some frames lose): read them as "
           "lower bounds.";
  }
  std::string names;
  for (const std::string& key : keys) {
    names += (names.empty() ? "" : ", ") + key;
  }
  return "Fitted: " + IntervalDataName(data) +
         ". On 100 noise draws (300 for tags) of the independent LV phantom "
         "with data of "
         "this kind the intervals of " +
         names +
         " (the frames' and the segments' numbers of those names) held the "
         "noise-free fit's number in 90-98 % of draws; every other "
         "interval held it in fewer (too narrow) or in more (too wide) "
         "(docs/uncertainty_calibration.md).";
}

}  // namespace pfdm
