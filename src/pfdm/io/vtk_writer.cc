#include "pfdm/io/vtk_writer.h"

#include <sstream>
#include <string>

#include "glog/logging.h"

namespace pfdm {

namespace {

// An index past the points makes ParaView crash or draw garbage, far from
// the code that built the cells; fail here instead.
void CheckIndex(int index, size_t n) {
  CHECK_GE(index, 0);
  CHECK_LT(static_cast<size_t>(index), n);
}

// The legacy format is line- and token-based: a newline in the title or a
// space in an array name shifts every token after it.
void CheckToken(const std::string& name) {
  CHECK(!name.empty() && name.find_first_of(" \t\n") == std::string::npos)
      << "'" << name << "'";
}

}  // namespace

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title) {
  const size_t n = data.points.size();
  CHECK_EQ(title.find('\n'), std::string::npos) << title;
  std::ostringstream out;
  // %.9g: a nanometre on a heart-sized model, and files half the size of
  // round-trip precision.
  out.precision(9);
  out << "# vtk DataFile Version 3.0\n"
      << title << "\nASCII\n"
      << "DATASET POLYDATA\nPOINTS " << n << " double\n";
  for (const auto& p : data.points) {
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  if (!data.vertices.empty()) {
    out << "VERTICES " << data.vertices.size() << ' '
        << 2 * data.vertices.size() << '\n';
    for (int v : data.vertices) {
      CheckIndex(v, n);
      out << "1 " << v << '\n';
    }
  }
  if (!data.triangles.empty()) {
    out << "POLYGONS " << data.triangles.size() << ' '
        << 4 * data.triangles.size() << '\n';
    for (const auto& t : data.triangles) {
      for (int v : t) CheckIndex(v, n);
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
  }
  if (!data.point_scalars.empty() || !data.point_vectors.empty()) {
    out << "POINT_DATA " << n << '\n';
  }
  for (const auto& [name, values] : data.point_scalars) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
    for (double value : values) out << value << '\n';
  }
  for (const auto& [name, values] : data.point_vectors) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    out << "VECTORS " << name << " double\n";
    for (const auto& v : values) {
      out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    }
  }
  return out.str();
}

}  // namespace pfdm
