// The module functions that make a PointSequence: read_points and
// read_mesh_points read files as the CLI does, simulate makes a phantom.
#include <string>

#include "binding_helpers.h"
#include "bindings.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/mesh_source.h"
#include "pfdm/phantom/phantom.h"
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

// `pfdm simulate`'s phantom; the GIL released while it is made.
py::tuple Simulate(int frames, int tags, double noise, double outliers,
                   unsigned seed) {
  PhantomOptions options;
  options.num_frames = frames;
  options.num_points = tags;
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
