#include "pfdm/io/mesh_reader.h"

#include <sstream>

#include "pfdm/io/mesh_fields.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

namespace pfdm {
namespace {

std::istringstream Open(const std::string& path) {
  return std::istringstream(ReadInputFile(path));
}

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
