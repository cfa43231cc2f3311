// The Python module `pfdm`: points in and fits out as NumPy arrays and
// plain dicts (README "Python").  The dicts are fit.json's, parsed, so what
// FitJson reports reaches Python without a change here.
#include <memory>
#include <string>
#include <vector>

#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_json.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/mesh_source.h"
#include "pfdm/io/point_source.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// A fit with everything its outputs are made of.
struct FitResult {
  PointSequence points;
  FitOptions options;
  SequenceFit fit;
  std::vector<BasePlane> base_planes;
  FitAnalysis analysis;
  std::string json;  // fit.json.
};
using FitPtr = std::shared_ptr<const FitResult>;

struct FitFrame {
  FitPtr result;
  int t = 0;
  py::dict Entry() const {
    return FromJson(result->json)["frames"][py::int_(t)];
  }
};

// An entry of a parsed document.  Returned as an object, not as the
// accessor operator[] makes, which borrows the document it points into.
py::object JsonMember(const py::object& document, const char* key) {
  return document[key];
}

int CheckedFrame(int t, size_t count) {
  if (t < 0) t += static_cast<int>(count);
  if (t < 0 || t >= static_cast<int>(count)) {
    throw py::index_error("frame " + std::to_string(t) + " of " +
                          std::to_string(count));
  }
  return t;
}

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

// Lets Ctrl-C stop a fit: checked at every solver step, with the GIL held
// for the check only.  The exception stops the solve (SolverOptions::on_step)
// and reaches Python as KeyboardInterrupt.
void CheckSignals(const SolverTracePoint&) {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

PointSequence SequenceFrom(const py::object& points,
                           const FitSettings& settings) {
  if (py::isinstance<PointSequence>(points)) {
    return points.cast<PointSequence>();
  }
  if (py::isinstance<py::str>(points) || py::isinstance<py::bytes>(points) ||
      py::hasattr(points, "__fspath__")) {
    const std::string path = PathString(points);
    py::gil_scoped_release release;
    return ReadPoints(path, settings.format, settings.contours);
  }
  return SequenceFromArrays(points, py::none(), "arrays");
}

std::shared_ptr<FitResult> Fit(const py::object& points,
                               const FitSettings& settings) {
  auto result = std::make_shared<FitResult>();
  const ModelConfig config = ModelConfigFrom(settings);
  result->options = FitOptionsFrom(settings);
  BasePlanesFrom(settings, "");  // Checks base_plane before the fit.
  result->points = SequenceFrom(points, settings);
  FitOptions options = result->options;
  options.solver.on_step = CheckSignals;
  py::gil_scoped_release release;
  result->fit = FitSequence(result->points, config, options);
  result->base_planes = BasePlanesFrom(settings, result->points.source);
  result->analysis = AnalyzeFit(result->fit, result->base_planes);
  result->json =
      FitJson(result->points, result->fit, result->options, result->analysis);
  return result;
}

py::list Names() {
  py::list names;
  for (int f = 0; f < kNumFunctions; ++f) names.append(FunctionName(f));
  return names;
}

py::list Units() {
  py::list units;
  for (int f = 0; f < kNumFunctions; ++f) units.append(ReportedUnit(f));
  return units;
}

int FunctionIndex(const std::string& name) {
  const int f = FunctionFromName(name);
  if (f < 0) {
    std::string names;
    for (int g = 0; g < kNumFunctions; ++g) {
      names += (g ? ", " : "") + std::string(FunctionName(g));
    }
    throw InputError("unknown function '" + name + "' (expected " + names +
                     ")");
  }
  return f;
}

constexpr const char* kFunctionsDoc =
    "(knots, 17) array: row k holds every function at knot k, columns in "
    "the order of function_names, in function_units (as parameters.csv: "
    "a0, a1..a3 as a0*a_i, b0, b2 and the offsets in mm, tau in radians, "
    "eps1, eps2, b1, b3 unitless).";

constexpr const char* kEvaluateDoc =
    "The model's surface point x(u, v) in world "
    "coordinates (mm), for array-likes u (latitude, apex u_min to base "
    "u_max) and v (longitude, -pi to pi) that broadcast together; shape "
    "theirs + (3,).  Beyond [u_min, u_max] the functions hold their end "
    "values.";

constexpr const char* kSurfaceDoc =
    "(vertices, faces): the model surface "
    "as a (V, 3) float array (mm) and an (F, 3) int array of outward-facing "
    "triangles, rings equally spaced in u from apex to base, open at the "
    "base rim; the defaults are the VTK files'.  For PyVista: "
    "pv.PolyData(vertices, np.hstack([np.full((len(faces), 1), 3), faces])); "
    "for trimesh: trimesh.Trimesh(vertices, faces).";

void BindPointSequence(py::module_& m) {
  py::class_<PointSequence>(
      m, "PointSequence",
      "Frames of 3D points (mm) with integer ids: the same id in several "
      "frames is the same material point (a tracked tag), an id seen once "
      "an untracked surface sample (a contour point).")
      .def(py::init([](const py::object& frames, const py::object& ids,
                       const std::string& source) {
             return SequenceFromArrays(frames, ids, source);
           }),
           py::arg("frames"), py::arg("ids") = py::none(),
           py::arg("source") = "arrays",
           "PointSequence(frames, ids=None, source='arrays'): frames is a "
           "list of (N_t, 3) position arrays (mm) or one (F, N, 3) array; "
           "ids one integer array per frame, or None for point i of every "
           "frame being material point i.  Raises InputError for bad "
           "shapes, non-finite positions, repeated ids or empty frames.")
      .def_readonly("source", &PointSequence::source,
                    "Where the points came from (a path, 'arrays', "
                    "'phantom'); named in error messages and fit.json.")
      .def_readonly("contour_types", &PointSequence::contour_types,
                    "Guide points: the contour types kept; else empty.")
      .def_property_readonly(
          "num_frames", [](const PointSequence& s) { return s.frames.size(); },
          "Number of frames.")
      .def(
          "__len__", [](const PointSequence& s) { return s.frames.size(); },
          "Number of frames.")
      .def(
          "positions",
          [](const PointSequence& s, int t) {
            return PositionsArray(s.frames[CheckedFrame(t, s.frames.size())]);
          },
          py::arg("frame"), "(N, 3) array: the frame's positions (mm), a copy.")
      .def(
          "ids",
          [](const PointSequence& s, int t) {
            return IdsArray(s.frames[CheckedFrame(t, s.frames.size())]);
          },
          py::arg("frame"), "(N,) int64 array: the frame's point ids.")
      .def(
          "to_arrays",
          [](const PointSequence& s) {
            py::list positions, ids;
            for (const Frame& frame : s.frames) {
              positions.append(PositionsArray(frame));
              ids.append(IdsArray(frame));
            }
            return py::make_tuple(positions, ids);
          },
          "(positions, ids): lists with one array per frame, "
          "what PointSequence(positions, ids) takes.")
      .def(
          "write_csv",
          [](const PointSequence& s, const py::object& path) {
            WriteFileAtomically(PathString(path), ToPointsCsv(s));
          },
          py::arg("path"),
          "Writes the frame,id,x,y,z CSV that read_points and "
          "`pfdm fit --points` read, written whole or not at all.")
      .def("__repr__", [](const PointSequence& s) {
        size_t points = 0;
        for (const Frame& frame : s.frames) points += frame.points.size();
        return "<pfdm.PointSequence '" + s.source +
               "': " + std::to_string(s.frames.size()) + " frames, " +
               std::to_string(points) + " points>";
      });
}

void BindModel(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "One state of the deformable model: its parameter "
                    "functions over the knots and its pose.")
      .def_property_readonly(
          "name", [](const Model& model) { return model.config.name; },
          "The preset: 'paper' or 'superellipsoid'.")
      .def_property_readonly(
          "num_knots",
          [](const Model& model) { return model.config.num_knots; },
          "K, knots per function.")
      .def_property_readonly(
          "u_range",
          [](const Model& model) {
            return py::make_tuple(model.config.u_min, model.config.u_max);
          },
          "(u_min, u_max): latitude of the apex and of the base rim.")
      .def_property_readonly(
          "knot_u", [](const Model& model) { return KnotUArray(model.config); },
          "(K,) array: each knot's latitude u, apex to base.")
      .def_property_readonly(
          "functions", [](const Model& model) { return FunctionsArray(model); },
          kFunctionsDoc)
      .def(
          "function",
          [](const Model& model, const std::string& name) {
            const int f = FunctionIndex(name);
            const KnotGrid& grid = model.config.Grid();
            py::array_t<double> values(grid.num_knots());
            for (int k = 0; k < grid.num_knots(); ++k) {
              values.mutable_data()[k] = ReportedValue(model, f, grid.KnotU(k));
            }
            return values;
          },
          py::arg("name"),
          "(K,) array: one column of `functions`, e.g. "
          "'tau' (radians) or 'a3' (mm).")
      .def_property_readonly(
          "center",
          [](const Model& model) {
            return py::array_t<double>(3, model.state.center.data());
          },
          "(3,) array: the pose's translation (mm).")
      .def_property_readonly(
          "quaternion_wxyz",
          [](const Model& model) {
            return py::array_t<double>(4, model.state.quaternion.data());
          },
          "(4,) array: the pose's rotation, world from model, (w, x, y, z).")
      .def("evaluate", &EvaluateModel, py::arg("u"), py::arg("v"), kEvaluateDoc)
      .def("surface", &SurfaceArrays, py::arg("rings") = kSurfaceRings,
           py::arg("meridians") = kSurfaceMeridians, kSurfaceDoc)
      .def(
          "volume_ml",
          [](const Model& model, const py::object& w) {
            const double surface = !w.is_none()           ? w.cast<double>()
                                   : model.config.Solid() ? -1.0
                                                          : 0.0;
            return CavityVolumeMl(model, nullptr, surface);
          },
          py::arg("w") = py::none(),
          "The volume (ml) inside the model's surface w closed by a flat lid "
          "at the base rim: by default a solid's endocardium (w = -1, the "
          "cavity), or a single surface's own.")
      .def("__repr__", [](const Model& model) {
        return "<pfdm.Model '" + model.config.name + "', " +
               std::to_string(model.config.num_knots) + " knots>";
      });
}

// fit.json frame keys that are volumes or mass: *_volume_ml, lv_mass_g.
bool IsVolumeKey(const std::string& key) {
  const std::string tail = "_volume_ml";
  return key == "lv_mass_g" ||
         (key.size() > tail.size() &&
          key.compare(key.size() - tail.size(), tail.size(), tail) == 0);
}

void BindFit(py::module_& m) {
  py::class_<FitFrame>(m, "FitFrame",
                       "One fitted frame: the model, its numbers as dicts "
                       "(fit.json's frame entry) and per data point arrays.")
      .def_property_readonly(
          "frame",
          [](const FitFrame& f) { return f.result->fit.frames[f.t].frame; },
          "The frame's index.")
      .def_property_readonly(
          "model",
          [](const FitFrame& f) { return f.result->analysis.models[f.t]; },
          "The fitted Model.")
      .def_property_readonly(
          "functions",
          [](const FitFrame& f) {
            return FunctionsArray(f.result->analysis.models[f.t]);
          },
          kFunctionsDoc)
      .def_property_readonly(
          "stats",
          [](const FitFrame& f) {
            py::dict stats;
            for (auto [key, value] : f.Entry()) {
              if (py::isinstance<py::dict>(value) ||
                  IsVolumeKey(key.cast<std::string>()))
                continue;
              stats[key] = value;
            }
            return stats;
          },
          "dict: the fit statistics of fit.json's frame entry (n_points, "
          "rms_mm, mean_distance_mm, max_distance_mm, iterations, "
          "correspondence_rounds, solve_seconds, termination, ...).")
      .def_property_readonly(
          "pose",
          [](const FitFrame& f) { return JsonMember(f.Entry(), "pose"); },
          "dict: center_mm and quaternion_wxyz, as in fit.json.")
      .def_property_readonly(
          "clinical",
          [](const FitFrame& f) {
            py::dict entry = f.Entry();
            py::dict clinical = entry["clinical"];
            for (auto [key, value] : entry) {
              if (IsVolumeKey(key.cast<std::string>())) clinical[key] = value;
            }
            return clinical;
          },
          "dict: the clinical summary of fit.json's frame entry (net twist, "
          "apex and base rotation, radial contraction, longitudinal "
          "shortening, per-knot ratios to frame 0, a solid's endo_* and "
          "epi_* numbers and wall thickening) and its volumes, named for "
          "what they enclose: cavity_volume_ml, midwall_volume_ml or "
          "epicardial_volume_ml, with a solid's myocardial_volume_ml and "
          "lv_mass_g.")
      .def_property_readonly(
          "ids",
          [](const FitFrame& f) {
            return IdsArray(f.result->points.frames[f.t]);
          },
          "(N,) int64 array: the data points' ids.")
      .def_property_readonly(
          "points",
          [](const FitFrame& f) {
            return PositionsArray(f.result->points.frames[f.t]);
          },
          "(N, 3) array: the data points (mm).")
      .def_property_readonly(
          "material",
          [](const FitFrame& f) {
            return MaterialArray(f.result->fit.frames[f.t].material);
          },
          "(N, 2) array: each data point's material point (u, v) on the "
          "model.")
      .def_property_readonly(
          "residuals",
          [](const FitFrame& f) {
            return VectorsArray(f.result->fit.frames[f.t].residuals);
          },
          "(N, 3) array: model point minus data point (mm).")
      .def(
          "evaluate",
          [](const FitFrame& f, const py::object& u, const py::object& v) {
            return EvaluateModel(f.result->analysis.models[f.t], u, v);
          },
          py::arg("u"), py::arg("v"), kEvaluateDoc)
      .def(
          "surface",
          [](const FitFrame& f, int rings, int meridians) {
            return SurfaceArrays(f.result->analysis.models[f.t], rings,
                                 meridians);
          },
          py::arg("rings") = kSurfaceRings,
          py::arg("meridians") = kSurfaceMeridians, kSurfaceDoc)
      .def("__repr__", [](const FitFrame& f) {
        const FrameFit& frame = f.result->fit.frames[f.t];
        return "<pfdm.FitFrame " + std::to_string(frame.frame) + ": " +
               std::to_string(frame.residuals.size()) + " points, rms " +
               std::to_string(frame.rms_mm) + " mm>";
      });

  py::class_<FitResult, std::shared_ptr<FitResult>>(
      m, "Fit",
      "A fitted sequence: per frame a FitFrame; the whole fit.json as "
      "dicts; write() for the CLI's output files.")
      .def_property_readonly(
          "frames",
          [](const std::shared_ptr<FitResult>& r) {
            std::vector<FitFrame> frames;
            for (size_t t = 0; t < r->fit.frames.size(); ++t) {
              frames.push_back({r, static_cast<int>(t)});
            }
            return frames;
          },
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
                    "The PointSequence that was fitted.")
      .def_property_readonly(
          "functions",
          [](const FitResult& r) {
            const int frames = static_cast<int>(r.analysis.models.size());
            const int knots = r.fit.config.num_knots;
            py::array_t<double> all({frames, knots, int{kNumFunctions}});
            for (int t = 0; t < frames; ++t) {
              const py::array_t<double> one =
                  FunctionsArray(r.analysis.models[t]);
              std::copy(one.data(), one.data() + one.size(),
                        all.mutable_data() + t * one.size());
            }
            return all;
          },
          "(frames, knots, 17) array: every frame's `functions`.")
      .def_property_readonly(
          "knot_u", [](const FitResult& r) { return KnotUArray(r.fit.config); },
          "(K,) array: each knot's latitude u, apex to base.")
      .def_property_readonly(
          "function_names", [](const FitResult&) { return Names(); },
          "The 17 functions' names, the columns of `functions`.")
      .def_property_readonly(
          "function_units", [](const FitResult&) { return Units(); },
          "Their units: 'mm', 'rad' or '1'.")
      .def(
          "to_dict", [](const FitResult& r) { return FromJson(r.json); },
          "fit.json as Python dicts and lists (a fresh "
          "copy): settings, model, gauge_convention, ejection_fraction, "
          "regions, frames.")
      .def(
          "to_json", [](const FitResult& r) { return r.json; },
          "The text of fit.json.")
      .def_property_readonly(
          "settings",
          [](const FitResult& r) {
            return JsonMember(FromJson(r.json), "settings");
          },
          "dict: fit.json's settings.")
      .def_property_readonly(
          "model_info",
          [](const FitResult& r) {
            return JsonMember(FromJson(r.json), "model");
          },
          "dict: fit.json's model: name, knots, u range, and per function "
          "its mode (free, constant, fixed) and unit.")
      .def_property_readonly(
          "ejection_fraction",
          [](const FitResult& r) -> py::object {
            py::dict document = FromJson(r.json);
            if (!document.contains("ejection_fraction")) return py::none();
            return document["ejection_fraction"];
          },
          "dict: fit.json's ejection_fraction (ratio, ed_frame, es_frame, "
          "edv_ml, esv_ml, cavity_closure); None when the fitted surface "
          "is not the cavity's (volume_surface), whose volume fraction is "
          "then fit.json's <volume_surface>_volume_fraction.")
      .def_property_readonly(
          "volume_surface",
          [](const FitResult& r) { return r.analysis.volume_surface; },
          "What the volumes enclose: 'cavity', 'midwall' or 'epicardial'.")
      .def_property_readonly(
          "regions",
          [](const FitResult& r) {
            return JsonMember(FromJson(r.json), "regions");
          },
          "list of dict: the 16 AHA-style segments with rotation_deg and "
          "radial_contraction_percent per frame.")
      .def(
          "write",
          [](const FitResult& r, const py::object& out,
             const std::string& vtk_format) {
            const std::string dir = PathString(out);
            const VtkFormat format = VtkFormatFromName(vtk_format);
            py::gil_scoped_release release;
            CheckFitOutputFolder(dir, r.points.source);
            SvgRendering plots;
            WriteFitOutputs(dir, r.points, r.fit, r.analysis, r.options, format,
                            &plots);
          },
          py::arg("out"), py::kw_only(),
          py::arg("vtk_format") = FitSettings().vtk_format,
          "Writes the files `pfdm fit --out` writes into folder out "
          "(fit.json, parameters.csv, parameters.svg, report.html, "
          "frame_NNN.vtk and .vtp, fit.pvd), each whole or not at all, "
          "fit.json last; vtk_format 'binary' (legacy BINARY, XML appended "
          "raw) or 'ascii' as `--vtk_format`.")
      .def("__repr__", [](const FitResult& r) {
        return "<pfdm.Fit '" + r.points.source +
               "': " + std::to_string(r.fit.frames.size()) + " frames>";
      });
}

void BindFunctions(py::module_& m) {
  const FitSettings fit_defaults;
  const MeshSettings mesh_defaults;
  const PhantomOptions phantom_defaults;

  m.def(
      "read_points",
      [](const py::object& path, const std::string& format,
         const std::string& contours) {
        const std::string file = PathString(path);
        py::gil_scoped_release release;
        return ReadPoints(file, format, contours);
      },
      py::arg("path"), py::arg("format") = fit_defaults.format,
      py::arg("contours") = fit_defaults.contours,
      "Reads a PointSequence: a frame,id,x,y,z CSV, or biv-me guide points (a "
      "GPFile_*.txt or a folder of them) keeping the contour types listed, "
      "as `pfdm fit --points --format --contours` reads them.  Raises "
      "InputError naming the file and line.");

  m.def(
      "read_mesh_points",
      [](const py::object& path, const std::string& mesh_format,
         const std::string& mesh_filter, const std::string& label,
         const std::string& cap_surfaces) {
        const std::string file = PathString(path);
        py::gil_scoped_release release;
        return ReadMeshPoints(
            file, MeshSettings{mesh_format, mesh_filter, label, cap_surfaces});
      },
      py::arg("path"), py::kw_only(),
      py::arg("mesh_format") = mesh_defaults.mesh_format,
      py::arg("mesh_filter") = mesh_defaults.mesh_filter,
      py::arg("label") = mesh_defaults.label,
      py::arg("cap_surfaces") = mesh_defaults.cap_surfaces,
      "Reads a PointSequence: the vertices of corresponding meshes as tracked "
      "points (id = vertex "
      "index), as `pfdm mesh-points` reads them: a folder of .obj or .vtk "
      "files (one frame each, name order), a legacy .vtk polydata (ASCII or "
      "binary) or the CAP mean_shape.csv.");

  m.def(
      "simulate",
      [](int frames, int tags, double noise, double outliers, unsigned seed) {
        PhantomOptions options;
        options.num_frames = frames;
        options.num_points = tags;
        options.noise_mm = noise;
        options.outlier_fraction = outliers;
        options.seed = seed;
        CheckPhantomOptions(options);
        Phantom phantom;
        {
          py::gil_scoped_release release;
          phantom = MakePhantom(options);
        }
        return py::make_tuple(phantom.points, phantom.truth);
      },
      py::kw_only(), py::arg("frames") = phantom_defaults.num_frames,
      py::arg("tags") = phantom_defaults.num_points,
      py::arg("noise") = phantom_defaults.noise_mm,
      py::arg("outliers") = phantom_defaults.outlier_fraction,
      py::arg("seed") = phantom_defaults.seed,
      "(PointSequence, truth): `pfdm simulate`'s SPAMM-like LV phantom, "
      "its points and the list of true Models, one per frame.");

  m.def(
      "fit",
      [](const py::object& points, const std::string& format,
         const std::string& contours, const std::string& base_plane,
         const std::string& model, int knots, const std::string& wall,
         double smoothness, double prior, double untracked_prior,
         const std::string& loss, double loss_scale, int threads,
         const py::object& apex, const py::object& base,
         const std::string& solver, const std::string& linear_solver,
         double time_step, double rest_tolerance, int max_steps,
         const std::string& damping, const std::string& damping_scale,
         const std::string& jacobian, const std::string& local,
         const std::string& local_grid, double local_stiffness) {
        FitSettings s;
        s.format = format;
        s.contours = contours;
        s.base_plane = base_plane;
        s.model = model;
        s.knots = knots;
        s.wall = wall;
        s.smoothness = smoothness;
        s.prior = prior;
        s.untracked_prior = untracked_prior;
        s.loss = loss;
        s.loss_scale = loss_scale;
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
        return Fit(points, s);
      },
      py::arg("points"), py::kw_only(), py::arg("format") = fit_defaults.format,
      py::arg("contours") = fit_defaults.contours,
      py::arg("base_plane") = fit_defaults.base_plane,
      py::arg("model") = fit_defaults.model,
      py::arg("knots") = fit_defaults.knots,
      py::arg("wall") = fit_defaults.wall,
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
      "Releases the GIL; Ctrl-C raises KeyboardInterrupt within a solver "
      "step.  Raises InputError for bad options or data, with the CLI's "
      "message.");
}

}  // namespace

void BindModule(py::module_& m) {
  m.doc() =
      "pfdm: deformable models with parameter functions (Park, Metaxas & "
      "Young, CVPR 1994) fitted to 3D LV points; NumPy arrays in and out.";
  m.attr("__version__") = "0.1.0";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError)
      .attr("__doc__") =
      "Bad input (file, data, option) or a failed solve; the message is the "
      "CLI's one line naming the file and line, or the frame.";
  m.attr("FUNCTION_NAMES") = py::tuple(Names());
  m.attr("FUNCTION_UNITS") = py::tuple(Units());
  BindPointSequence(m);
  BindModel(m);
  BindFit(m);
  BindFunctions(m);
}

}  // namespace pfdm::python

PYBIND11_MODULE(pfdm, m) { pfdm::python::BindModule(m); }
