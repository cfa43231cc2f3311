#include "pfdm/io/intervals_json.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "pfdm/report/global_strain.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/report/interval_text.h"

namespace pfdm {

const char* const kUncertaintyDefinition =
    "With --uncertainty on, each number's 95 % interval is "
    "\"<key>_ci95\": [low, high] beside it (a list of intervals beside a "
    "per-frame list; null where the number is null): value -+ 1.96 sd, sd "
    "by the delta method, sqrt(g' C g), C the covariance of the frame's "
    "free parameters (pose, globals, knots) at its global solution and g "
    "the number's gradient by central differences.  A number of frame t "
    "against end-diastole adds the two frames' variances (their fits taken "
    "as independent); the ejection fraction adds the two volumes'.  The "
    "covariance is conditional on the material points (contours' closest "
    "points and the previous frame's model taken as known), and the "
    "interval covers noise, not a bias of the model: docs/uncertainty.md.";

namespace {

using json = nlohmann::ordered_json;

// The interval's json for `value` and `sd`: null where either is NaN.
json Interval(double value, double sd) {
  if (!Measured(value) || !Measured(sd)) return json();
  const double half = HalfWidth95(sd);
  return json::array({value - half, value + half});
}

// sd of the number under `key` (NaN: none); for a per-frame list, that of
// its element `index` (-1 for a lone number).
using SdOf = std::function<double(const std::string& key, int index)>;

// object with "<key>_ci95" after every key whose number (or list of
// numbers) has an sd.
json WithIntervals(const json& object, const SdOf& sd_of) {
  json out = json::object();
  for (const auto& [key, value] : object.items()) {
    out[key] = value;
    if (value.is_number() && Measured(sd_of(key, -1))) {
      out[key + "_ci95"] = Interval(value.get<double>(), sd_of(key, -1));
    } else if (value.is_array() && !value.empty() && Measured(sd_of(key, 0))) {
      json intervals = json::array();
      for (size_t i = 0; i < value.size(); ++i) {
        intervals.push_back(value[i].is_number()
                                ? Interval(value[i].get<double>(),
                                           sd_of(key, static_cast<int>(i)))
                                : json());
      }
      out[key + "_ci95"] = intervals;
    }
  }
  return out;
}

// The sd of the field named `key` (its Fields' index in `names`), NaN if
// none.
template <typename Struct>
double FieldSd(const std::vector<std::string>& names, const std::string& key,
               Struct sd, std::vector<double*> (*fields)(Struct*)) {
  const auto it = std::find(names.begin(), names.end(), key);
  return it == names.end() ? kNotMeasured : *fields(&sd)[it - names.begin()];
}

double ClinicalKeySd(const NumberSd& sd, size_t t, const std::string& key,
                     const std::string& volume_key) {
  if (key == volume_key) return sd.clinical[t].volume_ml;
  const double value =
      FieldSd(ClinicalFieldNames(), key, sd.clinical[t], &ClinicalFields);
  return Measured(value)
             ? value
             : FieldSd(StrainFieldNames(), key, sd.strain[t], &StrainFields);
}

void AddFrames(const FitAnalysis& analysis, json* frames) {
  const NumberSd& sd = analysis.sd;
  const std::string volume_key = analysis.volume_surface + "_volume_ml";
  for (size_t t = 0; t < frames->size() && t < sd.clinical.size(); ++t) {
    const SdOf sd_of = [&](const std::string& key, int) {
      return ClinicalKeySd(sd, t, key, volume_key);
    };
    json& frame = (*frames)[t];
    frame["clinical"] = WithIntervals(frame["clinical"], sd_of);
    frame = WithIntervals(frame, sd_of);
  }
}

void AddEjection(const NumberSd& sd, json* section) {
  const EjectionFraction& ef = sd.ejection_fraction;
  *section = WithIntervals(*section, [&](const std::string& key, int) {
    if (key == "ratio") return ef.ratio;
    if (key == "edv_ml") return ef.edv_ml;
    return key == "esv_ml" ? ef.esv_ml : kNotMeasured;
  });
}

void AddRegions(const FitAnalysis& analysis, json* regions) {
  const NumberSd& sd = analysis.sd;
  for (size_t r = 0; r < regions->size(); ++r) {
    const int peak = PeakEccFrame(analysis, r);
    (*regions)[r] =
        WithIntervals((*regions)[r], [&](const std::string& key, int index) {
          if (key == "peak_ecc_percent") {
            return sd.region_motion[peak][r].ecc_percent;
          }
          const size_t t = index < 0 ? 0 : static_cast<size_t>(index);
          return FieldSd(RegionFieldNames(), key, sd.region_motion[t][r],
                         &RegionFields);
        });
  }
}

void AddStrain(const FitAnalysis& analysis, json* strain) {
  const NumberSd& sd = analysis.sd;
  const int gcs = PeakGcs(analysis.strain).frame;
  const int gls = PeakGls(analysis.strain).frame;
  *strain = WithIntervals(*strain, [&](const std::string& key, int) {
    if (key == "peak_gcs_percent") return sd.strain[gcs].gcs_percent;
    return key == "peak_gls_percent" ? sd.strain[gls].gls_percent
                                     : kNotMeasured;
  });
  static const char* const kLevels[] = {"basal", "mid", "apical"};
  for (int level = 0; level < 3; ++level) {
    json& entry = (*strain)["levels"][kLevels[level]];
    entry = WithIntervals(entry, [&](const std::string& key, int index) {
      const GlobalStrain& s = sd.strain[std::max(index, 0)];
      if (key == "ecc_percent") return s.level_ecc_percent[level];
      return key == "ell_percent" ? s.level_ell_percent[level] : kNotMeasured;
    });
  }
}

}  // namespace

void AddIntervals(const FitAnalysis& analysis, json* document) {
  if (!analysis.sd.computed) return;
  (*document)["uncertainty_definition"] = kUncertaintyDefinition;
  (*document)["uncertainty_calibrated"] = {{"keys", CalibratedIntervalKeys()},
                                           {"note", kCalibrationNote}};
  for (const char* key : {"ejection_fraction", "midwall_volume_fraction",
                          "epicardial_volume_fraction"}) {
    if (document->contains(key)) AddEjection(analysis.sd, &(*document)[key]);
  }
  AddRegions(analysis, &(*document)["regions"]);
  AddStrain(analysis, &(*document)["strain"]);
  AddFrames(analysis, &(*document)["frames"]);
}

}  // namespace pfdm
