// Python's FitFrame: one fitted frame of a Fit, its model, its numbers as
// parts of fit.json's frame entry, and arrays with a row per data point.
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "class_docs.h"
#include "fit_result.h"
#include "pfdm/io/fit_output.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

using FitFrameClass = py::class_<FitFrame>;

// fit.json frame keys that are volumes or mass: *_volume_ml, lv_mass_g.
bool IsVolumeKey(const std::string& key) {
  const std::string tail = "_volume_ml";
  return key == "lv_mass_g" ||
         (key.size() > tail.size() &&
          key.compare(key.size() - tail.size(), tail.size(), tail) == 0);
}

// The frame entry's plain numbers and words: neither its nested dicts
// (pose, clinical) nor its volumes, which `clinical` reports.
py::dict FrameStats(const FitFrame& f) {
  py::dict stats;
  for (auto [key, value] : f.Entry()) {
    if (py::isinstance<py::dict>(value) || IsVolumeKey(key.cast<std::string>()))
      continue;
    stats[key] = value;
  }
  return stats;
}

// The frame entry's clinical dict with the entry's volumes and mass added.
py::dict FrameClinical(const FitFrame& f) {
  py::dict entry = f.Entry();
  py::dict clinical = entry["clinical"];
  for (auto [key, value] : entry) {
    if (IsVolumeKey(key.cast<std::string>())) clinical[key] = value;
  }
  return clinical;
}

std::string FitFrameRepr(const FitFrame& f) {
  const FrameFit& frame = f.frame_fit();
  return "<pfdm.FitFrame " + std::to_string(frame.frame) + ": " +
         std::to_string(frame.residuals.size()) + " points, rms " +
         std::to_string(frame.rms_mm) + " mm>";
}

// stats, pose, clinical and uncertainty: fit.json's frame entry, in parts.
void DefEntryDicts(FitFrameClass& fit_frame) {
  fit_frame
      .def_property_readonly(
          "stats", &FrameStats,
          "dict: the fit statistics of fit.json's frame entry (n_points, "
          "rms_mm, mean_distance_mm, max_distance_mm, iterations, "
          "correspondence_rounds, solve_seconds, termination, ...).")
      .def_property_readonly(
          "pose",
          [](const FitFrame& f) { return JsonMember(f.Entry(), "pose"); },
          "dict: center_mm and quaternion_wxyz, as in fit.json.")
      .def_property_readonly(
          "clinical", &FrameClinical,
          "dict: the clinical summary of fit.json's frame entry (net twist, "
          "apex and base rotation, radial contraction, longitudinal "
          "shortening, per-knot ratios to frame 0, a solid's endo_* and "
          "epi_* numbers and wall thickening) and its volumes, named for "
          "what they enclose: cavity_volume_ml, midwall_volume_ml or "
          "epicardial_volume_ml, with a solid's myocardial_volume_ml and "
          "lv_mass_g.  None where fit.json has null: the rotations, twists, "
          "torsion, shear angle and gcl_percent of a frame without tracked "
          "points (contours), and the volumes and mass of a frame whose "
          "data span too little of the axis (short_span).")
      .def_property_readonly(
          "uncertainty",
          [](const FitFrame& f) -> py::object {
            const py::dict entry = f.Entry();
            if (!entry.contains("uncertainty")) return py::none();
            return entry["uncertainty"];
          },
          "dict or None: how the frame's covariance was scaled, fit.json's "
          "frame `uncertainty` (sigma_mm, the data's pooled residual sd; "
          "noise_sigma_mm, the noise its data's rows are weighed by; "
          "normal_sigma_mm where that was measured across the wall; "
          "degrees_of_freedom, parameters, rank_deficiency, "
          "deficient_directions, held, seconds).  None with uncertainty "
          "off.");
}

// ids, points, material, residuals and loss weights: a row per data
// point.
void DefDataPointArrays(FitFrameClass& fit_frame) {
  fit_frame
      .def_property_readonly(
          "ids", [](const FitFrame& f) { return IdsArray(f.data_points()); },
          "(N,) int64 array: the data points' ids.")
      .def_property_readonly(
          "points",
          [](const FitFrame& f) { return PositionsArray(f.data_points()); },
          "(N, 3) array: the data points (mm).")
      .def_property_readonly(
          "material",
          [](const FitFrame& f) {
            return MaterialArray(f.frame_fit().material);
          },
          "(N, 2) array: each data point's material point (u, v) on the "
          "model.")
      .def_property_readonly(
          "residuals",
          [](const FitFrame& f) {
            return VectorsArray(f.frame_fit().residuals);
          },
          "(N, 3) array: model point minus data point (mm).")
      .def_property_readonly(
          "loss_weights",
          [](const FitFrame& f) {
            std::vector<double> weights = f.frame_fit().loss_weights;
            weights.resize(f.frame_fit().residuals.size(), 1.0);
            return py::array_t<double>(weights.size(), weights.data());
          },
          "(N,) array: each data point's weight under the robust loss at "
          "its residual, in (0, 1] (the frame files' loss_weight); all 1 "
          "without a loss.");
}

}  // namespace

void BindFitFrame(py::module_& m) {
  FitFrameClass fit_frame(m, "FitFrame", kFitFrameClassDoc);
  fit_frame
      .def_property_readonly(
          "frame", [](const FitFrame& f) { return f.frame_fit().frame; },
          "The frame's index.")
      .def_property_readonly(
          "model", [](const FitFrame& f) { return f.model(); },
          "The fitted Model.")
      .def_property_readonly(
          "functions",
          [](const FitFrame& f) { return FunctionsArray(f.model()); },
          kFunctionsDoc);
  DefEntryDicts(fit_frame);
  DefDataPointArrays(fit_frame);
  fit_frame
      .def(
          "evaluate",
          [](const FitFrame& f, const py::object& u, const py::object& v) {
            return EvaluateModel(f.model(), u, v);
          },
          py::arg("u"), py::arg("v"), kEvaluateDoc)
      .def(
          "surface",
          [](const FitFrame& f, std::int64_t rings, std::int64_t meridians) {
            return SurfaceArrays(f.model(), rings, meridians);
          },
          py::arg("rings") = kSurfaceRings,
          py::arg("meridians") = kSurfaceMeridians, kSurfaceDoc)
      .def("__repr__", &FitFrameRepr);
}

}  // namespace pfdm::python
