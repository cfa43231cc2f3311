// The module function contours_from_segmentation: what `pfdm fit
// --segmentation` takes from a label map, as arrays.
#include <string>

#include "bindings.h"
#include "pfdm/io/segmentation_source.h"
#include "pybind11/numpy.h"
#include "pybind11/stl.h"
#include "python_conversions.h"

namespace pfdm::python {
namespace {

// One frame's points of one wall, (N, 3).
py::array_t<double> WallArray(const Frame& frame, WallLayer layer) {
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : frame.points) {
    if (p.layer == layer) points.push_back(p.position);
  }
  return VectorsArray(points);
}

py::dict ContoursFromSegmentation(const py::object& path,
                                  const std::string& labels) {
  const Segmentation s = ReadSegmentation(PathString(path), labels);
  const MaskContours& c = s.contours;
  py::list endo, epi, misaligned;
  for (const Frame& frame : c.points.frames) {
    endo.append(WallArray(frame, WallLayer::kEndocardium));
    epi.append(WallArray(frame, WallLayer::kEpicardium));
  }
  for (const MisalignedSlice& m : c.misaligned) {
    py::dict slice;
    slice["slice"] = m.slice;
    slice["frames"] = m.frames;
    slice["max_offset_mm"] = m.max_offset_mm;
    misaligned.append(slice);
  }
  py::dict out;
  out["endo"] = endo;
  out["epi"] = epi;
  out["points"] = c.points;
  out["rv_insertion"] = VectorsArray(c.rv_insertion);
  out["apex_slice"] = c.apex_slice;
  out["base_slice"] = c.base_slice;
  out["slice_thickness_mm"] = c.slice_thickness_mm;
  out["geometry"] = s.volume.geometry;
  out["shape"] =
      py::make_tuple(s.volume.nx, s.volume.ny, s.volume.nz, s.volume.nt);
  out["misaligned"] = misaligned;
  out["warnings"] = c.warnings;
  return out;
}

}  // namespace

void BindSegmentation(py::module_& m) {
  m.def("contours_from_segmentation", &ContoursFromSegmentation,
        py::arg("path"), py::arg("labels") = "acdc",
        "What `pfdm fit --segmentation PATH --labels LABELS` fits, as a "
        "dict: 'endo' and 'epi', per frame an (N, 3) array of world points "
        "(mm) on the LV cavity's boundary and the outer boundary of cavity "
        "and myocardium; 'points', the PointSequence fit takes; "
        "'rv_insertion' (2 per slice of frame 0, the RV contact arc's "
        "ends); 'apex_slice', 'base_slice' (per frame), "
        "'slice_thickness_mm', 'geometry' (sform, qform or pixdim), "
        "'shape' (nx, ny, nz, nt), 'misaligned' (slices off their "
        "neighbours' line) and 'warnings'.  path: a NIfTI file or a folder "
        "of one 3D file per frame; labels 'acdc', 'mnms' or "
        "'lv=3,myo=2,rv=1'.  Raises InputError as the CLI does.");
}

}  // namespace pfdm::python
