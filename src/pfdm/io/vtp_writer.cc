#include "pfdm/io/vtp_writer.h"

#include <sstream>

#include "glog/logging.h"

namespace pfdm {
namespace {

// Escapes the characters XML forbids in attribute values.
std::string XmlAttribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void CellArrays(std::ostringstream& out, const char* element,
                const std::vector<std::vector<int>>& cells) {
  out << "      <" << element << ">\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"ascii\">\n";
  for (const auto& cell : cells) {
    for (int i : cell) out << ' ' << i;
    out << '\n';
  }
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  size_t offset = 0;
  for (const auto& cell : cells) out << ' ' << (offset += cell.size());
  out << "\n        </DataArray>\n      </" << element << ">\n";
}

}  // namespace

std::string ToVtkXmlPolyData(const VtkPolyData& data) {
  const size_t n = data.points.size();
  std::vector<std::vector<int>> vertices, polygons;
  for (int v : data.vertices) vertices.push_back({v});
  for (const auto& t : data.triangles) polygons.push_back({t[0], t[1], t[2]});
  std::ostringstream out;
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\""
      << vertices.size() << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
      << "NumberOfPolys=\"" << polygons.size() << "\">\n";
  out << "      <PointData>\n";
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), n) << name;
    out << "        <DataArray type=\"Float64\" Name=\"" << XmlAttribute(name)
        << "\" format=\"ascii\">\n";
    for (double value : values) out << ' ' << value;
    out << "\n        </DataArray>\n";
  }
  for (const auto& [name, values] : data.point_vectors) {
    CHECK_EQ(values.size(), n) << name;
    out << "        <DataArray type=\"Float64\" Name=\"" << XmlAttribute(name)
        << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& v : values) {
      out << ' ' << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    }
    out << "        </DataArray>\n";
  }
  out << "      </PointData>\n      <Points>\n"
      << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const auto& p : data.points) {
    out << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  out << "        </DataArray>\n      </Points>\n";
  if (!vertices.empty()) CellArrays(out, "Verts", vertices);
  if (!polygons.empty()) CellArrays(out, "Polys", polygons);
  out << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out.str();
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
        << "\" group=\"\" part=\"0\" file=\"" << XmlAttribute(file) << "\"/>\n";
  }
  out << "  </Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace pfdm
