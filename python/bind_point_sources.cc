// The module functions that make a PointSequence: read_points and
// read_mesh_points read files as the CLI does, simulate makes a phantom.
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/mesh_source.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/util/error.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

void BindReadPoints(py::module_& m) {
  const FitSettings fit_defaults;
  m.def(
      "read_points", &ReadPointsFrom, py::arg("path"),
      py::arg("format") = fit_defaults.format,
      py::arg("contours") = fit_defaults.contours,
      "Reads a PointSequence: a frame,id,x,y,z CSV, or biv-me guide points (a "
      "GPFile_*.txt or a folder of them) keeping the contour types listed, "
      "as `pfdm fit --points --format --contours` reads them.  Raises "
      "InputError naming the file and line.");
}

void BindReadMeshPoints(py::module_& m) {
  const MeshSettings mesh_defaults;
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
}

// frames or tags as an int for CheckPhantomOptions, which names the flag
// and its range; one beyond an int's range is refused here, as pybind11
// would refuse it as a TypeError naming no bound.
int PhantomCount(const char* name, std::int64_t value, double high) {
  if (value > std::numeric_limits<int>::max() ||
      value < std::numeric_limits<int>::min()) {
    std::ostringstream text;
    text << "--" << name << " must be between 1 and " << high << ", got "
         << value;
    throw InputError(text.str());
  }
  return static_cast<int>(value);
}

// `pfdm simulate`'s phantom, its size checked before it is made (also
// frames x tags, CheckPhantomOptions); the GIL released while it is made.
py::tuple Simulate(std::int64_t frames, std::int64_t tags, double noise,
                   double outliers, unsigned seed) {
  PhantomOptions options;
  options.num_frames = PhantomCount("frames", frames, 1000);
  options.num_points = PhantomCount("tags", tags, 1e6);
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
}

void BindSimulate(py::module_& m) {
  const PhantomOptions phantom_defaults;
  m.def("simulate", &Simulate, py::kw_only(),
        py::arg("frames") = phantom_defaults.num_frames,
        py::arg("tags") = phantom_defaults.num_points,
        py::arg("noise") = phantom_defaults.noise_mm,
        py::arg("outliers") = phantom_defaults.outlier_fraction,
        py::arg("seed") = phantom_defaults.seed,
        "(PointSequence, truth): `pfdm simulate`'s SPAMM-like LV phantom, "
        "its points and the list of true Models, one per frame.");
}

}  // namespace

void BindPointSources(py::module_& m) {
  BindReadPoints(m);
  BindReadMeshPoints(m);
  BindSimulate(m);
}

}  // namespace pfdm::python
