// Python's Model: one state of the deformable model, as its parameter
// functions at the knots and its pose, and the surface they make.
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "class_docs.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/model/model.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/model/parameter_function.h"
#include "pfdm/util/error.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// The parameter function named name, as FunctionFromName reads it; throws
// InputError listing the names for any other.
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

// (K,): the function named name at each knot, in its reported unit.
py::array_t<double> KnotValues(const Model& model, const std::string& name) {
  const int f = FunctionIndex(name);
  const KnotGrid& grid = model.config.Grid();
  py::array_t<double> values(grid.num_knots());
  for (int k = 0; k < grid.num_knots(); ++k) {
    values.mutable_data()[k] = ReportedValue(model, f, grid.KnotU(k));
  }
  return values;
}

// w None: the surface whose volume is reported, a solid's endocardium
// (w = -1) or a single surface's own (w = 0).
double VolumeMl(const Model& model, const py::object& w) {
  const double surface = !w.is_none()           ? w.cast<double>()
                         : model.config.Solid() ? -1.0
                                                : 0.0;
  return CavityVolumeMl(model, nullptr, surface);
}

std::string ModelRepr(const Model& model) {
  return "<pfdm.Model '" + model.config.name + "', " +
         std::to_string(model.config.num_knots) + " knots>";
}

}  // namespace

void BindModel(py::module_& m) {
  py::class_<Model>(m, "Model", kModelClassDoc)
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
      .def("function", &KnotValues, py::arg("name"), kFunctionDoc)
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
      .def("volume_ml", &VolumeMl, py::arg("w") = py::none(), kVolumeDoc)
      .def("__repr__", &ModelRepr);
}

}  // namespace pfdm::python
