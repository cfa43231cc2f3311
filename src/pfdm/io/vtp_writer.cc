#include "pfdm/io/vtp_writer.h"

#include <sstream>
#include <string>

#include "glog/logging.h"
#include "pfdm/util/markup_escape.h"

namespace pfdm {
namespace {

// Escapes the characters XML forbids in attribute values.
void CellArrays(const char* element, const std::vector<int>& connectivity,
                int cell_size, std::string* out) {
  *out += "      <";
  *out += element;
  *out +=
      ">\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
      "format=\"ascii\">\n";
  for (size_t i = 0; i < connectivity.size(); ++i) {
    *out += ' ';
    AppendVtkNumber(connectivity[i], out);
    if ((i + 1) % cell_size == 0) *out += '\n';
  }
  *out +=
      "        </DataArray>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" "
      "format=\"ascii\">\n";
  for (size_t offset = cell_size; offset <= connectivity.size();
       offset += cell_size) {
    *out += ' ';
    *out += std::to_string(offset);
  }
  *out += "\n        </DataArray>\n      </";
  *out += element;
  *out += ">\n";
}

}  // namespace

std::string ToVtkXmlPolyData(const VtkPolyData& data) {
  const size_t n = data.points.size();
  std::vector<int> polygons;
  polygons.reserve(3 * data.triangles.size());
  for (const auto& t : data.triangles)
    polygons.insert(polygons.end(), t.begin(), t.end());
  std::string out;
  out.reserve(32 * n * (2 + data.point_vectors.size()) +
              12 * n * data.point_scalars.size() + 16 * data.triangles.size());
  const auto append_vector = [&out](const Eigen::Vector3d& v) {
    out += ' ';
    AppendVtkNumber(v.x(), &out);
    out += ' ';
    AppendVtkNumber(v.y(), &out);
    out += ' ';
    AppendVtkNumber(v.z(), &out);
    out += '\n';
  };
  out +=
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n  <PolyData>\n"
      "    <Piece NumberOfPoints=\"";
  out += std::to_string(n) + "\" NumberOfVerts=\"" +
         std::to_string(data.vertices.size()) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(data.triangles.size()) + "\">\n";
  out += "      <PointData>\n";
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), n) << name;
    out += "        <DataArray type=\"Float64\" Name=\"" + EscapeMarkup(name) +
           "\" format=\"ascii\">\n";
    for (double value : values) {
      out += ' ';
      AppendVtkNumber(value, &out);
    }
    out += "\n        </DataArray>\n";
  }
  for (const auto& [name, values] : data.point_vectors) {
    CHECK_EQ(values.size(), n) << name;
    out += "        <DataArray type=\"Float64\" Name=\"" + EscapeMarkup(name) +
           "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& v : values) append_vector(v);
    out += "        </DataArray>\n";
  }
  out +=
      "      </PointData>\n      <Points>\n"
      "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
      "format=\"ascii\">\n";
  for (const auto& p : data.points) append_vector(p);
  out += "        </DataArray>\n      </Points>\n";
  if (!data.vertices.empty()) CellArrays("Verts", data.vertices, 1, &out);
  if (!polygons.empty()) CellArrays("Polys", polygons, 3, &out);
  out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

std::string PvdCollection(
    const std::vector<std::pair<double, std::string>>& timesteps) {
  std::ostringstream out;
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [time, file] : timesteps) {
    out << "    <DataSet timestep=\"" << time
        << "\" group=\"\" part=\"0\" file=\"" << EscapeMarkup(file) << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace pfdm
