#include "python_conversions.h"

#include <cmath>
#include <unordered_set>

#include "pfdm/io/fit_output.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/util/error.h"

namespace pfdm::python {
namespace {

using DoubleArray =
    py::array_t<double, py::array::c_style | py::array::forcecast>;
using IdArray =
    py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

std::vector<py::object> Items(const py::object& list, const std::string& what,
                              const std::string& source) {
  if (py::isinstance<py::str>(list) || !py::hasattr(list, "__iter__")) {
    throw InputError(source + ": " + what);
  }
  std::vector<py::object> items;
  for (py::handle item : list)
    items.push_back(py::reinterpret_borrow<py::object>(item));
  return items;
}

std::vector<std::int64_t> FrameIds(const py::object& ids, size_t count,
                                   const std::string& where) {
  const py::array raw = py::array::ensure(ids);
  // Floats would be truncated silently into other points' ids.
  if (!raw || (raw.dtype().kind() != 'i' && raw.dtype().kind() != 'u')) {
    throw InputError(where + ": ids must be an array of integers");
  }
  const IdArray array = IdArray::ensure(raw);
  if (array.ndim() != 1 || static_cast<size_t>(array.shape(0)) != count) {
    throw InputError(where + ": ids must have shape (" + std::to_string(count) +
                     ",), got " + ShapeText(array));
  }
  return std::vector<std::int64_t>(array.data(), array.data() + count);
}

}  // namespace

PointSequence SequenceFromArrays(const py::object& frames,
                                 const py::object& ids,
                                 const std::string& source) {
  const std::vector<py::object> positions = Items(
      frames, "frames must be a list of (N, 3) arrays or an (F, N, 3) array",
      source);
  std::vector<py::object> id_lists;
  if (!ids.is_none()) {
    id_lists = Items(ids, "ids must be a list of integer arrays, one per frame",
                     source);
    if (id_lists.size() != positions.size()) {
      throw InputError(source + ": " + std::to_string(id_lists.size()) +
                       " id arrays for " + std::to_string(positions.size()) +
                       " frames");
    }
  }
  if (positions.empty()) throw InputError(source + ": no points");
  PointSequence sequence;
  sequence.source = source;
  for (size_t t = 0; t < positions.size(); ++t) {
    const std::string where = source + ": frame " + std::to_string(t);
    const DoubleArray array = DoubleArray::ensure(positions[t]);
    if (!array) {
      throw InputError(where +
                       ": positions must be an (N, 3) array of numbers");
    }
    if (array.ndim() != 2 || array.shape(1) != 3) {
      throw InputError(where +
                       ": positions must be an (N, 3) array, got shape " +
                       ShapeText(array));
    }
    const size_t count = array.shape(0);
    if (count == 0) {
      throw InputError(source + ": frame " + std::to_string(t) +
                       " has no points");
    }
    std::vector<std::int64_t> frame_ids(count);
    if (id_lists.empty()) {
      for (size_t i = 0; i < count; ++i) frame_ids[i] = i;
    } else {
      frame_ids = FrameIds(id_lists[t], count, where);
    }
    Frame frame;
    frame.index = static_cast<int>(t);
    frame.points.reserve(count);
    // Ids 0..N-1 (ids None) are distinct: no set of a million of them.
    std::unordered_set<std::int64_t> seen;
    if (!id_lists.empty()) seen.reserve(count);
    const double* xyz = array.data();
    for (size_t i = 0; i < count; ++i) {
      const Eigen::Vector3d p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      if (!p.allFinite()) {
        throw InputError(where + ": point " + std::to_string(i) +
                         " is not finite");
      }
      if (!id_lists.empty() && !seen.insert(frame_ids[i]).second) {
        throw InputError(source + ": id " + std::to_string(frame_ids[i]) +
                         " appears twice in frame " + std::to_string(t));
      }
      frame.points.push_back({frame_ids[i], p});
    }
    sequence.frames.push_back(std::move(frame));
  }
  return sequence;
}

py::array_t<double> VectorsArray(const std::vector<Eigen::Vector3d>& vectors) {
  py::array_t<double> array(
      {static_cast<py::ssize_t>(vectors.size()), py::ssize_t{3}});
  double* out = array.mutable_data();
  for (const Eigen::Vector3d& v : vectors) {
    *out++ = v.x();
    *out++ = v.y();
    *out++ = v.z();
  }
  return array;
}

py::array_t<double> PositionsArray(const Frame& frame) {
  std::vector<Eigen::Vector3d> positions;
  for (const DataPoint& p : frame.points) positions.push_back(p.position);
  return VectorsArray(positions);
}

py::array_t<std::int64_t> IdsArray(const Frame& frame) {
  py::array_t<std::int64_t> array(
      static_cast<py::ssize_t>(frame.points.size()));
  std::int64_t* out = array.mutable_data();
  for (const DataPoint& p : frame.points) *out++ = p.id;
  return array;
}

py::array_t<double> MaterialArray(const std::vector<MaterialPoint>& material) {
  py::array_t<double> array(
      {static_cast<py::ssize_t>(material.size()), py::ssize_t{2}});
  double* out = array.mutable_data();
  for (const MaterialPoint& m : material) {
    *out++ = m.u;
    *out++ = m.v;
  }
  return array;
}

py::array_t<double> FunctionsArray(const Model& model) {
  const KnotGrid& grid = model.config.Grid();
  const int knots = grid.num_knots();
  py::array_t<double> array({knots, static_cast<int>(kNumFunctions)});
  double* out = array.mutable_data();
  for (int k = 0; k < knots; ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      *out++ = ReportedValue(model, f, grid.KnotU(k));
    }
  }
  return array;
}

py::array_t<double> KnotUArray(const ModelConfig& config) {
  const KnotGrid& grid = config.Grid();
  py::array_t<double> array(grid.num_knots());
  for (int k = 0; k < grid.num_knots(); ++k) {
    array.mutable_data()[k] = grid.KnotU(k);
  }
  return array;
}

py::array_t<double> EvaluateModel(const Model& model, const py::object& u,
                                  const py::object& v) {
  const py::module_ numpy = py::module_::import("numpy");
  const py::tuple both = numpy.attr("broadcast_arrays")(
      numpy.attr("asarray")(u, "float64"), numpy.attr("asarray")(v, "float64"));
  // Broadcasting made views; the copies below and the result are what
  // would be allocated.
  const auto size = both[0].attr("size").cast<std::int64_t>();
  if (size > kMaxEvaluatePoints) {
    throw InputError("evaluate: u and v broadcast to " + std::to_string(size) +
                     " points, more than " +
                     std::to_string(kMaxEvaluatePoints));
  }
  const DoubleArray us = DoubleArray::ensure(both[0]);
  const DoubleArray vs = DoubleArray::ensure(both[1]);
  std::vector<py::ssize_t> shape(us.shape(), us.shape() + us.ndim());
  shape.push_back(3);
  py::array_t<double> points(shape);
  double* out = points.mutable_data();
  for (py::ssize_t i = 0; i < us.size(); ++i) {
    const double ui = us.data()[i], vi = vs.data()[i];
    if (!std::isfinite(ui) || !std::isfinite(vi)) {
      throw InputError("evaluate: u and v must be finite, got u = " +
                       std::to_string(ui) + ", v = " + std::to_string(vi));
    }
    const Eigen::Vector3d x = model.WorldPoint(ui, vi);
    *out++ = x.x();
    *out++ = x.y();
    *out++ = x.z();
  }
  return points;
}

py::tuple SurfaceArrays(const Model& model, std::int64_t rings,
                        std::int64_t meridians) {
  if (rings < 2 || meridians < 3) {
    throw InputError("surface needs rings >= 2 and meridians >= 3, got " +
                     std::to_string(rings) + " and " +
                     std::to_string(meridians));
  }
  // Checked before MakeModelSurface allocates: rings = meridians = 1e9
  // once ran for minutes towards 1e18 vertices.
  if (rings > kMaxSurfaceVertices / meridians) {
    throw InputError("surface needs rings x meridians <= " +
                     std::to_string(kMaxSurfaceVertices) + " vertices, got " +
                     std::to_string(rings) + " x " + std::to_string(meridians));
  }
  const ModelSurface surface = MakeModelSurface(model, static_cast<int>(rings),
                                                static_cast<int>(meridians));
  const auto& triangles = surface.mesh.triangles;
  py::array_t<std::int64_t> faces(
      {static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
  std::int64_t* out = faces.mutable_data();
  for (const auto& t : triangles) {
    for (int corner : t) *out++ = corner;
  }
  return py::make_tuple(VectorsArray(surface.mesh.points), faces);
}

py::object FromJson(const std::string& text) {
  return py::module_::import("json").attr("loads")(py::str(text));
}

std::string PathString(const py::object& path) {
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
}

}  // namespace pfdm::python
