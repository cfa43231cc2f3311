#include "pfdm/io/vtp_writer.h"

#include <algorithm>
#include <climits>
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

static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double),
              "vectors of points are copied as packed doubles");

constexpr const char* kByteOrder =
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    "BigEndian";
#else
    "LittleEndian";
#endif

template <typename To, typename From>
std::string BytesOf(const From* data, size_t count) {
  std::string bytes(count * sizeof(To), '\0');
  for (size_t i = 0; i < count; ++i) {
    const To value = static_cast<To>(data[i]);
    std::memcpy(&bytes[i * sizeof(To)], &value, sizeof(To));
  }
  return bytes;
}

// The <DataArray> elements of one file, ASCII inline or appended raw.  In
// the appended raw form the XML names each array with its offset into the
// bytes after the '_' that opens <AppendedData>.  The arrays' bytes are
// copied once, by Close, into a string reserved for them: built up by
// appending, the file's megabytes were copied three times over into fresh
// memory, whose page faults were half of the writing.
class DataArrays {
 public:
  explicit DataArrays(VtkFormat format)
      : binary_(format == VtkFormat::kBinary) {}

  // `count` reals at `data` (which must live until Close) as Float32 or
  // Float64; in ASCII a newline after every per_line values (0: at the end).
  void Reals(const std::string& attributes, const double* data, size_t count,
             bool single, int per_line, std::string* xml) {
    const std::string type = single ? "Float32" : "Float64";
    if (!binary_) {
      Open(type, attributes, xml);
      for (size_t i = 0; i < count; ++i) {
        *xml += ' ';
        if (single) {
          AppendVtkNumber(static_cast<float>(data[i]), xml);
        } else {
          AppendVtkNumber(data[i], xml);
        }
        EndOfLine(i, count, per_line, xml);
      }
      *xml += "        </DataArray>\n";
    } else if (single) {
      Append(type, attributes, Keep(BytesOf<float>(data, count)), xml);
    } else {
      Append(type, attributes,
             {reinterpret_cast<const char*>(data), count * sizeof(double)},
             xml);
    }
  }

  // Indices as Int32 where the largest fits, else Int64.
  void Integers(const std::string& attributes,
                const std::vector<std::int64_t>& values, int per_line,
                std::string* xml) {
    const bool narrow =
        values.empty() ||
        *std::max_element(values.begin(), values.end()) <= INT32_MAX;
    const std::string type = narrow ? "Int32" : "Int64";
    if (!binary_) {
      Open(type, attributes, xml);
      for (size_t i = 0; i < values.size(); ++i) {
        *xml += ' ';
        *xml += std::to_string(values[i]);
        EndOfLine(i, values.size(), per_line, xml);
      }
      *xml += "        </DataArray>\n";
      return;
    }
    Append(type, attributes,
           Keep(narrow ? BytesOf<std::int32_t>(values.data(), values.size())
                       : BytesOf<std::int64_t>(values.data(), values.size())),
           xml);
  }

  // Appends the <AppendedData> element, if any, with room reserved for the
  // file's closing tag after it.
  void Close(std::string* xml) const {
    if (!binary_) return;
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
  using Bytes = std::pair<const char*, std::uint64_t>;

  static void Open(const std::string& type, const std::string& attributes,
                   std::string* xml) {
    *xml += "        <DataArray type=\"" + type + "\" " + attributes +
            " format=\"ascii\">\n";
  }

  static void EndOfLine(size_t i, size_t count, int per_line,
                        std::string* xml) {
    if (per_line > 0 ? (i + 1) % per_line == 0 : i + 1 == count) *xml += '\n';
  }

  Bytes Keep(std::string bytes) {
    kept_.push_back(std::move(bytes));
    return {kept_.back().data(), kept_.back().size()};
  }

  void Append(const std::string& type, const std::string& attributes,
              Bytes bytes, std::string* xml) {
    *xml += "        <DataArray type=\"" + type + "\" " + attributes +
            " format=\"appended\" offset=\"" + std::to_string(size_) + "\"/>\n";
    arrays_.push_back(bytes);
    size_ += sizeof(std::uint64_t) + bytes.second;
  }

  bool binary_;
  std::vector<Bytes> arrays_;
  std::list<std::string> kept_;  // Stay put as it grows.
  std::uint64_t size_ = 0;
};

// A cell section (Verts, Polys) of cells of cell_size point indices.
void CellArrays(const char* element, const std::vector<int>& indices,
                int cell_size, DataArrays* arrays, std::string* xml) {
  std::vector<std::int64_t> offsets;
  for (size_t end = cell_size; end <= indices.size(); end += cell_size) {
    offsets.push_back(static_cast<std::int64_t>(end));
  }
  *xml += std::string("      <") + element + ">\n";
  arrays->Integers("Name=\"connectivity\"",
                   std::vector<std::int64_t>(indices.begin(), indices.end()),
                   cell_size, xml);
  arrays->Integers("Name=\"offsets\"", offsets, 0, xml);
  *xml += std::string("      </") + element + ">\n";
}

}  // namespace

std::string ToVtkXmlPolyData(const VtkPolyData& data, VtkFormat format,
                             VtkPrecision precision) {
  const size_t n = data.points.size();
  const bool binary = format == VtkFormat::kBinary;
  std::string xml;
  if (!binary) {
    xml.reserve(32 * n * (2 + data.point_vectors.size()) +
                12 * n * data.point_scalars.size() +
                16 * data.triangles.size());
  }
  DataArrays arrays(format);
  xml +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
      "byte_order=\"";
  xml += kByteOrder;
  xml += binary ? "\" header_type=\"UInt64\">\n" : "\">\n";
  xml += "  <PolyData>\n    <Piece NumberOfPoints=\"";
  xml += std::to_string(n) + "\" NumberOfVerts=\"" +
         std::to_string(data.vertices.size()) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(data.triangles.size()) + "\">\n";
  xml += "      <PointData>\n";
  for (const auto& [name, values] : data.point_scalars) {
    CHECK_EQ(values.size(), n) << name;
    arrays.Reals("Name=\"" + EscapeMarkup(name) + "\"", values.data(),
                 values.size(), IsFloat32Array(data, name, precision), 0, &xml);
  }
  for (const auto& [name, values] : data.point_vectors) {
    CHECK_EQ(values.size(), n) << name;
    arrays.Reals("Name=\"" + EscapeMarkup(name) + "\" NumberOfComponents=\"3\"",
                 values.empty() ? nullptr : values[0].data(), 3 * n,
                 IsFloat32Array(data, name, precision), 3, &xml);
  }
  xml += "      </PointData>\n      <Points>\n";
  arrays.Reals("NumberOfComponents=\"3\"",
               data.points.empty() ? nullptr : data.points[0].data(), 3 * n,
               precision == VtkPrecision::kFloat, 3, &xml);
  xml += "      </Points>\n";
  if (!data.vertices.empty()) {
    CellArrays("Verts", data.vertices, 1, &arrays, &xml);
  }
  if (!data.triangles.empty()) {
    std::vector<int> polygons;
    polygons.reserve(3 * data.triangles.size());
    for (const auto& t : data.triangles) {
      polygons.insert(polygons.end(), t.begin(), t.end());
    }
    CellArrays("Polys", polygons, 3, &arrays, &xml);
  }
  xml += "    </Piece>\n  </PolyData>\n";
  arrays.Close(&xml);
  xml += "</VTKFile>\n";
  return xml;
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
