// Python's PointSequence: frames of points with ids, what a fit takes.
#include <cstddef>
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/point_data.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// Frame t, a negative t counting from the end (CheckedFrame).
const Frame& FrameAt(const PointSequence& sequence, int t) {
  return sequence.frames[CheckedFrame(t, sequence.frames.size())];
}

// (positions, ids): one array of each per frame.
py::tuple SequenceArrays(const PointSequence& sequence) {
  py::list positions, ids;
  for (const Frame& frame : sequence.frames) {
    positions.append(PositionsArray(frame));
    ids.append(IdsArray(frame));
  }
  return py::make_tuple(positions, ids);
}

std::string SequenceRepr(const PointSequence& sequence) {
  size_t points = 0;
  for (const Frame& frame : sequence.frames) points += frame.points.size();
  return "<pfdm.PointSequence '" + sequence.source +
         "': " + std::to_string(sequence.frames.size()) + " frames, " +
         std::to_string(points) + " points>";
}

}  // namespace

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
      .def_readonly("time_ms", &PointSequence::time_ms,
                    "Per frame, its time from the trigger (ms) when the "
                    "input has a time_ms column; else empty.")
      .def_property_readonly(
          "num_frames", [](const PointSequence& s) { return s.frames.size(); },
          "Number of frames.")
      .def(
          "__len__", [](const PointSequence& s) { return s.frames.size(); },
          "Number of frames.")
      .def(
          "positions",
          [](const PointSequence& s, int t) {
            return PositionsArray(FrameAt(s, t));
          },
          py::arg("frame"), "(N, 3) array: the frame's positions (mm), a copy.")
      .def(
          "ids",
          [](const PointSequence& s, int t) { return IdsArray(FrameAt(s, t)); },
          py::arg("frame"), "(N,) int64 array: the frame's point ids.")
      .def("to_arrays", &SequenceArrays,
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
      .def("__repr__", &SequenceRepr);
}

}  // namespace pfdm::python
