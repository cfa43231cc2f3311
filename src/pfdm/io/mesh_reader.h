// Reads the surface meshes other LV tools write: Wavefront OBJ and the
// Cardiac Atlas Project's mean-shape vector (legacy VTK:
// legacy_vtk_reader.h), and frames of meshes as tracked points.
#ifndef PFDM_IO_MESH_READER_H_
#define PFDM_IO_MESH_READER_H_

#include <string>
#include <vector>

#include "pfdm/util/point_data.h"
#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// `v x y z` and `f a b c ...` lines (1-based or negative indices, `a/t/n`
// forms; polygons are fanned into triangles); other lines are ignored.
// Throws InputError "PATH:LINE: ...".
TriangleMesh ReadObj(const std::string& path);

// The CAP mean shape (cap-lv-mean/mean_shape.csv): one coordinate per line,
// x y z of each point in turn, four surfaces of equal size one after the
// other: ED-endo, ED-epi, ES-endo, ES-epi.  Returns the four point lists.
std::vector<std::vector<Eigen::Vector3d>> ReadCapMeanShape(
    const std::string& path);
// Its triangulation, surface_face.csv: 1-based index triples.
std::vector<std::array<int, 3>> ReadCapFaces(const std::string& path,
                                             int num_points);

// Frames of corresponding vertices as tracked points: id = vertex index.
// Throws InputError when the frames' vertex counts differ.
PointSequence MeshPointSequence(
    const std::string& source,
    const std::vector<std::vector<Eigen::Vector3d>>& frames);

}  // namespace pfdm

#endif  // PFDM_IO_MESH_READER_H_
