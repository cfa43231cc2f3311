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
    "(knots, 18) array: row k holds every function at knot k, columns in "
    "the order of function_names, in function_units (as parameters.csv: "
    "a0, a1..a3 as a0*a_i, b0, b2 and the offsets in mm, tau in radians, "
    "eps1, eps2, b1, b3 unitless).";

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_BINDING_HELPERS_H_
