// Python's Fit.intervals: every derived number's values, standard
// deviations and 95 % intervals as arrays (report/number_uncertainty.h).
#include <array>
#include <string>
#include <vector>

#include "fit_intervals.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/report/number_sd.h"
#include "pybind11/stl.h"

namespace pfdm::python {
namespace {

// {"value": (n,) or (n, R), "sd": same, "bias": same, "ci95": same +
// (2,)} from values, sds and biases laid out frame-major; NaN where not
// measured (a NaN bias: none, the interval about the value).
py::dict Arrays(const std::vector<double>& values,
                const std::vector<double>& sds,
                const std::vector<double>& biases,
                const std::vector<py::ssize_t>& shape) {
  py::array_t<double> value(shape), sd(shape), bias(shape);
  std::vector<py::ssize_t> pair_shape = shape;
  pair_shape.push_back(2);
  py::array_t<double> ci95(pair_shape);
  for (size_t i = 0; i < values.size(); ++i) {
    value.mutable_data()[i] = values[i];
    sd.mutable_data()[i] = sds[i];
    bias.mutable_data()[i] = biases[i];
    const std::array<double, 2> interval =
        Interval95(values[i], sds[i], biases[i]);
    ci95.mutable_data()[2 * i] = interval[0];
    ci95.mutable_data()[2 * i + 1] = interval[1];
  }
  py::dict out;
  out["value"] = value;
  out["sd"] = sd;
  out["bias"] = bias;
  out["ci95"] = ci95;
  return out;
}

// Field `i` of Fields() over the frames (and regions).
template <typename Struct>
std::vector<double> Column(const std::vector<Struct>& items, size_t i,
                           std::vector<double*> (*fields)(Struct*)) {
  std::vector<double> column;
  for (Struct item : items) column.push_back(*fields(&item)[i]);
  return column;
}

// The biases' column (FitAnalysis::noise_bias), NaN when not computed.
template <typename Struct>
std::vector<double> BiasColumn(const FitAnalysis& a,
                               const std::vector<Struct>& biases, size_t i,
                               size_t size,
                               std::vector<double*> (*fields)(Struct*)) {
  return a.noise_bias.computed ? Column(biases, i, fields)
                               : std::vector<double>(size, kNotMeasured);
}

py::dict PerFrame(const FitAnalysis& a) {
  py::dict out;
  const py::ssize_t frames = a.clinical.size();
  for (size_t i = 0; i < ClinicalFieldNames().size(); ++i) {
    out[py::str(ClinicalFieldNames()[i])] =
        Arrays(Column(a.clinical, i, &ClinicalFields),
               Column(a.sd.clinical, i, &ClinicalFields),
               BiasColumn(a, a.noise_bias.clinical, i, frames, &ClinicalFields),
               {frames});
  }
  for (size_t i = 0; i < StrainFieldNames().size(); ++i) {
    out[py::str(StrainFieldNames()[i])] = Arrays(
        Column(a.strain, i, &StrainFields),
        Column(a.sd.strain, i, &StrainFields),
        BiasColumn(a, a.noise_bias.strain, i, frames, &StrainFields), {frames});
  }
  return out;
}

py::dict PerSegment(const FitAnalysis& a) {
  std::vector<RegionMotion> values, sds, biases;  // Frame-major.
  for (size_t t = 0; t < a.region_motion.size(); ++t) {
    values.insert(values.end(), a.region_motion[t].begin(),
                  a.region_motion[t].end());
    sds.insert(sds.end(), a.sd.region_motion[t].begin(),
               a.sd.region_motion[t].end());
    if (a.noise_bias.computed) {
      biases.insert(biases.end(), a.noise_bias.region_motion[t].begin(),
                    a.noise_bias.region_motion[t].end());
    }
  }
  const py::ssize_t frames = a.region_motion.size();
  const py::ssize_t regions = frames > 0 ? a.region_motion[0].size() : 0;
  py::dict out;
  for (size_t i = 0; i < RegionFieldNames().size(); ++i) {
    out[py::str(RegionFieldNames()[i])] =
        Arrays(Column(values, i, &RegionFields), Column(sds, i, &RegionFields),
               BiasColumn(a, biases, i, values.size(), &RegionFields),
               {frames, regions});
  }
  return out;
}

py::dict Ejection(const FitAnalysis& a) {
  const EjectionFraction& ef = a.ejection_fraction;
  const EjectionFraction& sd = a.sd.ejection_fraction;
  const EjectionFraction& bias = a.noise_bias.ejection_fraction;
  const bool biased = a.noise_bias.computed;
  return Arrays(
      {ef.ratio, ef.edv_ml, ef.esv_ml}, {sd.ratio, sd.edv_ml, sd.esv_ml},
      biased ? std::vector<double>{bias.ratio, bias.edv_ml, bias.esv_ml}
             : std::vector<double>(3, kNotMeasured),
      {3});
}

}  // namespace

py::object Intervals(const FitResult& result) {
  const FitAnalysis& a = result.analysis;
  if (!a.sd.computed) return py::none();
  py::dict out;
  out["frames"] = PerFrame(a);
  out["segments"] = PerSegment(a);
  out["ejection_fraction"] = Ejection(a);
  out["data"] = IntervalDataName(a.interval_data);
  out["calibrated"] = CalibratedIntervalKeys(a.interval_data);
  return out;
}

}  // namespace pfdm::python
