// Legacy VTK polydata (.vtk) as ParaView, VTK 9 and pfdm itself write it.
#ifndef PFDM_IO_LEGACY_VTK_READER_H_
#define PFDM_IO_LEGACY_VTK_READER_H_

#include <map>
#include <string>
#include <vector>

#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// A legacy VTK POLYDATA file, ASCII or BINARY, in the classic cell layout
// or VTK 5.1's (OFFSETS and CONNECTIVITY): its points, its POLYGONS
// (fanned) and its one-component point arrays by name, SCALARS or FIELD
// arrays (as ParaView saves them); cell data, vectors and the like are read
// past.  Throws InputError "PATH:LINE: ..." ("PATH: byte N: ..." past
// binary data).
struct VtkMesh {
  TriangleMesh mesh;
  std::map<std::string, std::vector<double>> point_scalars;
};
VtkMesh ReadLegacyVtkPolyData(const std::string& path);

}  // namespace pfdm

#endif  // PFDM_IO_LEGACY_VTK_READER_H_
