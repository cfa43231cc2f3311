// The module's bindings, one function per Python class or group of module
// functions.  BindModule (pfdm_module.cc) calls them in this order, which
// matters: pybind11 writes a signature's Python type names when a function
// is bound, so a class must be bound before the functions that take or
// return it.
#ifndef PFDM_PYTHON_BINDINGS_H_
#define PFDM_PYTHON_BINDINGS_H_

#include "pybind11/pybind11.h"

namespace pfdm::python {

namespace py = pybind11;

// PointSequence (bind_point_sequence.cc).
void BindPointSequence(py::module_& m);
// Model (bind_model.cc).
void BindModel(py::module_& m);
// FitFrame (bind_fit_frame.cc).
void BindFitFrame(py::module_& m);
// Fit (bind_fit_result.cc).
void BindFitResult(py::module_& m);
// read_points, read_mesh_points and simulate (bind_point_sources.cc).
void BindPointSources(py::module_& m);
// contours_from_segmentation (bind_segmentation.cc).
void BindSegmentation(py::module_& m);
// fit (bind_fit_function.cc).
void BindFitFunction(py::module_& m);

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_BINDINGS_H_
