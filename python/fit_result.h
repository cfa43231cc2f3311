// What the Python classes Fit and FitFrame hold: a fit with everything its
// outputs are made of, and one frame of it.
#ifndef PFDM_PYTHON_FIT_RESULT_H_
#define PFDM_PYTHON_FIT_RESULT_H_

#include <memory>
#include <string>
#include <vector>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/point_data.h"
#include "pybind11/pybind11.h"
#include "python_conversions.h"

namespace pfdm::python {

namespace py = pybind11;

// A fit with everything its outputs are made of.
struct FitResult {
  PointSequence points;
  FitOptions options;
  SequenceFit fit;
  std::vector<BasePlane> base_planes;
  FitAnalysis analysis;
  std::string json;  // fit.json.
  // A segmentation's slices with the fitted walls (fit(segmentation=)),
  // else empty.
  std::string slices_svg;
};
using FitPtr = std::shared_ptr<const FitResult>;

// Frame t of a fit.  It shares the fit, so a FitFrame taken from a Fit in
// Python stays valid after that Fit is gone.
struct FitFrame {
  FitPtr result;
  int t = 0;

  const Model& model() const { return result->analysis.models[t]; }
  const FrameFit& frame_fit() const { return result->fit.frames[t]; }
  const Frame& data_points() const { return result->points.frames[t]; }

  // The frame's entry of fit.json, parsed.
  py::dict Entry() const {
    return FromJson(result->json)["frames"][py::int_(t)];
  }
};

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_FIT_RESULT_H_
