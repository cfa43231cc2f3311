// Between the library's types and NumPy arrays, Python dicts and lists:
// the pybind11 module's conversions, kept apart from its bindings.
#ifndef PFDM_PYTHON_PYTHON_CONVERSIONS_H_
#define PFDM_PYTHON_PYTHON_CONVERSIONS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"
#include "pybind11/numpy.h"
#include "pybind11/pybind11.h"

namespace pfdm::python {

namespace py = pybind11;

// frames: one (N_t, 3) array-like of positions (mm) per frame, or one
// (F, N, 3) array; ids: None (point i of every frame is material point i),
// or one integer array-like of N_t ids per frame.  Throws InputError
// "SOURCE: frame T: ..." for bad shapes, non-finite coordinates, non-integer
// or repeated ids, empty frames.
PointSequence SequenceFromArrays(const py::object& frames,
                                 const py::object& ids,
                                 const std::string& source);

// (N, 3) float64 array of the vectors, a copy.
py::array_t<double> VectorsArray(const std::vector<Eigen::Vector3d>& vectors);
py::array_t<double> PositionsArray(const Frame& frame);
py::array_t<std::int64_t> IdsArray(const Frame& frame);
// (N, 2) array of (u, v).
py::array_t<double> MaterialArray(const std::vector<MaterialPoint>& material);

// (K, kNumFunctions) array, row k the functions at knot k in the units
// parameters.csv reports them in (ReportedValue).
py::array_t<double> FunctionsArray(const Model& model);
// The knots' latitudes u, (K,).
py::array_t<double> KnotUArray(const ModelConfig& config);

// The most points evaluate and surface make (the result's float64 (N, 3):
// 1.2 GB and 0.1 GB, with surface's faces 0.3 GB), so that a size typed
// wrong is refused at once instead of swapping for minutes.
inline constexpr std::int64_t kMaxEvaluatePoints = 50000000;
inline constexpr std::int64_t kMaxSurfaceVertices = 4000000;

// x(u, v) in world coordinates (mm) for u, v array-likes that broadcast
// against each other; shape: theirs plus a last axis of 3.  Throws
// InputError for non-finite u or v, or over kMaxEvaluatePoints points.
py::array_t<double> EvaluateModel(const Model& model, const py::object& u,
                                  const py::object& v);

// (vertices (V, 3) float64, faces (F, 3) int64) of the model's u, v grid,
// as MakeModelSurface makes it.  Throws InputError for rings < 2 or
// meridians < 3, or over kMaxSurfaceVertices vertices, before allocating.
py::tuple SurfaceArrays(const Model& model, std::int64_t rings,
                        std::int64_t meridians);

// A JSON text as Python dicts, lists and numbers (json.loads).
py::object FromJson(const std::string& text);

// A path-like (str, os.PathLike) as a string.
std::string PathString(const py::object& path);

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_PYTHON_CONVERSIONS_H_
