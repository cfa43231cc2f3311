// Python's Fit: a fitted sequence, its frames (FitFrame), fit.json as dicts
// and the CLI's output files.
#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "binding_helpers.h"
#include "bindings.h"
#include "class_docs.h"
#include "fit_intervals.h"
#include "fit_result.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/vtk_output.h"
#include "pfdm/report/gnuplot.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

using FitClass = py::class_<FitResult, std::shared_ptr<FitResult>>;

std::vector<FitFrame> AllFrames(const std::shared_ptr<FitResult>& result) {
  std::vector<FitFrame> frames;
  for (size_t t = 0; t < result->fit.frames.size(); ++t) {
    frames.push_back({result, static_cast<int>(t)});
  }
  return frames;
}

// (frames, knots, kNumFunctions): every frame's FunctionsArray.
py::array_t<double> StackedFunctions(const FitResult& result) {
  const int frames = static_cast<int>(result.analysis.models.size());
  const int knots = result.fit.config.num_knots;
  py::array_t<double> all({frames, knots, int{kNumFunctions}});
  for (int t = 0; t < frames; ++t) {
    const py::array_t<double> one = FunctionsArray(result.analysis.models[t]);
    std::copy(one.data(), one.data() + one.size(),
              all.mutable_data() + t * one.size());
  }
  return all;
}

// (frames, knots, kNumFunctions): each knot value's sd as parameters.csv's
// (ReportedSd, a3 with LengthVariance's length term), NaN on a frame whose
// covariance was not computed; None without --uncertainty.
py::object StackedFunctionSds(const FitResult& result) {
  if (!result.options.uncertainty) return py::none();
  const int frames = static_cast<int>(result.analysis.models.size());
  const int knots = result.fit.config.num_knots;
  py::array_t<double> all({frames, knots, int{kNumFunctions}});
  double* out = all.mutable_data();
  for (int t = 0; t < frames; ++t) {
    const Model& model = result.analysis.models[t];
    const FrameCovariance& covariance = result.fit.frames[t].covariance;
    const double length = LengthVariance(result.fit, t);
    for (int k = 0; k < knots; ++k) {
      for (int f = 0; f < kNumFunctions; ++f) {
        *out++ = covariance.computed
                     ? ReportedSd(model, covariance, f, k, length)
                     : std::numeric_limits<double>::quiet_NaN();
      }
    }
  }
  return std::move(all);
}

// A top-level member of fit.json, parsed afresh.
py::object FitJsonMember(const FitResult& result, const char* key) {
  return JsonMember(FromJson(result.json), key);
}

// fit.json's ejection_fraction, which only a fit of the cavity has.
py::object EjectionFraction(const FitResult& result) {
  py::dict document = FromJson(result.json);
  if (!document.contains("ejection_fraction")) return py::none();
  return document["ejection_fraction"];
}

// What `pfdm fit --out` writes; the GIL released once the arguments are read.
void WriteFitFiles(const FitResult& result, const py::object& out,
                   const std::string& vtk_format,
                   const std::string& vtk_precision) {
  const std::string dir = PathString(out);
  const VtkOutput format = VtkOutputFromNames(vtk_format, vtk_precision);
  py::gil_scoped_release release;
  CheckFitOutputFolder(dir, result.points.source);
  SvgRendering plots;
  WriteFitOutputs(dir, result.points, result.fit, result.analysis,
                  result.options, format, &plots, result.slices_svg);
}

std::string FitRepr(const FitResult& result) {
  return "<pfdm.Fit '" + result.points.source +
         "': " + std::to_string(result.fit.frames.size()) + " frames>";
}

// frames, len(fit), fit[t] and points: the frames and the data fitted.
void DefFrames(FitClass& fit) {
  fit.def_property_readonly("frames", &AllFrames,
                            "list of FitFrame, one per frame.")
      .def(
          "__len__", [](const FitResult& r) { return r.fit.frames.size(); },
          "Number of frames.")
      .def(
          "__getitem__",
          [](const std::shared_ptr<FitResult>& r, int t) {
            return FitFrame{r, CheckedFrame(t, r->fit.frames.size())};
          },
          py::arg("frame"), "fit[t]: the FitFrame of frame t.")
      .def_readonly("points", &FitResult::points,
                    "The PointSequence that was fitted.");
}

// functions, knot_u, function_names and function_units: the parameter
// functions of every frame and what their columns are.
void DefFunctions(FitClass& fit) {
  fit.def_property_readonly(
         "functions", &StackedFunctions,
         "(frames, knots, 18) array: every frame's `functions`.")
      .def_property_readonly(
          "function_sds", &StackedFunctionSds,
          "(frames, knots, 18) array: each value's standard deviation in its "
          "unit (parameters.csv's sd), NaN where a frame's covariance could "
          "not be computed; None without uncertainty.")
      .def_property_readonly(
          "knot_u", [](const FitResult& r) { return KnotUArray(r.fit.config); },
          "(K,) array: each knot's latitude u, apex to base.")
      .def_property_readonly(
          "function_names", [](const FitResult&) { return FunctionNames(); },
          "The 18 functions' names, the columns of `functions`.")
      .def_property_readonly(
          "function_units", [](const FitResult&) { return FunctionUnits(); },
          "Their units: 'mm', 'rad' or '1'.");
}

// to_dict, to_json and the members of fit.json that have a property.
void DefFitJson(FitClass& fit) {
  fit.def(
         "to_dict", [](const FitResult& r) { return FromJson(r.json); },
         "fit.json as Python dicts and lists (a fresh "
         "copy): settings, model, gauge_convention, ejection_fraction, "
         "regions, frames.")
      .def(
          "to_json", [](const FitResult& r) { return r.json; },
          "The text of fit.json.")
      .def_property_readonly(
          "settings",
          [](const FitResult& r) { return FitJsonMember(r, "settings"); },
          "dict: fit.json's settings.")
      .def_property_readonly(
          "model_info",
          [](const FitResult& r) { return FitJsonMember(r, "model"); },
          "dict: fit.json's model: name, knots, u range, and per function "
          "its mode (free, constant, fixed) and unit.")
      .def_property_readonly(
          "ejection_fraction", &EjectionFraction,
          "dict: fit.json's ejection_fraction (ratio, ed_frame, es_frame, "
          "edv_ml, esv_ml, es_by_midwall, cavity_closure); None when the "
          "fitted surface is not the cavity's (volume_surface), whose "
          "volume fraction is then fit.json's "
          "<volume_surface>_volume_fraction.  Its ratio and esv_ml are None "
          "when a frame has no volume (its data span too little of the "
          "axis: to_dict()['not_measured']['short_span']), or when ES, "
          "found by the volume inside the mid-wall where frames have no "
          "cavity (es_by_midwall), is such a frame "
          "(to_dict()['not_measured']['walls_unseen']).")
      .def_property_readonly(
          "volume_surface",
          [](const FitResult& r) { return r.analysis.volume_surface; },
          "What the volumes enclose: 'cavity', 'midwall' or 'epicardial'.")
      .def_property_readonly(
          "intervals", &Intervals,
          "dict of arrays, every derived number's value, sd, bias and 95 "
          "% interval (ci95: value - bias -+ 1.96 sd; sd by the delta "
          "method and the local field's noise draws, bias the local "
          "field's noise's, NaN without a local field), with "
          "uncertainty='on': 'frames' {name: {'value', 'sd', 'bias', "
          "'ci95'}} per frame, 'segments' the same per (frame, segment), "
          "'ejection_fraction' of (ratio, edv_ml, esv_ml), 'data' the "
          "kind of data fitted ('midwall tags', 'wall tags', 'wall "
          "contours', 'endocardial contours', 'epicardial contours', "
          "'midwall contours' or 'other') and 'calibrated' the names whose "
          "intervals held the truth in 90-98 % of noise draws on that kind "
          "(the others: lower bounds); None without.")
      .def_property_readonly(
          "dyssynchrony",
          [](const FitResult& r) { return FitJsonMember(r, "dyssynchrony"); },
          "dict: fit.json's dyssynchrony: index (the standard deviation of "
          "the segments' time to peak Ecc), unit ('ms' or 'frames'), "
          "time_to_peak and peak_frame per segment (None where not "
          "measured).")
      .def_property_readonly(
          "segments",
          [](const FitResult& r) { return FitJsonMember(r, "segments"); },
          "dict: fit.json's segments: anatomical, anchor (the RV "
          "insertion's source, or why the segments are not anatomical), "
          "definition, rv_insertion, apex_cap, and through_the_wall for a "
          "solid: what its segments cannot show (without "
          "--local_transmural, a regional defect through the wall; with it, "
          "a third of the wall's thickening).")
      .def_property_readonly(
          "regions",
          [](const FitResult& r) { return FitJsonMember(r, "regions"); },
          "list of dict: the 16 AHA-style segments with rotation_deg and "
          "radial_contraction_percent per frame; rotation_deg and "
          "ecl_percent None in frames without tracked points.");
}

}  // namespace

void BindFitResult(py::module_& m) {
  FitClass fit(m, "Fit", kFitClassDoc);
  DefFrames(fit);
  DefFunctions(fit);
  DefFitJson(fit);
  fit.def("write", &WriteFitFiles, py::arg("out"), py::kw_only(),
          py::arg("vtk_format") = FitSettings().vtk_format,
          py::arg("vtk_precision") = FitSettings().vtk_precision, kWriteDoc)
      .def("__repr__", &FitRepr);
}

}  // namespace pfdm::python
