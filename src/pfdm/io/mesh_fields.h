// Fields of the mesh formats' text, checked as the readers take them:
// errors name where they stand ("PATH:LINE").
#ifndef PFDM_IO_MESH_FIELDS_H_
#define PFDM_IO_MESH_FIELDS_H_

#include <cstddef>
#include <string>
#include <vector>

#include "pfdm/util/triangle_mesh.h"

namespace pfdm {

// A finite number; throws InputError("WHERE: 'TEXT' is not a number").
double ToNumber(const std::string& where, const std::string& text);
// A number within kMaxCoordinateMm of the origin (input_file.h).
double ToCoordinate(const std::string& where, const std::string& text);
// The same bound on a value read otherwise (binary), `text` its spelling in
// the error.
double CheckCoordinate(const std::string& where, double value,
                       const std::string& text);
// A whole number, all of text.
long long ToInteger(const std::string& where, const std::string& text);

// Adds the polygon's fan of triangles about its first vertex; throws
// InputError("WHERE: vertex I out of range") for an index past num_points.
void AddFan(const std::string& where, const std::vector<long long>& polygon,
            size_t num_points, TriangleMesh* mesh);

}  // namespace pfdm

#endif  // PFDM_IO_MESH_FIELDS_H_
