#include "pfdm/io/intervals_json.h"

#include <algorithm>
#include <array>
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
    "per-frame list; null where the number is null): value - bias -+ 1.96 "
    "sd.  The sd: by the delta method, sqrt(g' C g), C the covariance of "
    "the frame's free parameters (pose, globals, knots) at its global "
    "solution and g the number's gradient by central differences, plus "
    "the spread the local field's noise gives it (draws of the field the "
    "frame's noise alone fits, added to the fitted field); the bias: "
    "those draws' mean shift of the number, the bias the noise puts into "
    "a number not linear in the field (strain).  A number of frame t "
    "against end-diastole adds the two frames' variances (their fits taken "
    "as independent); the ejection fraction adds the two volumes'.  The "
    "covariance is conditional on the material points (contours' closest "
    "points and the previous frame's model taken as known), and the "
    "interval covers noise, not a bias of the model: docs/uncertainty.md.";

namespace {

using json = nlohmann::ordered_json;

// The interval's json for `value`, its `sd` and `bias`: null where the
// value or sd is NaN; centred on value - bias (a NaN bias: none).
json Interval(double value, double sd, double bias) {
  if (!Measured(value) || !Measured(sd)) return json();
  const std::array<double, 2> interval = Interval95(value, sd, bias);
  return json::array({interval[0], interval[1]});
}

// In `numbers` (the sds, or the biases), the entry of the number under
// `key` (NaN: none); for a per-frame list, that of its element `index` (-1
// for a lone number).
using EntryOf = std::function<double(const NumberSd& numbers,
                                     const std::string& key, int index)>;

// object with "<key>_ci95" after every key whose number (or list of
// numbers) has an sd.
json WithIntervals(const json& object, const FitAnalysis& analysis,
                   const EntryOf& entry_of) {
  const auto sd_of = [&](const std::string& key, int index) {
    return entry_of(analysis.sd, key, index);
  };
  const auto bias_of = [&](const std::string& key, int index) {
    return analysis.noise_bias.computed
               ? entry_of(analysis.noise_bias, key, index)
               : kNotMeasured;
  };
  json out = json::object();
  for (const auto& [key, value] : object.items()) {
    out[key] = value;
    if (value.is_number() && Measured(sd_of(key, -1))) {
      out[key + "_ci95"] =
          Interval(value.get<double>(), sd_of(key, -1), bias_of(key, -1));
    } else if (value.is_array() && !value.empty() && Measured(sd_of(key, 0))) {
      json intervals = json::array();
      for (size_t i = 0; i < value.size(); ++i) {
        const int index = static_cast<int>(i);
        intervals.push_back(value[i].is_number()
                                ? Interval(value[i].get<double>(),
                                           sd_of(key, index),
                                           bias_of(key, index))
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
  const std::string volume_key = analysis.volume_surface + "_volume_ml";
  for (size_t t = 0; t < frames->size() && t < analysis.sd.clinical.size();
       ++t) {
    const EntryOf entry_of = [&](const NumberSd& numbers,
                                 const std::string& key, int) {
      return ClinicalKeySd(numbers, t, key, volume_key);
    };
    json& frame = (*frames)[t];
    frame["clinical"] = WithIntervals(frame["clinical"], analysis, entry_of);
    frame = WithIntervals(frame, analysis, entry_of);
  }
}

void AddEjection(const FitAnalysis& analysis, json* section) {
  *section =
      WithIntervals(*section, analysis,
                    [&](const NumberSd& numbers, const std::string& key, int) {
                      const EjectionFraction& ef = numbers.ejection_fraction;
                      if (key == "ratio") return ef.ratio;
                      if (key == "edv_ml") return ef.edv_ml;
                      return key == "esv_ml" ? ef.esv_ml : kNotMeasured;
                    });
}

void AddRegions(const FitAnalysis& analysis, json* regions) {
  for (size_t r = 0; r < regions->size(); ++r) {
    const int peak = PeakEccFrame(analysis, r);
    (*regions)[r] = WithIntervals(
        (*regions)[r], analysis,
        [&](const NumberSd& numbers, const std::string& key, int index) {
          if (key == "peak_ecc_percent") {
            return numbers.region_motion[peak][r].ecc_percent;
          }
          const size_t t = index < 0 ? 0 : static_cast<size_t>(index);
          return FieldSd(RegionFieldNames(), key, numbers.region_motion[t][r],
                         &RegionFields);
        });
  }
}

void AddStrain(const FitAnalysis& analysis, json* strain) {
  const int gcs = PeakGcs(analysis.strain).frame;
  const int gls = PeakGls(analysis.strain).frame;
  *strain = WithIntervals(
      *strain, analysis,
      [&](const NumberSd& numbers, const std::string& key, int) {
        if (key == "peak_gcs_percent") return numbers.strain[gcs].gcs_percent;
        return key == "peak_gls_percent" ? numbers.strain[gls].gls_percent
                                         : kNotMeasured;
      });
  static const char* const kLevels[] = {"basal", "mid", "apical"};
  for (int level = 0; level < 3; ++level) {
    json& entry = (*strain)["levels"][kLevels[level]];
    entry = WithIntervals(
        entry, analysis,
        [&](const NumberSd& numbers, const std::string& key, int index) {
          const GlobalStrain& s = numbers.strain[std::max(index, 0)];
          if (key == "ecc_percent") return s.level_ecc_percent[level];
          return key == "ell_percent" ? s.level_ell_percent[level]
                                      : kNotMeasured;
        });
  }
}

}  // namespace

void AddIntervals(const FitAnalysis& analysis, json* document) {
  if (!analysis.sd.computed) return;
  (*document)["uncertainty_definition"] = kUncertaintyDefinition;
  const IntervalData data = analysis.interval_data;
  (*document)["uncertainty_calibrated"] = {
      {"data", IntervalDataName(data)},
      {"keys", CalibratedIntervalKeys(data)},
      {"note", CalibrationNote(data)}};
  for (const char* key : {"ejection_fraction", "midwall_volume_fraction",
                          "epicardial_volume_fraction"}) {
    if (document->contains(key)) AddEjection(analysis, &(*document)[key]);
  }
  AddRegions(analysis, &(*document)["regions"]);
  AddStrain(analysis, &(*document)["strain"]);
  AddFrames(analysis, &(*document)["frames"]);
}

}  // namespace pfdm
