// Fit.intervals (bind_fit_intervals.cc).
#ifndef PFDM_PYTHON_FIT_INTERVALS_H_
#define PFDM_PYTHON_FIT_INTERVALS_H_

#include "fit_result.h"
#include "pybind11/numpy.h"

namespace pfdm::python {

// None without the covariances (uncertainty off); else {"frames": {name:
// {"value": (frames,), "sd": (frames,), "ci95": (frames, 2)}} for every
// clinical and strain number, "segments": the same with (frames, regions)
// for each segment number, "ejection_fraction": {"value", "sd", "ci95"}
// of (ratio, edv_ml, esv_ml), "data": the kind of data fitted,
// "calibrated": the names calibrated on it (interval_calibration.h)}.  NaN
// where a number is not measured.
py::object Intervals(const FitResult& result);

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_FIT_INTERVALS_H_
