#include "pfdm/vtk_writer.h"

#include <sstream>

#include "glog/logging.h"

namespace pfdm {

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title) {
  const size_t n = data.points.size();
  std::ostringstream out;
  out.precision(9);
  out << "# vtk DataFile Version 3.0\n" << title << "\nASCII\n"
      << "DATASET POLYDATA\nPOINTS " << n << " double\n";
  for (const auto& p : data.points) {
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  if (!data.vertices.empty()) {
    out << "VERTICES " << data.vertices.size() << ' '
        << 2 * data.vertices.size() << '\n';
    for (int v : data.vertices) out << "1 " << v << '\n';
  }
  if (!data.triangles.empty()) {
    out << "POLYGONS " << data.triangles.size() << ' '
        << 4 * data.triangles.size() << '\n';
    for (const auto& t : data.triangles) {
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
  }
  if (!data.point_scalars.empty() || !data.point_vectors.empty()) {
    out << "POINT_DATA " << n << '\n';
  }
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), n) << name;
    out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
    for (double value : values) out << value << '\n';
  }
  for (const auto& [name, values] : data.point_vectors) {
    CHECK_EQ(values.size(), n) << name;
    out << "VECTORS " << name << " double\n";
    for (const auto& v : values) {
      out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    }
  }
  return out.str();
}

}  // namespace pfdm
