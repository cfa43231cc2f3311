// The module function fit: `pfdm fit` from Python, the flags as keywords.
#include <memory>
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
#include "pfdm/report/fit_analysis.h"
#include "pfdm/util/error.h"
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

// Fits the points with everything the outputs are made of.  The settings
// are checked before the points are read, and the solve runs without the
// GIL.
std::shared_ptr<FitResult> FitPoints(const py::object& points,
                                     const FitSettings& settings) {
  auto result = std::make_shared<FitResult>();
  const ModelConfig config = ModelConfigFrom(settings);
  result->options = FitOptionsFrom(settings);
  BasePlanesFrom(settings, "");             // Checks base_plane before the fit.
  ParseRvInsertion(settings.rv_insertion);  // Likewise.
  result->points = SequenceFrom(points, settings);
  CheckOptionsAgainstPoints(result->options, result->points);
  result->base_planes = BasePlanesFrom(settings, result->points.source);
  FitOptions options = result->options;
  options.solver.interrupt = CheckSignals;
  AddLandmarkAxis(result->points.source, &options);
  py::gil_scoped_release release;
  result->fit = FitSequence(result->points, config, options);
  CheckPlanesBelowApex(result->points.source, result->base_planes, result->fit);
  result->analysis = AnalyzeFit(
      result->fit, result->base_planes,
      AnatomicalLayout(
          result->fit.ModelAt(0),
          RvInsertionFrom(settings.rv_insertion, result->points.source)));
  result->json =
      FitJson(result->points, result->fit, result->options, result->analysis);
  return result;
}

// fit(points, **flags): one parameter per `pfdm fit` flag, in the order
// BindFitFunction names them.
std::shared_ptr<FitResult> FitWithFlags(
    const py::object& points, const std::string& format,
    const std::string& contours, const std::string& base_plane,
    const py::object& rv_insertion, const std::string& model, int knots,
    const std::string& wall, const std::string& surface, int ed_frame,
    double smoothness, double prior, double untracked_prior,
    const std::string& loss, const py::object& loss_scale, int threads,
    const py::object& apex, const py::object& base, const std::string& solver,
    const std::string& linear_solver, double time_step, double rest_tolerance,
    int max_steps, const std::string& damping, const std::string& damping_scale,
    const std::string& jacobian, const std::string& local,
    const std::string& local_grid, double local_stiffness) {
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
  return FitPoints(points, s);
}

}  // namespace

void BindFitFunction(py::module_& m) {
  const FitSettings fit_defaults;
  m.def("fit", &FitWithFlags, py::arg("points"), py::kw_only(),
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
        "Fits every frame, as `pfdm fit` does "
        "with the flags of the same names and defaults.  points: a "
        "PointSequence, a path (read as read_points with format and "
        "contours), or a list of (N, 3) arrays (point i of every frame the "
        "same material point).  apex and base: (x, y, z) in mm or 'x,y,z', "
        "together.  base_plane 'auto' closes the cavity at the mitral valve "
        "planes of guide points read from a path, 'rim' at the base rim.  "
        "loss_scale: 'auto' or a number of mm.  "
        "rv_insertion: the anterior RV insertion (x, y, z), or it and the "
        "inferior one (6 numbers), or 'x,y,z[,x,y,z]': the AHA segments' "
        "anchor; without, guide points' RV_INSERT.  "
        "Releases the GIL; Ctrl-C raises KeyboardInterrupt within a solver "
        "step.  Raises InputError for bad options or data, with the CLI's "
        "message.");
}

}  // namespace pfdm::python
