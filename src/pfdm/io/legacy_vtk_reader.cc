#include "pfdm/io/legacy_vtk_reader.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pfdm/io/mesh_fields.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
         c == '\f';
}

// A binary section's number type: its size in bytes and how to read them.
struct BinaryType {
  int size;
  bool floating;
  bool is_signed;
};

BinaryType BinaryTypeOf(const std::string& where, const std::string& name) {
  static const std::map<std::string, BinaryType> types = {
      {"float", {4, true, true}},         {"double", {8, true, true}},
      {"char", {1, false, true}},         {"unsigned_char", {1, false, false}},
      {"short", {2, false, true}},        {"unsigned_short", {2, false, false}},
      {"int", {4, false, true}},          {"unsigned_int", {4, false, false}},
      {"vtktypeint32", {4, false, true}}, {"vtktypeuint32", {4, false, false}},
      {"vtktypeint64", {8, false, true}}, {"vtktypeuint64", {8, false, false}}};
  const auto it = types.find(name);
  if (it != types.end()) return it->second;
  if (name == "long" || name == "unsigned_long" || name == "vtkIdType") {
    throw InputError(where + ": binary '" + name +
                     "' has the size of the writer's platform; write the "
                     "file as ASCII or with vtktypeint64");
  }
  throw InputError(where + ": unknown data type '" + Clip(name) + "'");
}

// The legacy format's binary numbers are big-endian whatever the machine.
double DecodeBigEndian(const char* bytes, const BinaryType& type) {
  std::uint64_t bits = 0;
  for (int i = 0; i < type.size; ++i) {
    bits = bits << 8 | static_cast<unsigned char>(bytes[i]);
  }
  if (type.floating && type.size == 4) {
    const auto narrow = static_cast<std::uint32_t>(bits);
    float value;
    std::memcpy(&value, &narrow, sizeof(value));
    return value;
  }
  if (type.floating) {
    double value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }
  if (type.is_signed && type.size < 8) {
    const int unused = 64 - 8 * type.size;
    return static_cast<double>(static_cast<std::int64_t>(bits << unused) >>
                               unused);
  }
  return type.is_signed ? static_cast<double>(static_cast<std::int64_t>(bits))
                        : static_cast<double>(bits);
}

// A legacy VTK file: keywords and counts are whitespace-separated text, and
// each section's numbers are text too (ASCII) or big-endian bytes from the
// line after the section's header (BINARY).  Errors name the line, or the
// byte once binary data has been passed (its bytes may hold line breaks).
class VtkCursor {
 public:
  VtkCursor(const std::string& path, std::string bytes)
      : path_(path), bytes_(std::move(bytes)) {}

  const std::string& bytes() const { return bytes_; }

  // The rest of the current line, without its line break; false at the end.
  bool Line(std::string* line) {
    if (position_ >= bytes_.size()) return false;
    const size_t end = std::min(bytes_.find('\n', position_), bytes_.size());
    *line = bytes_.substr(position_, end - position_);
    const size_t last = line->find_last_not_of(" \t\r");
    line->erase(last == std::string::npos ? 0 : last + 1);
    line->erase(0, std::min(line->find_first_not_of(" \t"), line->size()));
    position_ = std::min(end + 1, bytes_.size());
    ++line_;
    return true;
  }

  bool Next(std::string* token) {
    while (position_ < bytes_.size() && IsSpace(bytes_[position_])) {
      line_ += bytes_[position_] == '\n';
      ++position_;
    }
    if (position_ >= bytes_.size()) return false;
    token_start_ = position_;
    while (position_ < bytes_.size() && !IsSpace(bytes_[position_])) {
      ++position_;
    }
    *token = bytes_.substr(token_start_, position_ - token_start_);
    return true;
  }

  // Whether the next token is `keyword`; consumes it only if so.
  bool NextIs(const std::string& keyword) {
    const size_t position = position_, token_start = token_start_;
    const int line = line_;
    std::string token;
    if (Next(&token) && token == keyword) return true;
    position_ = position;
    token_start_ = token_start;
    line_ = line;
    return false;
  }

  std::string Need(const char* what) {
    std::string token;
    if (!Next(&token)) throw InputError(path_ + ": ends before " + what);
    return token;
  }

  std::string Where() const {
    return binary_seen_ ? path_ + ": byte " + std::to_string(token_start_)
                        : path_ + ":" + std::to_string(line_);
  }

  long long Integer(const char* what) { return ToInteger(Where(), Need(what)); }

  // A section's number type, checked where it stands in a binary file.
  std::string Type(const char* what) {
    std::string type = Need(what);
    if (binary_) BinaryTypeOf(Where(), type);
    return type;
  }

  // A count of items that each take at least a byte of the file: bounded,
  // so that the counts' products cannot overflow.
  long long Count(const char* what) {
    const long long count = Integer(what);
    if (count < 0 || count > static_cast<long long>(bytes_.size())) {
      throw InputError(Where() + ": " + std::to_string(count) + " is not " +
                       what + " of a file of " + std::to_string(bytes_.size()) +
                       " bytes");
    }
    return count;
  }

  // `count` numbers of `type` (the section's, as its header names it): text
  // in an ASCII file, big-endian bytes in a BINARY one.  Coordinates are
  // bounded (kMaxCoordinateMm); integers must be whole.
  enum class Kind { kNumber, kCoordinate, kInteger };
  std::vector<double> Numbers(const std::string& type, long long count,
                              const char* what, Kind kind) {
    std::vector<double> values;
    if (!binary_) {
      for (long long i = 0; i < count; ++i) {
        const std::string token = Need(what);
        values.push_back(
            kind == Kind::kInteger ? CheckInteger(ToInteger(Where(), token))
            : kind == Kind::kCoordinate ? ToCoordinate(Where(), token)
                                        : ToNumber(Where(), token));
      }
      return values;
    }
    const BinaryType binary = BinaryTypeOf(Where(), type);
    if (kind == Kind::kInteger && binary.floating) {
      throw InputError(Where() + ": " + what + " as '" + type +
                       "', not an integer type");
    }
    const char* at = Take(count, binary.size, what);
    values.reserve(count);
    for (long long i = 0; i < count; ++i, at += binary.size) {
      const double value = DecodeBigEndian(at, binary);
      token_start_ = at - bytes_.data();
      if (!std::isfinite(value)) {
        throw InputError(Where() + ": not a finite number");
      }
      if (kind == Kind::kInteger) CheckInteger(value);
      // Spelled out only for the error (CheckCoordinate throws).
      if (kind == Kind::kCoordinate && std::abs(value) > kMaxCoordinateMm) {
        char text[32];
        std::snprintf(text, sizeof(text), "%.9g", value);
        CheckCoordinate(Where(), value, text);
      }
      values.push_back(value);
    }
    return values;
  }

  void SetBinary(bool binary) { binary_ = binary; }

  // Indices and offsets travel as doubles, exact to 2^53, and are turned
  // back into integers: beyond that the conversion is undefined.
  double CheckInteger(double value) const {
    if (std::abs(value) > 9007199254740992.0) {
      throw InputError(Where() + ": integer " + std::to_string(value) +
                       " is out of range");
    }
    return value;
  }

  // METADATA (VTK 5.1): lines up to the first blank one.
  void SkipMetadata() {
    std::string line;
    Line(&line);  // The keyword's own.
    while (Line(&line) && !line.empty()) {
    }
  }

 private:
  // The section's bytes: from the line after its header, count * size.
  const char* Take(long long count, int size, const char* what) {
    const size_t end = bytes_.find('\n', position_);
    position_ = end == std::string::npos ? bytes_.size() : end + 1;
    binary_seen_ = true;
    token_start_ = position_;
    if (static_cast<unsigned long long>(count) >
        (bytes_.size() - position_) / size) {
      throw InputError(Where() + ": the file ends inside " + what);
    }
    const char* at = bytes_.data() + position_;
    position_ += count * size;
    return at;
  }

  std::string path_;
  std::string bytes_;
  size_t position_ = 0;
  size_t token_start_ = 0;
  int line_ = 1;
  bool binary_ = false;
  bool binary_seen_ = false;
};

// A cell section's cells after its header's two counts: VTK 5.1's OFFSETS
// (first of them) into CONNECTIVITY (second indices), or the classic list
// of `first` cells, each its size and indices, `second` numbers in all.
std::vector<std::vector<long long>> ReadCells(long long first, long long second,
                                              VtkCursor* in) {
  using Kind = VtkCursor::Kind;
  std::vector<std::vector<long long>> cells;
  if (in->NextIs("OFFSETS")) {
    // VTK 5.1: first + 1 offsets into second indices.
    const std::vector<double> offsets = in->Numbers(
        in->Type("the offsets' type"), first, "the offsets", Kind::kInteger);
    if (in->Need("CONNECTIVITY") != "CONNECTIVITY") {
      throw InputError(in->Where() + ": CONNECTIVITY expected");
    }
    const std::vector<double> connectivity =
        in->Numbers(in->Type("the connectivity's type"), second,
                    "the connectivity", Kind::kInteger);
    for (size_t c = 0; c + 1 < offsets.size(); ++c) {
      if (offsets[c] < 0 || offsets[c + 1] < offsets[c] ||
          offsets[c + 1] > second) {
        throw InputError(in->Where() + ": offsets not increasing within " +
                         std::to_string(second) + " indices");
      }
      cells.emplace_back(
          connectivity.begin() + static_cast<std::ptrdiff_t>(offsets[c]),
          connectivity.begin() + static_cast<std::ptrdiff_t>(offsets[c + 1]));
    }
  } else {
    // first cells, each its size and indices: second numbers.
    const std::vector<double> list =
        in->Numbers("int", second, "the cells", Kind::kInteger);
    size_t at = 0;
    for (long long c = 0; c < first; ++c) {
      const double size = at < list.size() ? list[at] : -1.0;
      if (size < 0 || size > static_cast<double>(list.size() - at - 1)) {
        throw InputError(in->Where() + ": " + std::to_string(first) +
                         " cells do not fit a list of " +
                         std::to_string(second));
      }
      const auto begin = list.begin() + static_cast<std::ptrdiff_t>(at);
      cells.emplace_back(begin + 1,
                         begin + 1 + static_cast<std::ptrdiff_t>(size));
      at += 1 + static_cast<size_t>(size);
    }
  }
  return cells;
}

// The header's lines (the version, a title, ASCII or BINARY) and the
// dataset's type, which must be POLYDATA.
void ReadHeader(const std::string& path, VtkCursor* in) {
  std::string line;
  if (!in->Line(&line) || line.rfind("# vtk DataFile", 0) != 0) {
    throw InputError(path + ":1: not a legacy VTK file");
  }
  in->Line(&line);  // The title, which may hold anything.
  std::string format;
  in->Line(&format);
  if (format == "ASCII") {
    CheckNoNul(path, in->bytes());
  } else if (format != "BINARY") {
    throw InputError(path + ":3: '" + Clip(format) +
                     "' where ASCII or BINARY belongs");
  }
  in->SetBinary(format == "BINARY");
  if (in->Need("DATASET") != "DATASET" || in->Need("POLYDATA") != "POLYDATA") {
    throw InputError(in->Where() + ": only DATASET POLYDATA is read");
  }
}

// The sections after the header, each opened by its keyword: keeps the
// points, the polygons and the point scalars, and reads past the rest.
class PolyDataSections {
 public:
  explicit PolyDataSections(VtkCursor* in) : in_(*in) {}

  // Reads the sections up to the end of the file.
  VtkMesh ReadToEnd() {
    std::string keyword;
    while (in_.Next(&keyword)) Read(keyword);
    return std::move(result_);
  }

 private:
  using Kind = VtkCursor::Kind;

  // Reads the section `keyword` opens.
  void Read(const std::string& keyword) {
    if (keyword == "POINTS") {
      ReadPoints();
    } else if (keyword == "POLYGONS" || keyword == "VERTICES" ||
               keyword == "LINES" || keyword == "TRIANGLE_STRIPS") {
      ReadCellSection(keyword);
    } else if (keyword == "POINT_DATA") {
      ReadPointData();
    } else if (keyword == "CELL_DATA") {
      // Read past, for the POINT_DATA that VTK writes after it.
      attribute_count_ = in_.Count("the cell-data count");
      point_data_ = false;
    } else if (keyword == "SCALARS") {
      ReadScalars();
    } else if (keyword == "VECTORS" || keyword == "NORMALS" ||
               keyword == "TENSORS") {
      in_.Need("an array name");
      const std::string type = in_.Type("an array type");
      in_.Numbers(type, (keyword == "TENSORS" ? 9 : 3) * attribute_count_,
                  "an array value", Kind::kNumber);
    } else if (keyword == "TEXTURE_COORDINATES") {
      ReadTextureCoordinates();
    } else if (keyword == "FIELD") {
      ReadField();
    } else if (keyword == "LOOKUP_TABLE") {
      // A table's definition: RGBA rows.
      in_.Need("a lookup table name");
      const long long size = in_.Count("the table size");
      in_.Numbers("unsigned_char", 4 * size, "a colour", Kind::kNumber);
    } else if (keyword == "METADATA") {
      in_.SkipMetadata();
    } else if (keyword == "COLOR_SCALARS") {
      ReadColorScalars();
    } else {
      throw InputError(in_.Where() + ": unexpected '" + Clip(keyword) + "'");
    }
  }

  void ReadPoints() {
    const long long n = in_.Count("the point count");
    const std::string type = in_.Type("the point type");
    const std::vector<double> xyz =
        in_.Numbers(type, 3 * n, "the points", Kind::kCoordinate);
    for (size_t i = 0; i < xyz.size(); i += 3) {
      result_.mesh.points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    }
  }

  // Every cell section is read (its counts checked); only POLYGONS become
  // triangles.
  void ReadCellSection(const std::string& keyword) {
    const long long first = in_.Count("the cell count");
    const long long second = in_.Count("the cell list size");
    const std::vector<std::vector<long long>> cells =
        ReadCells(first, second, &in_);
    if (keyword != "POLYGONS") return;
    for (const auto& cell : cells) {
      AddFan(in_.Where(), cell, result_.mesh.points.size(), &result_.mesh);
    }
  }

  void ReadPointData() {
    const long long n = in_.Count("the point-data count");
    // Scalars of another count would be paired with the wrong points.
    if (n != static_cast<long long>(result_.mesh.points.size())) {
      throw InputError(in_.Where() + ": POINT_DATA " + std::to_string(n) +
                       " does not match POINTS " +
                       std::to_string(result_.mesh.points.size()));
    }
    attribute_count_ = n;
    point_data_ = true;
  }

  void ReadScalars() {
    const std::string name = in_.Need("a scalar name");
    const std::string type = in_.Type("a scalar type");
    std::string next = in_.Need("LOOKUP_TABLE");
    long long components = 1;
    if (next != "LOOKUP_TABLE") {
      components = ToInteger(in_.Where(), next);
      if (components < 1 || components > 4) {
        throw InputError(in_.Where() + ": " + std::to_string(components) +
                         " components, not 1 to 4");
      }
      next = in_.Need("LOOKUP_TABLE");
    }
    in_.Need("a lookup table name");
    Keep(name, components,
         in_.Numbers(type, components * attribute_count_, "a scalar",
                     Kind::kNumber));
  }

  void ReadTextureCoordinates() {
    in_.Need("an array name");
    const long long dimension = in_.Integer("the texture dimension");
    if (dimension < 1 || dimension > 3) {
      throw InputError(in_.Where() + ": texture dimension " +
                       std::to_string(dimension) + ", not 1 to 3");
    }
    in_.Numbers(in_.Type("an array type"), dimension * attribute_count_,
                "a texture coordinate", Kind::kNumber);
  }

  // Arrays of any name and shape, as ParaView writes point data: a
  // one-component array of a value per point is a point scalar.
  void ReadField() {
    in_.Need("a field name");
    const long long arrays = in_.Count("the field's array count");
    for (long long i = 0; i < arrays; ++i) {
      const std::string name = in_.Need("an array name");
      const long long components = in_.Count("the array's components");
      const long long tuples = in_.Count("the array's tuples");
      const std::string type = in_.Type("the array's type");
      if (components * tuples > static_cast<long long>(in_.bytes().size())) {
        throw InputError(in_.Where() + ": " + std::to_string(components) +
                         " x " + std::to_string(tuples) +
                         " values do not fit the file");
      }
      std::vector<double> values = in_.Numbers(type, components * tuples,
                                               "an array value", Kind::kNumber);
      if (tuples == attribute_count_) Keep(name, components, std::move(values));
      if (in_.NextIs("METADATA")) in_.SkipMetadata();
    }
  }

  // Colours: floats in text, unsigned chars in binary.
  void ReadColorScalars() {
    in_.Need("an array name");
    const long long components = in_.Integer("the colour components");
    if (components < 1 || components > 4) {
      throw InputError(in_.Where() + ": " + std::to_string(components) +
                       " colour components, not 1 to 4");
    }
    in_.Numbers("unsigned_char", components * attribute_count_, "a colour",
                Kind::kNumber);
  }

  // A point section's one-component arrays are its scalars, by name.
  void Keep(const std::string& name, long long components,
            std::vector<double> values) {
    if (point_data_ && components == 1) {
      result_.point_scalars[name] = std::move(values);
    }
  }

  VtkCursor& in_;
  VtkMesh result_;
  // The current attribute section's: POINT_DATA's (point_data_) or
  // CELL_DATA's count, before either none.
  long long attribute_count_ = 0;
  bool point_data_ = false;
};

}  // namespace

VtkMesh ReadLegacyVtkPolyData(const std::string& path) {
  VtkCursor in(path, ReadInputBytes(path));
  ReadHeader(path, &in);
  VtkMesh result = PolyDataSections(&in).ReadToEnd();
  if (result.mesh.points.empty()) throw InputError(path + ": no points");
  return result;
}

}  // namespace pfdm
