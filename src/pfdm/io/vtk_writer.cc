#include "pfdm/io/vtk_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>

#include "glog/logging.h"
#include "pfdm/util/error.h"

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

// The legacy format's binary numbers are big-endian whatever the machine.
void AppendBigEndian(std::uint64_t bits, std::string* out) {
  char bytes[8];
  for (int i = 0; i < 8; ++i)
    bytes[i] = static_cast<char>(bits >> (56 - 8 * i));
  out->append(bytes, 8);
}

void AppendBigEndian(double value, std::string* out) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  AppendBigEndian(bits, out);
}

void AppendBigEndian(float value, std::string* out) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  const char bytes[4] = {static_cast<char>(bits >> 24),
                         static_cast<char>(bits >> 16),
                         static_cast<char>(bits >> 8), static_cast<char>(bits)};
  out->append(bytes, 4);
}

void AppendBigEndian(int value, std::string* out) {
  const auto bits = static_cast<std::uint32_t>(value);
  const char bytes[4] = {static_cast<char>(bits >> 24),
                         static_cast<char>(bits >> 16),
                         static_cast<char>(bits >> 8), static_cast<char>(bits)};
  out->append(bytes, 4);
}

}  // namespace

VtkFormat VtkFormatFromName(const std::string& name) {
  if (name == "ascii") return VtkFormat::kAscii;
  if (name == "binary") return VtkFormat::kBinary;
  throw InputError("unknown --vtk_format '" + name +
                   "' (expected ascii or binary)");
}

VtkPrecision VtkPrecisionFromName(const std::string& name) {
  if (name == "float") return VtkPrecision::kFloat;
  if (name == "double") return VtkPrecision::kDouble;
  throw InputError("unknown --vtk_precision '" + name +
                   "' (expected float or double)");
}

bool IsFloat32Array(const VtkPolyData& data, const std::string& name,
                    VtkPrecision precision) {
  return precision == VtkPrecision::kFloat ||
         std::find(data.float32_scalars.begin(), data.float32_scalars.end(),
                   name) != data.float32_scalars.end();
}

void AppendVtkNumber(float value, std::string* out) {
  char buffer[32];
  const std::to_chars_result end =
      std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, end.ptr);
}

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

std::string ToLegacyVtk(const VtkPolyData& data, const std::string& title,
                        VtkFormat format, VtkPrecision precision) {
  const size_t n = data.points.size();
  const bool binary = format == VtkFormat::kBinary;
  CHECK_EQ(title.find('\n'), std::string::npos) << title;
  std::string out;
  // About 30 characters per point and per point's vector.
  out.reserve(32 * n * (2 + data.point_vectors.size()) +
              12 * n * data.point_scalars.size() + 16 * data.triangles.size());
  // In binary, a section's numbers follow its header line without
  // separators, and a newline closes the section before the next keyword.
  const auto append_number = [&out, binary](auto value, char separator) {
    if (binary) {
      AppendBigEndian(value, &out);
    } else {
      AppendVtkNumber(value, &out);
      out += separator;
    }
  };
  const auto end_section = [&out, binary] {
    if (binary) out += '\n';
  };
  // A real as float or double, as its array's type says.
  const auto append_real = [&append_number](double value, bool single,
                                            char separator) {
    if (single) {
      append_number(static_cast<float>(value), separator);
    } else {
      append_number(value, separator);
    }
  };
  const auto append_vector = [&append_real](const Eigen::Vector3d& v,
                                            bool single) {
    append_real(v.x(), single, ' ');
    append_real(v.y(), single, ' ');
    append_real(v.z(), single, '\n');
  };
  const auto type_name = [](bool single) {
    return single ? std::string("float") : std::string("double");
  };
  const bool single_points = precision == VtkPrecision::kFloat;
  const auto append_count = [&out](size_t count) {
    out += std::to_string(count);
  };
  out += "# vtk DataFile Version 3.0\n";
  out += title;
  out += binary ? "\nBINARY" : "\nASCII";
  out += "\nDATASET POLYDATA\nPOINTS ";
  append_count(n);
  out += " " + type_name(single_points) + "\n";
  for (const auto& p : data.points) append_vector(p, single_points);
  end_section();
  if (!data.vertices.empty()) {
    out += "VERTICES ";
    append_count(data.vertices.size());
    out += ' ';
    append_count(2 * data.vertices.size());
    out += '\n';
    for (int v : data.vertices) {
      CheckIndex(v, n);
      append_number(1, ' ');
      append_number(v, '\n');
    }
    end_section();
  }
  if (!data.triangles.empty()) {
    out += "POLYGONS ";
    append_count(data.triangles.size());
    out += ' ';
    append_count(4 * data.triangles.size());
    out += '\n';
    for (const auto& t : data.triangles) {
      for (int v : t) CheckIndex(v, n);
      append_number(3, ' ');
      append_number(t[0], ' ');
      append_number(t[1], ' ');
      append_number(t[2], '\n');
    }
    end_section();
  }
  if (!data.point_scalars.empty() || !data.point_vectors.empty()) {
    out += "POINT_DATA ";
    append_count(n);
    out += '\n';
  }
  for (const auto& [name, values] : data.point_scalars) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    const bool single = IsFloat32Array(data, name, precision);
    out += "SCALARS " + name + " " + type_name(single) +
           " 1\nLOOKUP_TABLE default\n";
    for (double value : values) append_real(value, single, '\n');
    end_section();
  }
  for (const auto& [name, values] : data.point_vectors) {
    CheckToken(name);
    CHECK_EQ(values.size(), n) << name;
    const bool single = IsFloat32Array(data, name, precision);
    out += "VECTORS " + name + " " + type_name(single) + "\n";
    for (const auto& v : values) append_vector(v, single);
    end_section();
  }
  return out;
}

}  // namespace pfdm
