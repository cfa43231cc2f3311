// What several of the module's bindings share: frame indexing, the
// parameter functions' names and units, fit.json members, and the
// docstrings of members that Model and FitFrame both have.
#ifndef PFDM_PYTHON_BINDING_HELPERS_H_
#define PFDM_PYTHON_BINDING_HELPERS_H_

#include <cstddef>
#include <string>

#include "pfdm/util/point_data.h"
#include "pybind11/pybind11.h"

namespace pfdm::python {

namespace py = pybind11;

// Frame t of count, a negative t counting from the end as Python's
// indexing does.  Throws IndexError "frame T of COUNT" for one out of range.
int CheckedFrame(int t, size_t count);

// The kNumFunctions parameter functions' names (FunctionName) and units
// (ReportedUnit), in the column order of the `functions` arrays.
py::list FunctionNames();
py::list FunctionUnits();

// ReadPoints on a path-like (read_points, and fit given a path), the GIL
// released while the file is read.
PointSequence ReadPointsFrom(const py::object& path, const std::string& format,
                             const std::string& contours);

// An entry of a parsed document.  Returned as an object, not as the
// accessor operator[] makes, which borrows the document it points into.
py::object JsonMember(const py::object& document, const char* key);

inline constexpr const char* kFunctionsDoc =
    "(knots, 17) array: row k holds every function at knot k, columns in "
    "the order of function_names, in function_units (as parameters.csv: "
    "a0, a1..a3 as a0*a_i, b0, b2 and the offsets in mm, tau in radians, "
    "eps1, eps2, b1, b3 unitless).";

inline constexpr const char* kEvaluateDoc =
    "The model's surface point x(u, v) in world "
    "coordinates (mm), for array-likes u (latitude, apex u_min to base "
    "u_max) and v (longitude, -pi to pi) that broadcast together; shape "
    "theirs + (3,).  Beyond [u_min, u_max] the functions hold their end "
    "values.";

inline constexpr const char* kSurfaceDoc =
    "(vertices, faces): the model surface "
    "as a (V, 3) float array (mm) and an (F, 3) int array of outward-facing "
    "triangles, rings equally spaced in u from apex to base, open at the "
    "base rim; the defaults are the VTK files'.  For PyVista: "
    "pv.PolyData(vertices, np.hstack([np.full((len(faces), 1), 3), faces])); "
    "for trimesh: trimesh.Trimesh(vertices, faces).";

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_BINDING_HELPERS_H_
