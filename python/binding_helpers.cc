#include "binding_helpers.h"

#include <string>

#include "pfdm/io/fit_output.h"
#include "pfdm/io/point_source.h"
#include "pfdm/model/parameter_function.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// describe(f) for every parameter function f, in column order.
py::list PerFunction(const char* (*describe)(int f)) {
  py::list list;
  for (int f = 0; f < kNumFunctions; ++f) list.append(describe(f));
  return list;
}

}  // namespace

int CheckedFrame(int t, size_t count) {
  if (t < 0) t += static_cast<int>(count);
  if (t < 0 || t >= static_cast<int>(count)) {
    throw py::index_error("frame " + std::to_string(t) + " of " +
                          std::to_string(count));
  }
  return t;
}

py::list FunctionNames() { return PerFunction(FunctionName); }

py::list FunctionUnits() { return PerFunction(ReportedUnit); }

PointSequence ReadPointsFrom(const py::object& path, const std::string& format,
                             const std::string& contours) {
  const std::string file = PathString(path);
  py::gil_scoped_release release;
  return ReadPoints(file, format, contours);
}

py::object JsonMember(const py::object& document, const char* key) {
  return document[key];
}

}  // namespace pfdm::python
