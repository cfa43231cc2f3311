#include "pfdm/io/vtk_writer.h"

#include <charconv>
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

void AppendVtkNumber(double value, std::string* out) {
  char buffer[32];
  const std::to_chars_result end = std::to_chars(
      buffer, buffer + sizeof(buffer), value, std::chars_format::general, 9);
  out->append(buffer, end.ptr);
}

void AppendVtkNumber(int value, std::string* out) {
  char buffer[16];
  const std::to_chars_result end =
      std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, end.ptr);
}

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title) {
  const size_t n = data.points.size();
  CHECK_EQ(title.find('\n'), std::string::npos) << title;
  std::string out;
  // About 30 characters per point and per point's vector.
  out.reserve(32 * n * (2 + data.point_vectors.size()) +
              12 * n * data.point_scalars.size() + 16 * data.triangles.size());
  const auto append_vector = [&out](const Eigen::Vector3d& v) {
    AppendVtkNumber(v.x(), &out);
    out += ' ';
    AppendVtkNumber(v.y(), &out);
    out += ' ';
    AppendVtkNumber(v.z(), &out);
    out += '\n';
  };
  const auto append_count = [&out](size_t count) {
    out += std::to_string(count);
  };
  out += "# vtk DataFile Version 3.0\n";
  out += title;
  out += "\nASCII\nDATASET POLYDATA\nPOINTS ";
  append_count(n);
  out += " double\n";
  for (const auto& p : data.points) append_vector(p);
  if (!data.vertices.empty()) {
    out += "VERTICES ";
    append_count(data.vertices.size());
    out += ' ';
    append_count(2 * data.vertices.size());
    out += '\n';
    for (int v : data.vertices) {
      CheckIndex(v, n);
      out += "1 ";
      AppendVtkNumber(v, &out);
      out += '\n';
    }
  }
  if (!data.triangles.empty()) {
    out += "POLYGONS ";
    append_count(data.triangles.size());
    out += ' ';
    append_count(4 * data.triangles.size());
    out += '\n';
    for (const auto& t : data.triangles) {
      for (int v : t) CheckIndex(v, n);
      out += "3 ";
      AppendVtkNumber(t[0], &out);
      out += ' ';
      AppendVtkNumber(t[1], &out);
      out += ' ';
      AppendVtkNumber(t[2], &out);
      out += '\n';
    }
  }
  if (!data.point_scalars.empty() || !data.point_vectors.empty()) {
    out += "POINT_DATA ";
    append_count(n);
    out += '\n';
  }
  for (const auto& [name, values] : data.point_scalars) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    out += "SCALARS " + name + " double 1\nLOOKUP_TABLE default\n";
    for (double value : values) {
      AppendVtkNumber(value, &out);
      out += '\n';
    }
  }
  for (const auto& [name, values] : data.point_vectors) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    out += "VECTORS " + name + " double\n";
    for (const auto& v : values) append_vector(v);
  }
  return out;
}

}  // namespace pfdm
