#include "pfdm/io/vtp_writer.h"

#include <cstdint>
#include <cstring>
#include <list>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "glog/logging.h"
#include "pfdm/util/markup_escape.h"

namespace pfdm {
namespace {

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

static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double),
              "vectors of points are copied as packed doubles");

// The appended raw form: the XML names each array with its offset into the
// bytes after the '_' that opens <AppendedData>.  The arrays' bytes are
// copied once, by Close, into a string reserved for them: built up by
// appending, the file's megabytes were copied three times over into fresh
// memory, whose page faults were half of the writing.
class AppendedArrays {
 public:
  // Declares an array of `count` values at `data` with the given XML
  // attributes (type, name, components); data must live until Close.
  template <typename Value>
  void Add(const std::string& attributes, const Value* data, size_t count,
           std::string* xml) {
    static_assert(std::is_trivially_copyable_v<Value>);
    *xml += "        <DataArray " + attributes +
            " format=\"appended\" offset=\"" + std::to_string(size_) + "\"/>\n";
    const std::uint64_t size = count * sizeof(Value);
    arrays_.push_back({reinterpret_cast<const char*>(data), size});
    size_ += sizeof(size) + size;
  }

  // Add for values this object keeps.
  void Add(const std::string& attributes, std::vector<std::int64_t> values,
           std::string* xml) {
    kept_.push_back(std::move(values));
    Add(attributes, kept_.back().data(), kept_.back().size(), xml);
  }

  // Appends the <AppendedData> element, with room reserved for the file's
  // closing tag after it.
  void Close(std::string* xml) const {
    constexpr const char* kOpen = "  <AppendedData encoding=\"raw\">\n   _";
    constexpr const char* kEnd = "\n  </AppendedData>\n";
    constexpr size_t kClosingTag = 16;
    xml->reserve(xml->size() + std::strlen(kOpen) + size_ + std::strlen(kEnd) +
                 kClosingTag);
    *xml += kOpen;
    for (const auto& [data, size] : arrays_) {
      xml->append(reinterpret_cast<const char*>(&size), sizeof(size));
      xml->append(data, size);
    }
    *xml += kEnd;
  }

 private:
  std::vector<std::pair<const char*, std::uint64_t>> arrays_;
  std::list<std::vector<std::int64_t>> kept_;  // Stay put as it grows.
  std::uint64_t size_ = 0;
};

constexpr const char* kByteOrder =
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    "BigEndian";
#else
    "LittleEndian";
#endif

// Binary VTK XML: the same arrays as the ASCII form, in the same order.
std::string AppendedRawPolyData(const VtkPolyData& data) {
  const size_t n = data.points.size();
  std::string xml;
  AppendedArrays arrays;
  xml +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
      "byte_order=\"";
  xml += kByteOrder;
  xml +=
      "\" header_type=\"UInt64\">\n  <PolyData>\n    <Piece NumberOfPoints=\"";
  xml += std::to_string(n) + "\" NumberOfVerts=\"" +
         std::to_string(data.vertices.size()) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(data.triangles.size()) + "\">\n";
  xml += "      <PointData>\n";
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), n) << name;
    arrays.Add("type=\"Float64\" Name=\"" + EscapeMarkup(name) + "\"",
               values.data(), values.size(), &xml);
  }
  for (const auto& [name, values] : data.point_vectors) {
    CHECK_EQ(values.size(), n) << name;
    arrays.Add("type=\"Float64\" Name=\"" + EscapeMarkup(name) +
                   "\" NumberOfComponents=\"3\"",
               values.empty() ? nullptr : values[0].data(), 3 * n, &xml);
  }
  xml += "      </PointData>\n      <Points>\n";
  arrays.Add("type=\"Float64\" NumberOfComponents=\"3\"",
             data.points.empty() ? nullptr : data.points[0].data(), 3 * n,
             &xml);
  xml += "      </Points>\n";
  const auto cells = [&](const char* element, const std::vector<int>& indices,
                         int cell_size) {
    std::vector<std::int64_t> offsets;
    for (size_t end = cell_size; end <= indices.size(); end += cell_size) {
      offsets.push_back(static_cast<std::int64_t>(end));
    }
    xml += std::string("      <") + element + ">\n";
    arrays.Add("type=\"Int64\" Name=\"connectivity\"",
               std::vector<std::int64_t>(indices.begin(), indices.end()), &xml);
    arrays.Add("type=\"Int64\" Name=\"offsets\"", std::move(offsets), &xml);
    xml += std::string("      </") + element + ">\n";
  };
  if (!data.vertices.empty()) cells("Verts", data.vertices, 1);
  if (!data.triangles.empty()) {
    std::vector<int> polygons;
    polygons.reserve(3 * data.triangles.size());
    for (const auto& t : data.triangles) {
      polygons.insert(polygons.end(), t.begin(), t.end());
    }
    cells("Polys", polygons, 3);
  }
  xml += "    </Piece>\n  </PolyData>\n";
  arrays.Close(&xml);
  xml += "</VTKFile>\n";
  return xml;
}

}  // namespace

std::string ToVtkXmlPolyData(const VtkPolyData& data, VtkFormat format) {
  if (format == VtkFormat::kBinary) return AppendedRawPolyData(data);
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
