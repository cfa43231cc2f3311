// Frames of meshes whose vertices correspond (pfdm mesh-points): a folder
// of OBJ or legacy VTK files, one such file, or the CAP mean shape.
#ifndef PFDM_IO_MESH_SOURCE_H_
#define PFDM_IO_MESH_SOURCE_H_

#include <string>
#include <vector>

#include "pfdm/util/point_data.h"
#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// pfdm mesh-points' settings under their flag names, with the flags'
// defaults (the Python module's keyword arguments too).
struct MeshSettings {
  std::string mesh_format = "auto";  // obj, vtk, cap-mean or auto.
  std::string mesh_filter;  // In a folder, the file names containing it.
  std::string label;        // VTK: keep the points whose scalar is this.
  std::string cap_surfaces = "ED-endo,ES-endo";  // CAP: the frames.
};

// One mesh per frame: the .obj files of a folder in name order (or its .vtk
// files, where it has no .obj or mesh_format is vtk), one .obj or .vtk
// file, or the CAP surfaces listed (their faces from surface_face.csv beside
// mean_shape.csv).  Throws InputError.
std::vector<TriangleMesh> ReadMeshFrames(const std::string& path,
                                         const MeshSettings& settings);

// The wall the meshes are of, by name: the CAP surfaces listed, or every
// frame file's name (biv-me's patient1_LV_ENDOCARDIAL_000.obj), all of the
// endocardium ("endo" in the name) or all of the epicardium ("epi" and no
// "endo"); kAnywhere otherwise, and for a VTK label, whose number means what
// the mesh's maker chose.
WallLayer MeshSurface(const std::string& path, const MeshSettings& settings);

// Their vertices as tracked points, id = vertex index (MeshPointSequence),
// on the MeshSurface.
PointSequence ReadMeshPoints(const std::string& path,
                             const MeshSettings& settings);

}  // namespace pfdm

#endif  // PFDM_IO_MESH_SOURCE_H_
