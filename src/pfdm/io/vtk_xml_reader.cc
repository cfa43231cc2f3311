#include "pfdm/io/vtk_xml_reader.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "pfdm/io/mesh_fields.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The value of attribute name="..." in one tag, "" when absent.
std::string Attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

struct NumberType {
  int size;
  bool floating;
  bool is_signed;
};

bool LittleEndianMachine() {
  const std::uint16_t one = 1;
  char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Reads one value of `type` at bytes, swapped when the file's byte order is
// not the machine's.
double Decode(const char* bytes, const NumberType& type, bool swap) {
  char b[8];
  std::memcpy(b, bytes, type.size);
  if (swap) std::reverse(b, b + type.size);
  const auto as = [&b](auto value) {
    std::memcpy(&value, b, sizeof(value));
    return static_cast<double>(value);
  };
  if (type.floating) return type.size == 4 ? as(float()) : as(double());
  switch (type.size) {
    case 1:
      return type.is_signed ? as(std::int8_t()) : as(std::uint8_t());
    case 2:
      return type.is_signed ? as(std::int16_t()) : as(std::uint16_t());
    case 4:
      return type.is_signed ? as(std::int32_t()) : as(std::uint32_t());
    default:
      return type.is_signed ? as(std::int64_t()) : as(std::uint64_t());
  }
}

class XmlPolyDataReader {
 public:
  XmlPolyDataReader(std::string path, std::string text)
      : path_(std::move(path)), text_(std::move(text)) {}

  VtkMesh Read() {
    const size_t appended = text_.find("<AppendedData");
    if (appended != std::string::npos) {
      const std::string tag = TagAt(appended);
      if (Attribute(tag, "encoding") != "raw") {
        Fail("appended data encoded '" + Attribute(tag, "encoding") +
             "' (pfdm reads raw; save without base64)");
      }
      data_ = text_.find('_', appended + tag.size());
      if (data_ == std::string::npos) Fail("<AppendedData> without '_'");
      ++data_;
    }
    const size_t end = std::min(appended, text_.size());
    ReadHeader();
    std::string section;
    for (size_t at = text_.find('<'); at < end; at = text_.find('<', at + 1)) {
      const std::string tag = TagAt(at);
      for (const char* name : {"PointData", "CellData", "Points", "Verts",
                               "Lines", "Strips", "Polys"}) {
        if (tag.rfind(std::string("<") + name, 0) == 0 &&
            (tag[std::strlen(name) + 1] == '>' ||
             tag[std::strlen(name) + 1] == ' ')) {
          section = name;
        }
      }
      if (tag.rfind("<DataArray", 0) == 0) TakeArray(section, tag, at);
    }
    return Assemble();
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw InputError(path_ + ": " + what);
  }

  std::string TagAt(size_t at) const {
    const size_t close = text_.find('>', at);
    if (close == std::string::npos)
      Fail("unclosed tag at byte " + std::to_string(at));
    return text_.substr(at, close - at + 1);
  }

  void ReadHeader() {
    const size_t at = text_.find("<VTKFile");
    if (at == std::string::npos) Fail("not a VTK XML file (no <VTKFile>)");
    const std::string tag = TagAt(at);
    if (Attribute(tag, "type") != "PolyData") {
      Fail("a VTK XML '" + Attribute(tag, "type") + "' file, not PolyData");
    }
    if (!Attribute(tag, "compressor").empty()) {
      Fail("compressed arrays (" + Attribute(tag, "compressor") +
           "); save without compression");
    }
    swap_ =
        (Attribute(tag, "byte_order") == "BigEndian") == LittleEndianMachine();
    const std::string header = Attribute(tag, "header_type");
    if (header == "UInt64") {
      header_ = {8, false, false};
    } else if (header.empty() || header == "UInt32") {
      header_ = {4, false, false};
    } else {
      Fail("unknown header_type '" + header + "'");
    }
  }

  NumberType TypeOf(const std::string& tag) const {
    static const std::map<std::string, NumberType> kTypes = {
        {"Int8", {1, false, true}},   {"UInt8", {1, false, false}},
        {"Int16", {2, false, true}},  {"UInt16", {2, false, false}},
        {"Int32", {4, false, true}},  {"UInt32", {4, false, false}},
        {"Int64", {8, false, true}},  {"UInt64", {8, false, false}},
        {"Float32", {4, true, true}}, {"Float64", {8, true, true}}};
    const auto type = kTypes.find(Attribute(tag, "type"));
    if (type == kTypes.end()) {
      Fail("unknown DataArray type '" + Attribute(tag, "type") + "'");
    }
    return type->second;
  }

  // One array's values, from the text after its tag or the appended bytes.
  std::vector<double> Values(const std::string& tag, size_t at) const {
    const NumberType type = TypeOf(tag);
    const std::string format = Attribute(tag, "format");
    std::vector<double> values;
    if (format == "ascii") {
      const size_t begin = at + tag.size();
      const size_t end = text_.find("</DataArray>", begin);
      if (end == std::string::npos) Fail("unclosed DataArray");
      std::istringstream in(text_.substr(begin, end - begin));
      std::string word;
      while (in >> word) values.push_back(ToNumber(path_, word));
      return values;
    }
    if (format != "appended") {
      Fail("DataArray format '" + format +
           "' (pfdm reads ascii and appended raw)");
    }
    if (data_ == std::string::npos)
      Fail("appended DataArray without <AppendedData>");
    const std::string offset = Attribute(tag, "offset");
    const size_t begin = data_ + std::stoull(offset.empty() ? "0" : offset);
    if (begin + header_.size > text_.size())
      Fail("DataArray offset past the end");
    const auto bytes =
        static_cast<size_t>(Decode(&text_[begin], header_, swap_));
    if (bytes % type.size != 0 || begin + header_.size + bytes > text_.size()) {
      Fail("DataArray at offset " + offset + " runs past the end");
    }
    for (size_t i = 0; i < bytes / type.size; ++i) {
      values.push_back(
          Decode(&text_[begin + header_.size + i * type.size], type, swap_));
    }
    return values;
  }

  void TakeArray(const std::string& section, const std::string& tag,
                 size_t at) {
    const std::string name = Attribute(tag, "Name");
    const std::string components = Attribute(tag, "NumberOfComponents");
    if (section == "Points") {
      points_ = Values(tag, at);
    } else if (section == "Polys" &&
               (name == "connectivity" || name == "offsets")) {
      (name == "connectivity" ? connectivity_ : offsets_) = Values(tag, at);
    } else if (section == "PointData" &&
               (components.empty() || components == "1")) {
      scalars_[name] = Values(tag, at);
    }
  }

  VtkMesh Assemble() const {
    VtkMesh result;
    if (points_.size() % 3 != 0) Fail("Points not in threes");
    for (size_t i = 0; i < points_.size(); i += 3) {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) {
        p[k] = CheckCoordinate(path_, points_[i + k],
                               std::to_string(points_[i + k]));
      }
      result.mesh.points.push_back(p);
    }
    size_t start = 0;
    for (double end : offsets_) {
      if (end < start || end > connectivity_.size())
        Fail("Polys offsets out of order");
      std::vector<long long> polygon(
          connectivity_.begin() + start,
          connectivity_.begin() + static_cast<size_t>(end));
      AddFan(path_, polygon, result.mesh.points.size(), &result.mesh);
      start = static_cast<size_t>(end);
    }
    for (const auto& [name, values] : scalars_) {
      if (values.size() != result.mesh.points.size()) {
        Fail("point array '" + name + "' has " + std::to_string(values.size()) +
             " values for " + std::to_string(result.mesh.points.size()) +
             " points");
      }
      result.point_scalars[name] = values;
    }
    return result;
  }

  std::string path_;
  std::string text_;
  size_t data_ = std::string::npos;
  NumberType header_{8, false, false};
  bool swap_ = false;
  std::vector<double> points_, connectivity_, offsets_;
  std::map<std::string, std::vector<double>> scalars_;
};

}  // namespace

VtkMesh ReadVtkXmlPolyData(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return XmlPolyDataReader(path, text.str()).Read();
}

}  // namespace pfdm
