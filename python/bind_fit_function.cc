// The module function fit: `pfdm fit` from Python, the flags as keywords.
#include <memory>
#include <optional>
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "fit_result.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_json.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/rv_insertion_source.h"
#include "pfdm/io/segmentation_overlay.h"
#include "pfdm/io/segmentation_source.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/error.h"
#include "pfdm/util/version.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// --apex, --base or --rv_insertion as the CLI reads it, from None (not
// given), a 'x,y,z' text or a sequence of numbers.
std::string PointText(const py::object& point, const char* name) {
  if (point.is_none()) return "";
  if (py::isinstance<py::str>(point)) return point.cast<std::string>();
  // repr round-trips a float exactly, so the hint is the one given.
  std::string text;
  for (py::handle x : point) {
    text += (text.empty() ? "" : ",") +
            py::repr(py::float_(py::reinterpret_borrow<py::object>(x)))
                .cast<std::string>();
  }
  if (text.empty()) throw InputError(std::string("--") + name + " is empty");
  return text;
}

// --loss_scale as the CLI reads it, from 'auto' (or any text) or a number.
std::string LossScaleText(const py::object& scale) {
  if (py::isinstance<py::str>(scale)) return scale.cast<std::string>();
  // repr round-trips a float exactly, so the scale is the one given.
  return py::repr(py::float_(scale)).cast<std::string>();
}

// Lets Ctrl-C stop a fit: checked at every step of every solver, refused
// ones too, and between the fit's rounds and stages
// (SolverOptions::interrupt), with the GIL held for the check only.  The
// exception stops the fit and reaches Python as KeyboardInterrupt.
void CheckSignals() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// fit's points: a PointSequence, a path read as read_points reads it, or
// arrays.
PointSequence SequenceFrom(const py::object& points,
                           const FitSettings& settings) {
  if (py::isinstance<PointSequence>(points)) {
    return points.cast<PointSequence>();
  }
  if (py::isinstance<py::str>(points) || py::isinstance<py::bytes>(points) ||
      py::hasattr(points, "__fspath__")) {
    return ReadPointsFrom(points, settings.format, settings.contours);
  }
  return SequenceFromArrays(points, py::none(), "arrays");
}

// The points, or a segmentation's contours (then *segmentation set and its
// misaligned slices raised as Python warnings).
PointSequence InputPoints(const py::object& points,
                          const py::object& segmentation,
                          const FitSettings& settings,
                          const std::string& labels,
                          std::optional<Segmentation>* read) {
  if (segmentation.is_none()) {
    if (points.is_none()) throw InputError("fit needs points or segmentation");
    return SequenceFrom(points, settings);
  }
  if (!points.is_none()) {
    throw InputError("give points or segmentation, not both");
  }
  *read = ReadSegmentation(PathString(segmentation), labels);
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& warning : (*read)->contours.warnings) {
    warn((*read)->volume.source + ": " + warning);
  }
  return (*read)->contours.points;
}

// Fits the points with everything the outputs are made of.  The settings
// are checked before the points are read, and the solve runs without the
// GIL.
std::shared_ptr<FitResult> FitPoints(const py::object& points,
                                     const py::object& segmentation,
                                     const std::string& labels,
                                     const FitSettings& settings) {
  auto result = std::make_shared<FitResult>();
  const ModelConfig config = ModelConfigFrom(settings);
  result->options = FitOptionsFrom(settings);
  BasePlanesFrom(settings, "");             // Checks base_plane before the fit.
  ParseRvInsertion(settings.rv_insertion);  // Likewise.
  std::optional<Segmentation> read;
  result->points = InputPoints(points, segmentation, settings, labels, &read);
  // Guide points' planes, landmarks and RV_INSERT: none in a label map.
  const std::string guides = read ? "" : result->points.source;
  CheckOptionsAgainstPoints(result->options, result->points);
  result->base_planes = BasePlanesFrom(settings, guides);
  FitOptions options = result->options;
  options.solver.interrupt = CheckSignals;
  AddLandmarkAxis(guides, &options);
  py::gil_scoped_release release;
  result->fit = FitSequence(result->points, config, options);
  CheckPlanesBelowApex(guides, result->base_planes, result->fit);
  const std::optional<RvInsertion> insertion =
      read && settings.rv_insertion.empty()
          ? read->rv_insertion
          : RvInsertionFrom(settings.rv_insertion, guides);
  result->analysis =
      AnalyzeFit(result->fit, result->base_planes,
                 AnatomicalLayout(result->fit.ModelAt(0), insertion));
  if (read) {
    AttachSegmentation(*read, &result->analysis);
    result->slices_svg = SegmentationOverlaySvg(
        read->volume, read->labels, read->contours, result->analysis.models,
        result->analysis.ejection_fraction.es_frame);
  }
  result->analysis.made_by = "pfdm.fit (Python)";
  result->analysis.made_utc = UtcMinuteNow();
  result->json =
      FitJson(result->points, result->fit, result->options, result->analysis);
  return result;
}

// fit(points, **flags): one parameter per `pfdm fit` flag, in the order
// BindFitFunction names them.
std::shared_ptr<FitResult> FitWithFlags(
    const py::object& points, const py::object& segmentation,
    const std::string& labels, const std::string& format,
    const std::string& contours, const std::string& base_plane,
    const py::object& rv_insertion, const std::string& model, int knots,
    const std::string& wall, const std::string& surface, int ed_frame,
    double smoothness, double prior, double untracked_prior,
    double untracked_prior_radii, double temporal_prior, double incompressible,
    const std::string& loss, const py::object& loss_scale, int threads,
    const py::object& apex, const py::object& base, const std::string& solver,
    const std::string& linear_solver, double time_step, double rest_tolerance,
    int max_steps, const std::string& damping, const std::string& damping_scale,
    const std::string& jacobian, const std::string& local,
    const std::string& local_grid, double local_stiffness,
    const std::string& local_transmural, const std::string& tag_depths,
    const std::string& uncertainty) {
  FitSettings s;
  s.format = format;
  s.contours = contours;
  s.base_plane = base_plane;
  s.rv_insertion = PointText(rv_insertion, "rv_insertion");
  s.model = model;
  s.knots = knots;
  s.wall = wall;
  s.surface = surface;
  s.ed_frame = ed_frame;
  s.smoothness = smoothness;
  s.prior = prior;
  s.untracked_prior = untracked_prior;
  s.untracked_prior_radii = untracked_prior_radii;
  s.temporal_prior = temporal_prior;
  s.incompressible = incompressible;
  s.loss = loss;
  s.loss_scale = LossScaleText(loss_scale);
  s.threads = threads;
  s.apex = PointText(apex, "apex");
  s.base = PointText(base, "base");
  s.solver = solver;
  s.linear_solver = linear_solver;
  s.time_step = time_step;
  s.rest_tolerance = rest_tolerance;
  s.max_steps = max_steps;
  s.damping = damping;
  s.damping_scale = damping_scale;
  s.jacobian = jacobian;
  s.local = local;
  s.local_grid = local_grid;
  s.local_stiffness = local_stiffness;
  s.local_transmural = local_transmural;
  s.tag_depths = tag_depths;
  s.uncertainty = uncertainty;
  return FitPoints(points, segmentation, labels, s);
}

}  // namespace

void BindFitFunction(py::module_& m) {
  const FitSettings fit_defaults;
  m.def("_fit", &FitWithFlags, py::arg("points") = py::none(), py::kw_only(),
        py::arg("segmentation") = py::none(), py::arg("labels") = "acdc",
        py::arg("format") = fit_defaults.format,
        py::arg("contours") = fit_defaults.contours,
        py::arg("base_plane") = fit_defaults.base_plane,
        py::arg("rv_insertion") = py::none(),
        py::arg("model") = fit_defaults.model,
        py::arg("knots") = fit_defaults.knots,
        py::arg("wall") = fit_defaults.wall,
        py::arg("surface") = fit_defaults.surface,
        py::arg("ed_frame") = fit_defaults.ed_frame,
        py::arg("smoothness") = fit_defaults.smoothness,
        py::arg("prior") = fit_defaults.prior,
        py::arg("untracked_prior") = fit_defaults.untracked_prior,
        py::arg("untracked_prior_radii") = fit_defaults.untracked_prior_radii,
        py::arg("temporal_prior") = fit_defaults.temporal_prior,
        py::arg("incompressible") = fit_defaults.incompressible,
        py::arg("loss") = fit_defaults.loss,
        py::arg("loss_scale") = fit_defaults.loss_scale,
        py::arg("threads") = fit_defaults.threads, py::arg("apex") = py::none(),
        py::arg("base") = py::none(), py::arg("solver") = fit_defaults.solver,
        py::arg("linear_solver") = fit_defaults.linear_solver,
        py::arg("time_step") = fit_defaults.time_step,
        py::arg("rest_tolerance") = fit_defaults.rest_tolerance,
        py::arg("max_steps") = fit_defaults.max_steps,
        py::arg("damping") = fit_defaults.damping,
        py::arg("damping_scale") = fit_defaults.damping_scale,
        py::arg("jacobian") = fit_defaults.jacobian,
        py::arg("local") = fit_defaults.local,
        py::arg("local_grid") = fit_defaults.local_grid,
        py::arg("local_stiffness") = fit_defaults.local_stiffness,
        py::arg("local_transmural") = fit_defaults.local_transmural,
        py::arg("tag_depths") = fit_defaults.tag_depths,
        py::arg("uncertainty") = fit_defaults.uncertainty,
        "pfdm.fit's compiled part, its keywords the CLI's strings.  Fits every "
        "frame, as `pfdm fit` does "
        "with the flags of the same names and defaults.  points: a "
        "PointSequence, a path (read as read_points with format and "
        "contours), or a list of (N, 3) arrays (point i of every frame the "
        "same material point).  segmentation: instead of points, a NIfTI "
        "label map (a 4D file, or a folder of 3D files one per frame) whose "
        "LV walls are fitted as contours, labels its values ('acdc', "
        "'mnms' or 'lv=3,myo=2,rv=1'), its misaligned slices raised as "
        "warnings (docs/segmentation.md).  apex and base: (x, y, z) in mm or "
        "'x,y,z', "
        "together.  base_plane 'auto' closes the cavity at the mitral valve "
        "planes of guide points read from a path, 'rim' at the base rim.  "
        "loss_scale: 'auto' or a number of mm.  "
        "rv_insertion: the anterior RV insertion (x, y, z), or it and the "
        "inferior one (6 numbers), or 'x,y,z[,x,y,z]': the AHA segments' "
        "anchor; without, guide points' RV_INSERT.  uncertainty 'on': "
        "each number's sd and 95 % interval (Fit.intervals, fit.json's "
        "*_ci95).  "
        "Releases the GIL; Ctrl-C raises KeyboardInterrupt within a solver "
        "step.  Raises InputError for bad options or data, with the CLI's "
        "message.");
}

}  // namespace pfdm::python
