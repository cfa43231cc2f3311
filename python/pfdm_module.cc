// The compiled part of the Python package `pfdm` (python/pfdm/ wraps it):
// points in and fits out as NumPy arrays and plain dicts (README "Python"). The
// dicts are fit.json's, parsed, so what FitJson reports reaches Python without
// a change here.  Each class and group of functions is bound in a bind_*.cc of
// its own (bindings.h).
#include "binding_helpers.h"
#include "bindings.h"
#include "pfdm/util/error.h"
#include "pfdm/util/version.h"
#include "pybind11/pybind11.h"

namespace pfdm::python {

void BindModule(py::module_& m) {
  m.doc() =
      "pfdm: deformable models with parameter functions (Park, Metaxas & "
      "Young, CVPR 1994) fitted to 3D LV points; NumPy arrays in and out.";
  m.attr("__version__") = PfdmVersion();
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError)
      .attr("__doc__") =
      "Bad input (file, data, option) or a failed solve; the message is the "
      "CLI's one line naming the file and line, or the frame.";
  m.attr("FUNCTION_NAMES") = py::tuple(FunctionNames());
  m.attr("FUNCTION_UNITS") = py::tuple(FunctionUnits());
  BindPointSequence(m);
  BindModel(m);
  BindFitFrame(m);
  BindFitResult(m);
  BindPointSources(m);
  BindSegmentation(m);
  BindFitFunction(m);
}

}  // namespace pfdm::python

PYBIND11_MODULE(_pfdm, m) { pfdm::python::BindModule(m); }
