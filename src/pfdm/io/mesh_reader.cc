#include "pfdm/io/mesh_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {
namespace {

std::istringstream Open(const std::string& path) {
  return std::istringstream(ReadInputFile(path));
}

double ToNumber(const std::string& where, const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || rest != end || text.empty()) {
    throw InputError(where + ": '" + Clip(text) + "' is not a number");
  }
  if (!std::isfinite(value)) throw InputError(where + ": not a finite number");
  return value;
}

double ToCoordinate(const std::string& where, const std::string& text) {
  const double value = ToNumber(where, text);
  if (std::abs(value) > kMaxCoordinateMm) {
    throw InputError(where + ": coordinate '" + Clip(text) +
                     "' is out of range (more than 1e6 mm from the origin)");
  }
  return value;
}

long long ToInteger(const std::string& where, const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || rest != end || text.empty()) {
    throw InputError(where + ": '" + Clip(text) + "' is not an integer");
  }
  return value;
}

void AddFan(const std::string& where, const std::vector<long long>& polygon,
            size_t num_points, TriangleMesh* mesh) {
  for (long long index : polygon) {
    if (index < 0 || index >= static_cast<long long>(num_points)) {
      throw InputError(where + ": vertex " + std::to_string(index) +
                       " out of range");
    }
  }
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    mesh->triangles.push_back({static_cast<int>(polygon[0]),
                               static_cast<int>(polygon[i]),
                               static_cast<int>(polygon[i + 1])});
  }
}

// Whitespace-separated tokens with the line each came from, for errors.
class Tokens {
 public:
  explicit Tokens(const std::string& path) : path_(path), in_(Open(path)) {}
  bool Next(std::string* token) {
    while (!(line_stream_ >> *token)) {
      std::string line;
      if (!std::getline(in_, line)) return false;
      ++line_;
      line_stream_.clear();
      line_stream_.str(line);
    }
    return true;
  }
  std::string Need(const char* what) {
    std::string token;
    if (!Next(&token)) throw InputError(path_ + ": ends before " + what);
    return token;
  }
  std::string Where() const { return path_ + ":" + std::to_string(line_); }
  double Number(const char* what) { return ToNumber(Where(), Need(what)); }
  double Coordinate() { return ToCoordinate(Where(), Need("a coordinate")); }
  long long Integer(const char* what) { return ToInteger(Where(), Need(what)); }

 private:
  std::string path_;
  std::istringstream in_;
  std::istringstream line_stream_;
  int line_ = 0;
};

}  // namespace

TriangleMesh ReadObj(const std::string& path) {
  std::istringstream in = Open(path);
  TriangleMesh mesh;
  std::vector<std::pair<int, std::vector<long long>>> faces;  // Line, indices.
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    const std::string where = path + ":" + std::to_string(number);
    if (kind == "v") {
      std::string x, y, z;
      if (!(fields >> x >> y >> z))
        throw InputError(where + ": vertex needs x y z");
      mesh.points.emplace_back(ToCoordinate(where, x), ToCoordinate(where, y),
                               ToCoordinate(where, z));
    } else if (kind == "f") {
      std::vector<long long> polygon;
      std::string corner;
      while (fields >> corner) {
        const long long index =
            ToInteger(where, corner.substr(0, corner.find('/')));
        // Negative indices count back from the latest vertex.
        polygon.push_back(
            index < 0 ? static_cast<long long>(mesh.points.size()) + index
                      : index - 1);
      }
      if (polygon.size() < 3)
        throw InputError(where + ": face needs 3 vertices");
      faces.emplace_back(number, std::move(polygon));
    }
  }
  if (mesh.points.empty()) throw InputError(path + ": no vertices");
  for (const auto& [number, polygon] : faces) {
    AddFan(path + ":" + std::to_string(number), polygon, mesh.points.size(),
           &mesh);
  }
  return mesh;
}

VtkMesh ReadLegacyVtkPolyData(const std::string& path) {
  Tokens tokens(path);
  VtkMesh result;
  std::string line;
  {
    std::istringstream in = Open(path);
    std::getline(in, line);
    if (line.rfind("# vtk DataFile", 0) != 0) {
      throw InputError(path + ":1: not a legacy VTK file");
    }
  }
  // Skip the version line, title line and format keyword by tokens: the
  // title may hold anything, so find "ASCII" or "BINARY" first.
  std::string token;
  while (tokens.Next(&token) && token != "ASCII" && token != "BINARY") {
  }
  if (token != "ASCII")
    throw InputError(tokens.Where() + ": only ASCII VTK is read");
  if (tokens.Need("DATASET") != "DATASET" ||
      tokens.Need("POLYDATA") != "POLYDATA") {
    throw InputError(tokens.Where() + ": only DATASET POLYDATA is read");
  }
  size_t data_points = 0;
  while (tokens.Next(&token)) {
    if (token == "POINTS") {
      const long long n = tokens.Integer("the point count");
      tokens.Need("the point type");
      for (long long i = 0; i < n; ++i) {
        const double x = tokens.Coordinate();
        const double y = tokens.Coordinate();
        result.mesh.points.emplace_back(x, y, tokens.Coordinate());
      }
    } else if (token == "POLYGONS" || token == "VERTICES" || token == "LINES" ||
               token == "TRIANGLE_STRIPS") {
      const long long cells = tokens.Integer("the cell count");
      tokens.Integer("the cell list size");
      for (long long c = 0; c < cells; ++c) {
        const long long size = tokens.Integer("a cell size");
        std::vector<long long> cell;
        for (long long i = 0; i < size; ++i)
          cell.push_back(tokens.Integer("an index"));
        if (token == "POLYGONS") {
          AddFan(tokens.Where(), cell, result.mesh.points.size(), &result.mesh);
        }
      }
    } else if (token == "POINT_DATA") {
      const long long n = tokens.Integer("the point-data count");
      // Scalars of another count would be paired with the wrong points.
      if (n != static_cast<long long>(result.mesh.points.size())) {
        throw InputError(tokens.Where() + ": POINT_DATA " + std::to_string(n) +
                         " does not match POINTS " +
                         std::to_string(result.mesh.points.size()));
      }
      data_points = static_cast<size_t>(n);
    } else if (token == "SCALARS") {
      const std::string name = tokens.Need("a scalar name");
      tokens.Need("a scalar type");
      std::string next = tokens.Need("LOOKUP_TABLE");
      if (next != "LOOKUP_TABLE") {
        if (ToInteger(tokens.Where(), next) != 1) {
          throw InputError(tokens.Where() +
                           ": only one-component scalars are read");
        }
        next = tokens.Need("LOOKUP_TABLE");
      }
      tokens.Need("a lookup table name");
      std::vector<double>& values = result.point_scalars[name];
      for (size_t i = 0; i < data_points; ++i)
        values.push_back(tokens.Number("a scalar"));
    } else if (token == "LOOKUP_TABLE") {  // A table's definition: RGBA rows.
      tokens.Need("a lookup table name");
      const long long size = tokens.Integer("the table size");
      for (long long i = 0; i < 4 * size; ++i) tokens.Number("a colour");
    } else if (token == "CELL_DATA" || token == "FIELD" || token == "NORMALS" ||
               token == "VECTORS" || token == "TEXTURE_COORDINATES") {
      break;  // Nothing pfdm uses follows.
    } else {
      throw InputError(tokens.Where() + ": unexpected '" + Clip(token) + "'");
    }
  }
  if (result.mesh.points.empty()) throw InputError(path + ": no points");
  return result;
}

std::vector<std::vector<Eigen::Vector3d>> ReadCapMeanShape(
    const std::string& path) {
  std::istringstream in = Open(path);
  std::vector<double> values;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const size_t begin = line.find_first_not_of(" \t");
    const size_t end = line.find_last_not_of(" \t\r");
    values.push_back(ToCoordinate(path + ":" + std::to_string(number),
                                  line.substr(begin, end - begin + 1)));
  }
  if (values.empty() || values.size() % 12 != 0) {
    throw InputError(path + ": " + std::to_string(values.size()) +
                     " values, not 4 surfaces of x y z points");
  }
  const size_t per_surface = values.size() / 12;
  std::vector<std::vector<Eigen::Vector3d>> surfaces(4);
  for (size_t s = 0; s < 4; ++s) {
    for (size_t i = 0; i < per_surface; ++i) {
      const double* p = &values[3 * (s * per_surface + i)];
      surfaces[s].emplace_back(p[0], p[1], p[2]);
    }
  }
  return surfaces;
}

std::vector<std::array<int, 3>> ReadCapFaces(const std::string& path,
                                             int num_points) {
  std::istringstream in = Open(path);
  std::vector<std::array<int, 3>> faces;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(number);
    std::istringstream fields(line);
    std::array<int, 3> face;
    std::string item;
    for (int i = 0; i < 3; ++i) {
      if (!std::getline(fields, item, ',')) {
        throw InputError(where + ": a face needs 3 indices");
      }
      const size_t begin = item.find_first_not_of(" \t");
      const size_t end = item.find_last_not_of(" \t\r");
      const long long index =
          ToInteger(where, begin == std::string::npos
                               ? ""
                               : item.substr(begin, end - begin + 1));
      if (index < 1 || index > num_points) {
        throw InputError(where + ": vertex " + std::to_string(index) +
                         " out of range 1.." + std::to_string(num_points));
      }
      face[i] = static_cast<int>(index - 1);
    }
    faces.push_back(face);
  }
  return faces;
}

PointSequence MeshPointSequence(
    const std::string& source,
    const std::vector<std::vector<Eigen::Vector3d>>& frames) {
  PointSequence sequence;
  sequence.source = source;
  for (size_t t = 0; t < frames.size(); ++t) {
    if (frames[t].size() != frames.front().size()) {
      throw InputError(source + ": frame " + std::to_string(t) + " has " +
                       std::to_string(frames[t].size()) +
                       " vertices, frame 0 " +
                       std::to_string(frames.front().size()));
    }
    Frame frame;
    frame.index = static_cast<int>(t);
    for (size_t i = 0; i < frames[t].size(); ++i) {
      frame.points.push_back({static_cast<std::int64_t>(i), frames[t][i]});
    }
    sequence.frames.push_back(std::move(frame));
  }
  return sequence;
}

}  // namespace pfdm
